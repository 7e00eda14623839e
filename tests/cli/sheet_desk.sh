#!/usr/bin/env bash
# The review sheet for the desk, read back with pdftotext: each cue's changes as ranges of one type
# ("201-204 LED Wash 19 @ 35 %, color #507cff"), palette names where the cue takes values from a
# palette, colours as sRGB codes, every changed fixture listed (no "... and N more", even for a
# cue that changes all twelve fixtures differently), and the patch by universe and address (the
# demo's file order is not; a patch moved out of order shows it). With ../shared/data, the imported
# Capture rig's focus cue lists its 76 fixtures as ranges too.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; failed=0
check() { if eval "$2"; then pass=$((pass + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi; }

cp -r "$root/examples/demo/." "$tmp/demo/"
# Cue 6: every fixture to its own pan; fixture 101 re-patched to universe 2, last in the patch.
python3 - "$tmp/demo/demo.haze.json" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
show["cue_lists"][0]["cues"].append({"number": "6", "label": "Spread", "fade": 2.0, "delay": 0.0, "follow": None,
    "values": {str(f["id"]): {"pan": 10.0 + i} for i, f in enumerate(show["fixtures"])}})
show["fixtures"][0]["patch"] = {"universe": 2, "address": 1}
json.dump(show, open(sys.argv[1], "w"), indent=1)
PY
"$haze" sheet "$tmp/demo/demo.haze.json" --quality draft -o "$tmp/demo.pdf" >/dev/null 2>"$tmp/err" ||
  { echo "FAIL: haze sheet: $(cat "$tmp/err")"; exit 1; }
pdftotext -layout "$tmp/demo.pdf" "$tmp/demo.txt"
text="$tmp/demo.txt"
check "cue 2's washes as one range with level and colour code" 'grep -q "201-204 LED Wash 19 @ 35 %, color #[0-9a-f]\{6\}, zoom 55" "$text"'
check "palette names: cue 1's spots in Warm white" 'grep -q "101 Profile Spot 600 @ 70 %, palette Warm white" "$text"'
check "cue 4's beams by palette" 'grep -q "301-304 Beam 230 @ 100 %, palette Finale" "$text"'
check "no summarised fixtures" '! grep -qi "more fixtures\|and [0-9]* more" "$text"'
check "no linear colour triples" '! grep -q "color \[" "$text"'
for id in 101 102 103 104 201 202 203 204 301 302 303 304; do
  check "cue 6 lists fixture $id" 'grep -qE "(^| )$id [A-Z][A-Za-z0-9 ]* pan [0-9]" "$text"'
done
# The patch: universe and address ascending, fixture 101 (moved to universe 2) last.
python3 - "$text" <<'PY' || failed=$((failed + 1))
import re, sys
lines = open(sys.argv[1]).read().split("\f")
rows = []
for page in lines:
    if " - patch" not in page:
        continue
    for line in page.splitlines():
        m = re.match(r"^(\d+) .*\s(\d+)\s+(\d+)\s*$", line)
        if m:
            rows.append((int(m.group(2)), int(m.group(3)), int(m.group(1))))
keys = [(u, a) for u, a, _ in rows]
ok = len(rows) == 12 and keys == sorted(keys) and rows[-1][2] == 101
print(("" if ok else "FAIL: ") + "patch order %s" % [f"{i}@{u}.{a}" for u, a, i in rows])
sys.exit(0 if ok else 1)
PY

source "$root/tests/cli/test_data.bash"
if mvr=$(data_path gdtf/mvr/capture_demo_show.mvr); then
  "$haze" import-mvr "$mvr" -o "$tmp/capture.haze.json" >/dev/null 2>&1
  "$haze" sheet "$tmp/capture.haze.json" --list "MVR focus" --quality draft -o "$tmp/capture.pdf" >/dev/null 2>"$tmp/err"
  check "Capture sheet: $(head -2 "$tmp/err")" '[ -s "$tmp/capture.pdf" ]'
  pdftotext -layout "$tmp/capture.pdf" "$tmp/capture.txt"
  lines=$(python3 -c '
import re, sys
page = open(sys.argv[1]).read().split("\f")[0]
print(sum(1 for l in page.splitlines() if re.search(r"\d+(-\d+)? [A-Za-z].* @ 100 %", l)))' "$tmp/capture.txt")
  check "Capture focus cue: its 76 fixtures in a few range lines ($lines)" '[ "$lines" -ge 1 ] && [ "$lines" -le 12 ]'
  check "Capture: no summarised fixtures" '! grep -qi "more fixtures\|and [0-9]* more" "$tmp/capture.txt"'
else
  want_data gdtf/mvr/capture_demo_show.mvr
fi
echo "$pass passed, $failed failed"
data_exit "$failed"
