#!/usr/bin/env bash
# The GUI opens the demo show under Xvfb (Mesa, no GPU), draws a few frames, writes a window
# screenshot and exits cleanly. The screenshot shows lit beams, not an empty window: the same
# view of the same show with the haze taken out (scattering 0: surfaces lit as before, no
# beams in the air) is darker, and the difference lies along the beams, not everywhere. Both
# at the same manual exposure, so the meter cannot even them out.
set -euo pipefail
haze=$1; root=$2
. "$root/tests/gui/xvfb.bash"
start_xvfb
out=$(mktemp -d)
export XDG_CONFIG_HOME="$out/config"  # the GUI's remembered settings: its own, not the user's
trap 'kill $XVFB_PID 2>/dev/null; rm -rf "$out"' EXIT
demo=$root/examples/demo/demo.haze.json
# The copy without haze lives in the temp folder; its venue and profiles point back to the demo's.
python3 "$root/tests/show_copy.py" "$demo" "$out/clear.haze.json" --scattering 0
args=(--width 640 --height 360 --frames 3 --cue 2 --exposure-mode manual --exposure 0)
"$haze" open "$demo" "${args[@]}" --screenshot "$out/shot.png"
"$haze" open "$out/clear.haze.json" "${args[@]}" --screenshot "$out/clear.png"
[ -s "$out/shot.png" ] && [ -s "$out/clear.png" ] || { echo "FAIL: no screenshot"; exit 1; }
mean() { convert "$1" -colorspace Gray -format "%[fx:mean]" info:; }
with=$(mean "$out/shot.png"); without=$(mean "$out/clear.png")
# The share of the viewport (between the side panels, below the menu bar) that the haze brightens
# by more than 10 % of full scale: the beams' footprint. (minus: the second image less the first.)
changed=$(convert "$out/clear.png" "$out/shot.png" -compose minus -composite -crop 250x330+200+25 +repage \
          -colorspace Gray -threshold 10% -format "%[fx:mean]" info:)
echo "screenshot mean brightness $with with haze, $without without; $changed of the viewport brightened by the beams"
awk -v m="$with" 'BEGIN { exit !(m > 0.01) }' || { echo "FAIL: screenshot is black"; exit 1; }
# Measured: 9.9 % of the viewport at cue 2. Beams cover part of it, not all of it (a uniform
# wash would be a haze bug, not beams); half the measured share is the floor.
awk -v c="$changed" 'BEGIN { exit !(c > 0.05 && c < 0.8) }' || { echo "FAIL: the haze changed $changed of the frame: not beams"; exit 1; }
echo "1 passed, 0 failed"
