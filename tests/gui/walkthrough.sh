#!/usr/bin/env bash
# The designer's path of the README, driven through the GUI by real X input events on the demo:
# Library tab, pick the spot profile, P, click the truss (a spot is placed hanging there: the
# title gets "*", the new fixture is selected); raise its intensity in the inspector; F, click
# the sphere (focus to point); Ctrl+R records cue 6; Ctrl+Shift+S saves it under a new name;
# Ctrl+Z / Ctrl+Shift+Z undo and redo (the "*" comes and goes); Ctrl+Q exits cleanly. Then the
# saved show is reopened: cue 6 holds the new fixture at full, and its beam lights the sphere
# (the window at cue 6 is brighter there than the demo at cue 5, which cue 6 tracks from; both at
# the manual exposure, so the meter does not even them out).
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"
saved="$tmp/walk.haze.json"

start_haze "haze - demo" "$root/examples/demo/demo.haze.json" --width 640 --height 360 --quality draft --cue 5
shot start
click 105 36               # the Library tab
click 60 104               # its "spot" row
tap p                      # place
click 341 67               # the truss between Spot 2 and Spot 3, in the FOH view
shot placed
check "placing marks the show modified (title '$(title)')" '[[ "$(title)" == *"demo.haze.json *" ]]'
ring=$(yellow_pixels placed 30x30+326+50)
check "the new fixture is selected on the truss ($ring yellow pixels)" '[ "$ring" -gt 40 ]'
click 577 253              # the inspector's intensity slider, right end: full
tap f                      # focus to point
click 357 285              # the sphere
shot focused
tap ctrl+r                 # record cue 6
tap ctrl+shift+s           # save as: the path popup, its field focused and holding the show's path
hold ctrl+a
type_text "$saved"
hold Return
sleep 1
check "Save as wrote the show" '[ -s "$saved" ]'
check "the saved show has the new fixture 305" 'grep -q "\"id\": 305" "$saved"'
check "and cue 6" 'grep -q "\"number\": \"6\"" "$saved"'
check "saving clears the mark (title '$(title)')" '[[ "$(title)" == "haze - walk.haze.json" ]]'
tap ctrl+z
check "Ctrl+Z undoes the record (title '$(title)')" '[[ "$(title)" == *" *" ]]'
tap ctrl+shift+z
check "Ctrl+Shift+Z redoes it, back to the saved state (title '$(title)')" '[[ "$(title)" == "haze - walk.haze.json" ]]'
tap ctrl+q
wait_exit
check "Ctrl+Q exits cleanly (status $rc)" '[ "$rc" = 0 ]'

# Reopen: the cue is there, with the fixture up, and the picture shows its beam on the sphere.
level=$("$haze" state "$saved" --cue 6 --json 2>&1 |
  awk '/"305": \{/ { f = 1 } f && /"intensity"/ { gsub(/[^0-9.]/, "", $2); print $2; exit }')
check "reopened, cue 6 has fixture 305 at $level" 'awk -v l="$level" "BEGIN { exit !(l > 0.95) }"'
"$haze" open "$saved" --width 640 --height 360 --quality draft --exposure-mode manual --cue 6 --frames 3 --screenshot "$tmp/reopened.png" 2>/dev/null
"$haze" open "$root/examples/demo/demo.haze.json" --width 640 --height 360 --quality draft --exposure-mode manual \
  --cue 5 --frames 3 \
  --screenshot "$tmp/cue5.png" 2>/dev/null
mean() { convert "$tmp/$1.png" -crop 50x40+333+265 +repage -colorspace Gray -format "%[fx:mean]" info:; }
lit=$(mean reopened); dark=$(mean cue5)
check "the new beam lights the sphere (mean $dark -> $lit)" 'awk -v a="$lit" -v b="$dark" "BEGIN { exit !(a > b + 0.05) }"'
[ -n "${HAZE_GUI_SHOTS:-}" ] && cp "$tmp/reopened.png" "$tmp/cue5.png" "$HAZE_GUI_SHOTS/"
finish
