#!/usr/bin/env bash
# The density field in the Air tab, by real X input events, on a copy of the fog-and-hazer
# example: turning "Density field" off changes the stage and marks the show modified, Ctrl+Z
# brings the field back; a drag on "Base density" is one undo step and one change of the saved
# show (Ctrl+S writes the dragged value; one Ctrl+Z and Ctrl+S write the old one again).
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"
show="$tmp/air.haze.json"
python3 "$root/tests/show_copy.py" "$root/examples/demo/air.haze.json" "$show"
base() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["atmosphere"]["density"]["base"])' "$show"; }
check "the copy starts at base density 0.25 ($(base))" '[ "$(base)" = 0.25 ]'

start_haze "haze - air" "$show" --width 640 --height 360 --quality draft --exposure-mode manual --tab air
view=250x341+200+19        # the viewport between the panels at 640x360
shot fog
click 16 168               # "Density field": off
away() { xdotool mousemove --window "$win" 540 330; settle; }  # no tooltip over the viewport
away
shot uniform
off=$(difference fog uniform $view)
check "turning the field off changes the stage (difference $off)" 'awk -v d="$off" "BEGIN { exit !(d > 0.02) }"'
check "and marks the show modified (title '$(title)')" '[ "$(title)" = "haze - air.haze.json *" ]'
tap ctrl+z
away
shot back
again=$(difference fog back $view)
check "Ctrl+Z brings the field back (difference $again against $off)" 'awk -v d="$again" -v o="$off" "BEGIN { exit !(d < 0.2 * o) }"'
check "and the unmodified title (title '$(title)')" '[ "$(title)" = "haze - air.haze.json" ]'

# A drag to the right on the Base density field: many frames of change, one edit.
xdotool mousemove --window "$win" 60 191; settle
xdotool mousedown 1; settle
for x in 70 80 90 100 110 120; do xdotool mousemove --window "$win" $x 191; settle 2; done
xdotool mouseup 1; settle
tap ctrl+s
dragged=$(base)
check "Ctrl+S saves the dragged base density ($dragged)" 'awk -v b="$dragged" "BEGIN { exit !(b > 0.3) }"'
check "the saved show validates" '"$haze" validate "$show" >/dev/null 2>&1'
tap ctrl+z
tap ctrl+s
check "one Ctrl+Z undoes the whole drag (saved base $(base))" '[ "$(base)" = 0.25 ]'
tap ctrl+q
wait_exit
check "Ctrl+Q exits cleanly (status $rc)" '[ "$rc" = 0 ]'
finish
