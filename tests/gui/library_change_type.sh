#!/usr/bin/env bash
# The Library tab's "Change type" under Xvfb with real X input: ten demo fixtures selected (each
# patched in a universe of its own, so any footprint fits), "robin 600e spot" typed into the library
# search, the first hit (a QLC+ spot) clicked, "Change type of 10 selected" clicked, Ctrl+S. The
# saved show validates; the ten have the hit's .qxf as their profile and keep id, name,
# position, rotation and patch; the other two are untouched. Ctrl+Z then Ctrl+S gives back the
# show byte for byte as it was saved before the change. Widget places come from the probe file
# (HAZE_GUI_PROBE_FILE, app/gui/gui_app.cpp: "library").
set -uo pipefail
haze=$1; root=$2
[ -d /usr/share/qlcplus/fixtures ] || { echo "skipped: needs qlcplus-data (/usr/share/qlcplus/fixtures; tools/install-deps.sh installs it)"; exit 77; }
. "$root/tests/gui/gui_session.bash"
# The library index is cached per user: the test's own, so it neither reads nor writes the user's.
export XDG_CACHE_HOME="$tmp/cache"

demo_copy "$tmp/rig.haze.json" <<'PY'
for i, f in enumerate(show["fixtures"]):
    f["patch"] = {"universe": i + 1, "address": 1}
PY
show="$tmp/rig.haze.json"
export HAZE_GUI_PROBE_FILE="$tmp/probe.json"
probe() {  # probe PYTHON-EXPRESSION: its value on the probe's JSON (p)
  python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$HAZE_GUI_PROBE_FILE" "$1" 2>/dev/null
}
centre() { probe "'%d %d' % (p['library']['$1']['x'] + p['library']['$1']['w'] / 2, p['library']['$1']['y'] + p['library']['$1']['h'] / 2)"; }
changed=(101 102 103 104 201 202 203 204 301 302)
selection=()
for id in "${changed[@]}"; do selection+=(--select "$id"); done
start_haze "haze - rig" "$show" --width 1280 --height 800 --quality draft --tab library "${selection[@]}"

tap ctrl+s
cp "$show" "$tmp/before.json"
check "the search field is drawn ($(probe "p['library']['search']"))" 'wait_until 60 "[ \"\$(probe \"p[\\\"library\\\"][\\\"search\\\"][\\\"w\\\"] > 0\")\" = True ]"'
click $(centre search)
type_text "robin 600e spot"
check "the search lists hits ($(probe "p['library']['hits']"))" 'wait_until 60 "[ \"\$(probe \"p[\\\"library\\\"][\\\"hits\\\"] > 0\")\" = True ]"'
click $(centre first_hit)
check "picking a hit shows the Change type button ($(probe "p['library']['change']"))" \
  'wait_until 60 "[ \"\$(probe \"p[\\\"library\\\"][\\\"change\\\"][\\\"w\\\"] > 0\")\" = True ]"'
shot picked
click $(centre change)
check "the status line reports the change ($(probe "p['status']"))" 'wait_until 60 "probe \"p[\\\"status\\\"]\" | grep -q \"^Changed 10 fixtures\""'
tap ctrl+s
cp "$show" "$tmp/after.json"
check "the changed show validates" '"$haze" validate "$tmp/after.json" >/dev/null 2>&1'
out=$(python3 - "$tmp/before.json" "$tmp/after.json" "${changed[*]}" <<'PY'
import json, sys
before, after = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
changed = {int(i) for i in sys.argv[3].split()}
b = {f["id"]: f for f in before["fixtures"]}
a = {f["id"]: f for f in after["fixtures"]}
problems = []
if set(a) != set(b):
    problems.append("ids %s -> %s" % (sorted(b), sorted(a)))
types = set()
for i in sorted(b):
    fa, fb = a.get(i), b[i]
    if fa is None:
        continue
    for k in ("name", "position", "rotation", "patch"):
        if fa.get(k) != fb.get(k):
            problems.append("%d: %s %s -> %s" % (i, k, fb.get(k), fa.get(k)))
    if i in changed:
        path = after["profiles"].get(fa["profile"], "")
        types.add(fa["profile"])
        if fa["profile"] == fb["profile"] or not str(path).endswith(".qxf") or "/qlcplus/" not in str(path):
            problems.append("%d: profile %s (%s), was %s" % (i, fa["profile"], path, fb["profile"]))
    elif fa != fb:
        problems.append("%d changed although not selected" % i)
if len(types) != 1:
    problems.append("the ten have types %s" % sorted(types))
print("; ".join(problems[:6]) if problems else "ok " + next(iter(types)))
PY
)
echo "   $out"
check "the ten have the QLC+ type, ids, names, positions, rotations and patches kept, the rest untouched" '[ "${out%% *}" = ok ]'
tap ctrl+z
tap ctrl+s
check "Ctrl+Z and Ctrl+S give back the show byte for byte" 'cmp -s "$tmp/before.json" "$show"'
tap ctrl+q
wait_exit
check "Ctrl+Q exits cleanly (status $rc)" '[ "$rc" = 0 ]'
finish
