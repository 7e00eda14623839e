#!/usr/bin/env bash
# View > Cells (docs/cells.md, "Cost"; docs/gui.md): the 19-cell test wash lit alike is drawn as
# one beam by default (auto), as 19 after View > Cells > One beam per cell, and as one again after
# View > Cells > One beam where driven alike; the choice is remembered between runs
# (gui-settings.json, docs/gui.md). Real X input (xdotool); the beams of each frame come from the
# GUI's probe (HAZE_GUI_PROBE_FILE).
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

export HAZE_GUI_PROBE_FILE="$tmp/probe.json"
probe() {  # probe PYTHON-EXPRESSION: its value on the probe's JSON (p)
  python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$HAZE_GUI_PROBE_FILE" "$1" 2>/dev/null
}
beams_are() { [ "$(probe "p['beams']")" = "$1" ]; }

python3 "$root/tests/data/gdtf/make_gdtf.py" "$root/tests/data/gdtf/hex19_wash.xml" "$tmp/hex19.gdtf"
python3 "$root/tests/cells_show.py" "$tmp/cells.haze.json" hex19.gdtf "$root/tests/data/shared/venues/Cube/Cube.gltf"

settings="$XDG_CONFIG_HOME/haze/gui-settings.json"
start() { rm -f "$HAZE_GUI_PROBE_FILE"; start_haze "haze - cells" "$tmp/cells.haze.json" --width 640 --height 360 --quality draft; }
quit() { tap ctrl+q; wait $pid; rc=$?; }
written() { grep -q "\"cells\": \"$1\"" "$settings" 2>/dev/null; }  # the settings file holds cells: $1
start
check "auto, the default: the wash lit alike is one beam ($(probe "p['beams']"))" 'wait_until 60 "beams_are 1"'
# The View menu at 114,10; Cells is its last item (at 150,209 with one camera), a submenu whose
# items open to its right, 17 px apart.
cells_item() { click 114 10; xdotool mousemove --window "$win" 150 "$CELLS_Y"; settle; }
CELLS_Y=209
cells_item; click 340 226
check "View > Cells > One beam per cell: 19 beams ($(probe "p['beams']"))" 'wait_until 60 "beams_are 19"'
check "the choice is written to gui-settings.json" 'wait_until 30 "written separate"'
quit
check "quits (rc $rc)" '[ "$rc" = 0 ]'
start
check "started again: still one beam per cell ($(probe "p['beams']"))" 'wait_until 60 "beams_are 19"'
cells_item; click 340 209
check "View > Cells > One beam where driven alike: one beam again ($(probe "p['beams']"))" 'wait_until 60 "beams_are 1"'
check "and written back" 'wait_until 30 "written auto"'
quit
check "quits (rc $rc)" '[ "$rc" = 0 ]'
finish
