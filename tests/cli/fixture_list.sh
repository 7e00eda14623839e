#!/usr/bin/env bash
# `haze fixture list SHOW [--json]`: every fixture by id (whatever the file's order) with its
# name, type, mode and universe.address; checked against the show's JSON and, for an imported
# Capture rig, against the MVR's own <Address> and <FixtureID> (read here with python's XML).
# Usage: fixture_list.sh HAZE REPO
set -u
haze=$1
repo=$2
source "$repo/tests/cli/test_data.bash"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$repo/tests/cli/checks.bash"

# The demo with its fixtures in reverse order in the file.
python3 "$repo/tests/show_copy.py" "$repo/examples/demo/demo.haze.json" "$tmp/demo.haze.json"
python3 - "$tmp/demo.haze.json" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
show["fixtures"].reverse()
show["fixtures"][0].pop("patch", None)  # one unpatched fixture: 304, the last of the file
json.dump(show, open(sys.argv[1], "w"))
PY
"$haze" fixture list "$tmp/demo.haze.json" --json >"$tmp/demo.json" 2>"$tmp/demo.err"
check "fixture list --json exits 0: $(head -2 "$tmp/demo.err")" $?
out=$(python3 - "$tmp/demo.haze.json" "$tmp/demo.json" <<'PY'
import json, sys
show, rows = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
want = sorted(show["fixtures"], key=lambda f: f["id"])
problems = []
if [r["id"] for r in rows] != [f["id"] for f in want]:
    problems.append("ids %s, expected %s" % ([r["id"] for r in rows], [f["id"] for f in want]))
for r, f in zip(rows, want):
    p = f.get("patch")
    if (r["name"], r["mode"]) != (f["name"], f["mode"]):
        problems.append("fixture %d: %s/%s" % (f["id"], r["name"], r["mode"]))
    if (r["universe"], r["address"]) != ((p["universe"], p["address"]) if p else (None, None)):
        problems.append("fixture %d patch %s.%s, expected %s" % (f["id"], r["universe"], r["address"], p))
    if not r["type"]:
        problems.append("fixture %d has no type" % f["id"])
print("; ".join(problems) if problems else "ok")
PY
)
check "the demo's rows are its fixtures by id with their names, modes and patches: $out" "$([ "$out" = ok ]; echo $?)"
"$haze" fixture list "$tmp/demo.haze.json" >"$tmp/demo.txt"
check "the table has a header and one line per fixture" \
  "$([ "$(head -1 "$tmp/demo.txt" | tr -s ' ')" = " id name type mode univ.addr" ] && [ "$(wc -l <"$tmp/demo.txt")" -eq 13 ]; echo $?)"
check "the unpatched fixture shows \"-\", the first patched one 1.1" \
  "$(grep -Eq '^304 .* -$' "$tmp/demo.txt" && grep -q ' 1\.1$' "$tmp/demo.txt"; echo $?)"
"$haze" fixture list "$tmp/missing.haze.json" >/dev/null 2>"$tmp/missing.err"
rc=$?
check "a missing show exits 1 with one line (got $rc: $(cat "$tmp/missing.err"))" \
  "$([ $rc -eq 1 ] && [ "$(wc -l <"$tmp/missing.err")" -eq 1 ]; echo $?)"
"$haze" fixture list >/dev/null 2>&1
check "no show is a usage error (exit 2)" "$([ $? -eq 2 ]; echo $?)"

if want_data gdtf/mvr/capture_demo_show.mvr; then
  mvr=$(data_path gdtf/mvr/capture_demo_show.mvr)
  "$haze" import-mvr "$mvr" -o "$tmp/cap.haze.json" >/dev/null 2>&1
  "$haze" fixture list "$tmp/cap.haze.json" --json >"$tmp/cap.json"
  out=$(python3 - "$mvr" "$tmp/cap.json" <<'PY'
import json, sys, zipfile
import xml.etree.ElementTree as ET
rows = json.load(open(sys.argv[2]))
scene = ET.fromstring(zipfile.ZipFile(sys.argv[1]).read("GeneralSceneDescription.xml"))
problems = []
by_id = {r["id"]: r for r in rows}
fixtures = list(scene.iter("Fixture"))
for fx in fixtures:
    fid = int(fx.findtext("FixtureID"))
    r = by_id.get(fid)
    if r is None:
        problems.append("no row for FixtureID %d" % fid)
        continue
    absolute = int(fx.find("Addresses/Address").text)
    want = ((absolute - 1) // 512 + 1, (absolute - 1) % 512 + 1)
    if (r["universe"], r["address"]) != want:
        problems.append("%d: patch %s.%s, expected %d.%d" % (fid, r["universe"], r["address"], want[0], want[1]))
    if not r["name"].startswith(fx.get("name")) or str(fid) not in r["name"]:
        problems.append("%d: name %r" % (fid, r["name"]))
if len(set(r["name"] for r in rows)) != len(rows) or len(rows) != len(fixtures):
    problems.append("%d rows, %d distinct names, %d fixtures" % (len(rows), len(set(r["name"] for r in rows)), len(fixtures)))
if [r["id"] for r in rows] != sorted(r["id"] for r in rows):
    problems.append("not sorted by id")
print("; ".join(problems[:5]) if problems else "ok %d" % len(rows))
PY
)
  check "the imported Capture rig: by id, distinct names with the FixtureID, patches from the MVR: $out" \
    "$([ "${out%% *}" = ok ]; echo $?)"
  # The composed names are the MVR's own: an export over the source writes its names back as they were.
  "$haze" export-mvr "$tmp/cap.haze.json" -o "$tmp/cap.mvr" >/dev/null 2>&1
  names() { python3 -c 'import sys, zipfile, xml.etree.ElementTree as E
print(sorted(f.get("name") for f in E.fromstring(zipfile.ZipFile(sys.argv[1]).read("GeneralSceneDescription.xml")).iter("Fixture")))' "$1"; }
  check "export-mvr writes the MVR's own fixture names back" "$([ "$(names "$mvr")" = "$(names "$tmp/cap.mvr")" ]; echo $?)"
fi

echo "$passed passed, $fail failed"
data_exit "$fail"
