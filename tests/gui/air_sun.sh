#!/usr/bin/env bash
# The sun in the Air tab, by real X input events, on a copy of the sun demo: turning "Sun" off
# darkens the stage and marks the show modified, Ctrl+Z brings it back; a drag on "Elevation"
# is one undo step and one change of the saved show.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"
show="$tmp/sun.haze.json"
python3 - "$root/examples/demo/sun.haze.json" "$show" <<'PY'
import json, os, sys
s = json.load(open(sys.argv[1]))
s['venue']['gltf'] = os.path.join(os.path.dirname(os.path.abspath(sys.argv[1])), s['venue']['gltf'])
json.dump(s, open(sys.argv[2], 'w'), indent=1)
PY
elevation() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["atmosphere"]["sun"]["elevation"])' "$show"; }
check "the copy starts at elevation 28 ($(elevation))" '[ "$(elevation)" = 28 ]'

start_haze "haze - sun" "$show" --width 640 --height 360 --quality draft --exposure-mode manual --tab air
view=250x341+200+19        # the viewport between the panels at 640x360
away() { xdotool mousemove --window "$win" 540 330; settle; }  # no tooltip over the viewport
away
shot sunny
click 16 191               # "Sun": off
away
shot dark
off=$(difference sunny dark $view)
check "turning the sun off changes the stage (difference $off)" 'awk -v d="$off" "BEGIN { exit !(d > 0.02) }"'
check "and marks the show modified (title '$(title)')" '[ "$(title)" = "haze - sun.haze.json *" ]'
tap ctrl+z
away
shot back
again=$(difference sunny back $view)
check "Ctrl+Z brings the sun back (difference $again against $off)" 'awk -v d="$again" -v o="$off" "BEGIN { exit !(d < 0.2 * o) }"'

# A drag to the right on the Elevation field: many frames of change, one edit.
xdotool mousemove --window "$win" 60 237; settle
xdotool mousedown 1; settle
for x in 70 80 90 100 110 120; do xdotool mousemove --window "$win" $x 237; settle 2; done
xdotool mouseup 1; settle
tap ctrl+s
dragged=$(elevation)
check "Ctrl+S saves the dragged elevation ($dragged)" 'awk -v e="$dragged" "BEGIN { exit !(e > 29) }"'
check "the saved show validates" '"$haze" validate "$show" >/dev/null 2>&1'
tap ctrl+z
tap ctrl+s
check "one Ctrl+Z undoes the whole drag (saved elevation $(elevation))" '[ "$(elevation)" = 28 ]'
tap ctrl+q
wait_exit
check "Ctrl+Q exits cleanly (status $rc)" '[ "$rc" = 0 ]'
finish
