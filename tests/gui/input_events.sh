#!/usr/bin/env bash
# The GUI under Xvfb driven by real X input events: the demo opens on cue 1; Space (a key press,
# as on a console) fades to cue 2 and the stage changes far more than a still cue's refinement
# noise; Backspace (BACK) brings cue 1's look back; a click on a fixture's marker in the
# viewport selects it (the inspector shows it, the viewport rings it in yellow) and a click on
# empty floor clears it; Delete, Ctrl+Z, Ctrl+Y show in the title's unsaved mark; Ctrl+Q asks
# about the unsaved change (Cancel stays, Discard exits with status 0). 640x360, draft quality.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

start_haze "haze - demo" "$root/examples/demo/demo.haze.json" --width 640 --height 360 --quality draft
view=250x341+200+19        # the viewport between the panels at 640x360
inspector=190x300+450+40   # the inspector panel
shot cue1a
sleep 1.5
shot cue1b
noise=$(difference cue1a cue1b $view)
tap space                  # GO: cue 2 (gobos, deep blue wash) fades in over 6 s
sleep 7
shot cue2
go=$(difference cue1a cue2 $view)
check "Space (GO) changes the stage (difference $go, still-cue noise $noise)" \
  'awk -v d="$go" -v n="$noise" "BEGIN { exit !(d > 3 * n && d > 0.02) }"'
tap BackSpace              # BACK: cue 1 over its 5 s fade
sleep 6.5
shot back1
back=$(difference cue1a back1 $view)
check "Backspace (BACK) brings cue 1's look back (difference $back)" \
  'awk -v d="$back" -v g="$go" "BEGIN { exit !(d < 0.5 * g) }"'

# Spot 3 hangs at (1, 8, -2.875): in the FOH view its marker is at (358, 63).
before=$(yellow_pixels back1 40x40+338+43)
click 358 63
shot selected
after=$(yellow_pixels selected 40x40+338+43)
check "a click on Spot 3's marker rings it in yellow ($before -> $after pixels)" '[ "$after" -gt $((before + 40)) ]'
panel=$(difference back1 selected $inspector)
check "the inspector shows the selection (difference $panel)" 'awk -v d="$panel" "BEGIN { exit !(d > 0.05) }"'
click 325 330              # the house floor in front of the stage: nothing there
shot deselected
cleared=$(difference back1 deselected $inspector)
check "a click on nothing clears the selection (inspector difference $cleared)" 'awk -v d="$cleared" "BEGIN { exit !(d < 0.01) }"'

# An edit, undo and redo (the title's "*"), and the unsaved-changes guard in front of Ctrl+Q.
check "no unsaved changes yet (title '$(title)')" '[ "$(title)" = "haze - demo.haze.json" ]'
click 358 63
tap Delete                 # deletes Spot 3
check "Delete marks the show modified (title '$(title)')" '[ "$(title)" = "haze - demo.haze.json *" ]'
tap ctrl+z
check "Ctrl+Z undoes it (title '$(title)')" '[ "$(title)" = "haze - demo.haze.json" ]'
tap ctrl+y
check "Ctrl+Y redoes it (title '$(title)')" '[ "$(title)" = "haze - demo.haze.json *" ]'
tap ctrl+q
sleep 1
check "Ctrl+Q with unsaved changes asks first" 'kill -0 $pid 2>/dev/null'
click 386 197              # the guard's Cancel
check "Cancel keeps haze running" 'kill -0 $pid 2>/dev/null'
tap ctrl+q
sleep 1
click 297 197              # the guard's Discard changes
wait_exit
check "Discard changes exits cleanly (status $rc)" '[ "$rc" = 0 ]'
finish
