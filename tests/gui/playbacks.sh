#!/usr/bin/env bash
# The Playback tab under Xvfb with real X input events: the demo's rig with a second cue list
# "Specials" (cue 1: the four fixtures that the demo's cue 1 leaves dark, 301-304, at full in
# blue). The show opens on Main's cue 1; a click on the second row's GO brings Specials' cue 1
# in beside it (HTP: Main's fixtures stay lit) and the stage changes far more than a still cue's
# refinement noise; its master fader at 0 (a click at the slider's left end) takes it out again.
# 640x360, draft quality.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

demo_copy "$tmp/lists.haze.json" <<'PY'
show["cue_lists"].append({"name": "Specials", "cues": [{"number": "1", "values": {
    str(i): {"intensity": 1, "color": [0, 0, 1]} for i in (301, 302, 303, 304)}}]})
PY

start_haze "haze - lists" "$tmp/lists.haze.json" --width 640 --height 360 --quality draft --tab playback
view=250x341+200+19        # the viewport between the panels at 640x360
# The Playback tab at 640x360: rows "Main" (GO at y 76) and "Specials" (GO at 19,144; its master
# fader from x 83 to 190 on the same line).
GO2_X=19; GO2_Y=144; MASTER2_X=85; MASTER2_Y=144
shot a
sleep 1.5
shot b
noise=$(difference a b $view)
click "$GO2_X" "$GO2_Y"    # GO on the second list's row
sleep 2
shot go
changed=$(difference a go $view)
check "GO on the second list changes the stage (difference $changed, still-cue noise $noise)" \
  'awk -v d="$changed" -v n="$noise" "BEGIN { exit !(d > 3 * n && d > 0.02) }"'
click "$MASTER2_X" "$MASTER2_Y"   # its master fader at the left end: 0
sleep 2
shot zero
back=$(difference a zero $view)
check "its master at 0 takes it out again (difference $back against $changed)" \
  'awk -v d="$back" -v g="$changed" "BEGIN { exit !(d < 0.5 * g) }"'
finish
