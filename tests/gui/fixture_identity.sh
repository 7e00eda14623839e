#!/usr/bin/env bash
# Fixture identity under Xvfb with real X input: six adjacent fixtures of the demo selected
# (101-104 and 201-202, interleaved on one truss: at 640x360 their labels, placed beside their
# markers, would print over one another) get label boxes that do not intersect, some pushed
# off their place (the declutter did work); the Fixtures tab lists by id although the show
# file lists the fixtures backwards, and its filter field, typed into, narrows the list
# ("wash": 201-204); View > Fixture numbers (on at start) turns the numbers off, and the labels
# then hold the names alone; the Patch tab lists by id too and filters by universe.address ("2.":
# fixture 104, moved to universe 2). What the GUI drew is read from its probe file
# (HAZE_GUI_PROBE_FILE, app/gui/gui_app.cpp): ids per row and the label boxes, in window pixels.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

demo_copy "$tmp/rig.haze.json" <<'PY'
show["fixtures"].reverse()  # 304 ... 101: the tabs must sort
for f in show["fixtures"]:
    if f["id"] == 104:
        f["patch"] = {"universe": 2, "address": 1}
PY
export HAZE_GUI_PROBE_FILE="$tmp/probe.json"
probe() {  # probe PYTHON-EXPRESSION: its value on the probe's JSON (p)
  python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$HAZE_GUI_PROBE_FILE" "$1"
}
rows_are() { [ "$(probe "p['$1']")" = "$2" ]; }  # rows_are fixture_rows|patch_rows "[101, ...]"
numbers_are() { [ "$(probe "p['numbers']")" = "$1" ]; }  # True or False: View > Fixture numbers
click_filter() { click $(probe "'%d %d' % (p['filter_field']['x'] + p['filter_field']['w'] / 2, p['filter_field']['y'] + p['filter_field']['h'] / 2)"); }
all="[101, 102, 103, 104, 201, 202, 203, 204, 301, 302, 303, 304]"

selection=()
for id in 101 102 103 104 201 202; do selection+=(--select "$id"); done
start_haze "haze - rig" "$tmp/rig.haze.json" --width 640 --height 360 --quality draft --tab fixtures "${selection[@]}"
settle
check "six labels placed ($(probe "len(p['labels'])"))" '[ "$(probe "len(p[\"labels\"])")" = 6 ]'
python3 - "$HAZE_GUI_PROBE_FILE" <<'PY2' && pass=$((pass + 1)) || fail=$((fail + 1))
import json, sys
labels = json.load(open(sys.argv[1]))["labels"]
def meet(a, b):
    return a["x"] < b["x"] + b["w"] and b["x"] < a["x"] + a["w"] and a["y"] < b["y"] + b["h"] and b["y"] < a["y"] + a["h"]
overlaps = [(a["fixture"], b["fixture"]) for i, a in enumerate(labels) for b in labels[i + 1:] if meet(a, b)]
# Where each label would be without the declutter: beside its marker, centred on it.
first = [dict(l, y=l["anchor"][1] - l["h"] / 2) for l in labels]
would = [(a["fixture"], b["fixture"]) for i, a in enumerate(first) for b in first[i + 1:] if meet(a, b)]
moved = [l["fixture"] for l in labels if l["moved"]]
ok = not overlaps and would and moved and sorted(l["fixture"] for l in labels) == [101, 102, 103, 104, 201, 202]
print(("ok" if ok else "FAIL") + f": label boxes intersect: {overlaps or 'none'}; unplaced they would: {would}; pushed: {moved}")
sys.exit(0 if ok else 1)
PY2
check "Fixtures tab: by id although the file lists them backwards ($(probe "p['fixture_rows']"))" 'rows_are fixture_rows "$all"'

# The filter field: a click into it (its place from the probe), then typing.
click_filter
type_text "wash"
check "Fixtures tab filtered by 'wash'" 'wait_until 30 "rows_are fixture_rows \"[201, 202, 203, 204]\""'
echo "   rows: $(probe "p['fixture_rows']")"
# View > Fixture numbers off (the View menu at 114,10; with the demo's three cameras the item is
# the menu's last, at 150,201 at 640x360): the labels hold the names alone, so 101's narrows.
wide=$(probe "[l['w'] for l in p['labels'] if l['fixture'] == 101][0]")
check "fixture numbers on by default" 'numbers_are True'
click 114 10
click 150 201
check "View > Fixture numbers turns them off" 'wait_until 30 "numbers_are False"'
narrow=$(probe "[l['w'] for l in p['labels'] if l['fixture'] == 101][0]")
check "101's label without its number: $narrow px wide, was $wide" 'awk -v a="$narrow" -v b="$wide" "BEGIN { exit !(a + 10 < b) }"'
kill $pid 2>/dev/null; wait $pid 2>/dev/null

start_haze "haze - rig" "$tmp/rig.haze.json" --width 640 --height 360 --quality draft --tab patch
settle
check "Patch tab: by id ($(probe "p['patch_rows']"))" 'rows_are patch_rows "$all"'
click_filter
type_text "2."
check "Patch tab filtered by universe.address '2.'" 'wait_until 30 "rows_are patch_rows \"[104]\""'
echo "   rows: $(probe "p['patch_rows']")"
check "no labels without a selection" '[ "$(probe "len(p[\"labels\"])")" = 0 ]'
finish
