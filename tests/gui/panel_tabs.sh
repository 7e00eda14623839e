#!/usr/bin/env bash
# The show panel's tabs at 1600x900 (docs/gui.md, "Panels"): by default the panel is as wide as
# its six tab names need (computed from their text widths), so none is truncated ("Fixtu...",
# "Libra...", "Playb..."): the probe (HAZE_GUI_PROBE_FILE) gives each tab's width as ImGui drew
# it and the width its name needs. The panel's right edge, dragged 80 px left with real X mouse
# events, makes it narrower (and the tabs shrink, which is what the first check would catch),
# then 150 px right makes it wider again.
set -uo pipefail
haze=$1; root=$2
export XVFB_SCREEN=1700x1000x24
. "$root/tests/gui/gui_session.bash"

export HAZE_GUI_PROBE_FILE="$tmp/probe.json"
probe() {  # probe PYTHON-EXPRESSION: its value on the probe's JSON (p)
  python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$HAZE_GUI_PROBE_FILE" "$1"
}
truncated() { probe "[t['name'] for t in p['tabs'] if t['width'] < t['needed'] - 0.5]"; }

start_haze "haze - demo" "$root/examples/demo/demo.haze.json" --width 1600 --height 900 --quality draft
settle
check "six tabs drawn ($(probe "[t['name'] for t in p['tabs']]"))" '[ "$(probe "len(p[\"tabs\"])")" = 6 ]'
check "no tab name truncated at 1600x900 (panel $(probe "p['show_panel_w']") px; tabs drawn/needed: $(probe "[(t['name'], t['width'], t['needed']) for t in p['tabs']]"))" \
  '[ "$(truncated)" = "[]" ]'

# The right edge, at mid-height of the panel, dragged left then right.
w0=$(probe "int(p['show_panel_w'])")
y=$((900 / 3))
drag() {  # drag FROM-X TO-X
  xdotool mousemove --window "$win" "$1" $y; settle
  xdotool mousedown 1; settle
  xdotool mousemove --window "$win" $(( ($1 + $2) / 2 )) $y; settle
  xdotool mousemove --window "$win" "$2" $y; settle
  xdotool mouseup 1; settle
}
drag $((w0 - 1)) $((w0 - 81))
w1=$(probe "int(p['show_panel_w'])")
check "dragging the edge 80 px left narrows the panel ($w0 -> $w1 px) and the tabs shrink ($(truncated))" \
  '[ $w1 -le $((w0 - 60)) ] && [ "$(truncated)" != "[]" ]'
drag $((w1 - 1)) $((w1 + 149))
w2=$(probe "int(p['show_panel_w'])")
check "dragging it 150 px right widens it ($w1 -> $w2 px), every name whole again" '[ $w2 -ge $((w1 + 130)) ] && [ "$(truncated)" = "[]" ]'
finish
