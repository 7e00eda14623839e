#!/usr/bin/env bash
# The GUI opens the demo show under Xvfb (Mesa, no GPU), draws a few frames, writes a window
# screenshot and exits cleanly; the screenshot shows lit beams, not an empty window.
set -euo pipefail
haze=$1; root=$2
. "$root/tests/gui/xvfb.bash"
start_xvfb 93
out=$(mktemp -d)
"$haze" open "$root/examples/demo/demo.haze.json" --width 640 --height 360 --screenshot "$out/shot.png" --frames 3
[ -s "$out/shot.png" ] || { echo "FAIL: no screenshot"; exit 1; }
# Mean brightness of the picture (ImageMagick): the stage is lit, so it is not black.
mean=$(convert "$out/shot.png" -colorspace Gray -format "%[fx:mean]" info:)
echo "screenshot mean brightness $mean"
awk -v m="$mean" 'BEGIN { exit !(m > 0.01) }' || { echo "FAIL: screenshot is black"; exit 1; }
echo "1 passed, 0 failed"
