#!/usr/bin/env bash
# The view settings remembered between runs (docs/gui.md, "Remembered between runs"), in
# $XDG_CONFIG_HOME/haze/gui-settings.json (gui_session.bash points XDG_CONFIG_HOME into $tmp).
# First run: the show panel's edge dragged 200 px right, E locks the exposure, View > Fixture
# numbers off, Ctrl+Q. Second run: the probe (HAZE_GUI_PROBE_FILE) shows the same panel width,
# the exposure locked (at this run's metered EV) and the numbers off. Third run in a window half
# as wide: the remembered width is clamped so the viewport keeps its room. Then a broken file:
# the GUI starts with the defaults, says so once (status line and stderr, naming the file and the
# line), and leaves the file as it is.
set -uo pipefail
haze=$1; root=$2
export XVFB_SCREEN=1700x1000x24
. "$root/tests/gui/gui_session.bash"

settings="$XDG_CONFIG_HOME/haze/gui-settings.json"
export HAZE_GUI_PROBE_FILE="$tmp/probe.json"
probe() {  # probe PYTHON-EXPRESSION: its value on the probe's JSON (p)
  python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$HAZE_GUI_PROBE_FILE" "$1"
}
demo="$root/examples/demo/demo.haze.json"
run() {  # run WIDTH HEIGHT: the demo in a window of that size, a fresh probe
  rm -f "$HAZE_GUI_PROBE_FILE"
  start_haze "haze - demo" "$demo" --width "$1" --height "$2" --quality draft
  settle
}
quit() { tap ctrl+q; wait_exit; }
locked_is() { [ "$(probe "p['exposure']['locked']")" = "$1" ]; }  # True or False
numbers_are() { [ "$(probe "p['numbers']")" = "$1" ]; }           # View > Fixture numbers
width_near() { [ "$(probe "int(abs(p['show_panel_w'] - $1) <= 1)")" = 1 ]; }

run 1600 900
check "nothing remembered yet: no settings file before a change" '[ ! -e "$settings" ]'
check "defaults: exposure unlocked, numbers on" 'locked_is False && numbers_are True'
w0=$(probe "int(p['show_panel_w'])")
y=$((900 / 3))
xdotool mousemove --window "$win" $((w0 - 1)) $y; settle
xdotool mousedown 1; settle
xdotool mousemove --window "$win" $((w0 + 99)) $y; settle
xdotool mousemove --window "$win" $((w0 + 199)) $y; settle
check "not written while the edge is held" '[ ! -e "$settings" ]'
xdotool mouseup 1; settle
w1=$(probe "round(p['show_panel_w'])")
check "the edge dragged 200 px right ($w0 -> $w1 px) is written when let go" \
  '[ $w1 -ge $((w0 + 180)) ] && [ -e "$settings" ]'
tap e
check "E locks the exposure" 'wait_until 30 "locked_is True"'
click 114 10      # View (the menu's place as in fixture_identity.sh)
click 150 201     # Fixture numbers
check "View > Fixture numbers turns them off" 'wait_until 30 "numbers_are False"'
check "the file holds the lock and the numbers off ($(tr -d '\n' <"$settings"))" \
  'grep -q "\"exposure_locked\": true" "$settings" && grep -q "\"fixture_numbers\": false" "$settings"'
# --quality draft was this run's choice, not the designer's: the file keeps the default.
check "a command-line quality is not remembered" 'grep -q "\"viewport_quality\": \"default\"" "$settings"'
quit
check "quits (rc $rc)" '[ "$rc" = 0 ]'

run 1600 900
check "started again: the same panel width ($(probe "p['show_panel_w']") px, was $w1)" \
  'width_near $w1'
check "exposure locked again, at this run's metered EV ($(probe "p['exposure']"))" \
  'wait_until 60 "locked_is True"'
check "fixture numbers still off" 'numbers_are False'
cp "$settings" "$tmp/settings.before"
quit
check "a run that changed nothing leaves the file as it was" 'cmp -s "$settings" "$tmp/settings.before"'

run 800 450
check "in a window half as wide the remembered $w1 px is clamped to half of it ($(probe "p['show_panel_w']") px)" \
  '[ "$(probe "int(p[\"show_panel_w\"] <= 400)")" = 1 ]'
quit
check "the clamp is not written: the wider screen gets its width back" 'cmp -s "$settings" "$tmp/settings.before"'

printf '{\n  "fixture_numbers": false,\n  "exposure_locked": tru\n}\n' >"$settings"
cp "$settings" "$tmp/settings.broken"
run 1600 900
check "a broken file: defaults (panel $(probe "p['show_panel_w']") px as at first, unlocked, numbers on)" \
  'width_near $w0 && locked_is False && numbers_are True'
check "said on the status line, naming the file and the line ($(probe "p['status']"))" \
  '[ "$(probe "p[\"status_error\"] and \"gui-settings.json:line 3\" in p[\"status\"]")" = True ]'
settle 8
quit
check "said once on stderr ($(grep -c gui-settings.json "$tmp/haze.out") lines)" \
  '[ "$(grep -c "gui-settings.json:line 3" "$tmp/haze.out")" = 1 ]'
check "the broken file is left as it was" 'cmp -s "$settings" "$tmp/settings.broken"'
finish
