#!/usr/bin/env bash
# When the view stops moving, the still view is drawn at the chosen quality and refined frame by
# frame (docs/gui.md). `haze open --turntable DEG --turn-frames K` turns the view for K frames,
# then holds it still, and its summary says how long the first frame at the chosen quality took
# to show after the view stopped. Timing-free checks: the line is there with a time and the
# refined frames counted, the still view is lit, and a view that never stops says nothing. The time itself
# is printed, not asserted (a loaded test machine takes longer): on the Capture rig of the
# optional test data at a 1280x720 viewport it is the figure docs/gui.md gives.
set -euo pipefail
haze=$1; root=$2
. "$root/tests/gui/xvfb.bash"
. "$root/tests/cli/test_data.bash"
XVFB_SCREEN=1920x1200x24 start_xvfb
out=$(mktemp -d)
export XDG_CONFIG_HOME="$out/config"  # the GUI's remembered settings: its own, not the user's
trap 'kill $XVFB_PID 2>/dev/null; rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
passed=0
demo=$root/examples/demo/demo.haze.json
args=(--width 640 --height 360 --cue 2 --quality default --exposure-mode manual --exposure 0)

# Still for frames 0-7 (the still renderer makes its maps and refines), turning for 8-11, then
# still again: the designer's case, a view moved and let go.
line=$("$haze" open "$demo" "${args[@]}" --turntable 5 --turn-frames 8-11 --frames 20 --screenshot "$out/turned.png" |
       grep '^still:' || true)
echo "$line"
ms=$(sed -n 's/^still: the first default frame shown \([0-9]*\) ms after the view stopped, \([0-9]*\) frames refined by the end$/\1 \2/p' <<<"$line")
[ -n "$ms" ] || fail "no still line with a time: '$line'"
read -r _ refined <<<"$ms"
[ "$refined" -ge 1 ] || fail "no frame refined after the view stopped"
# The still view shows the lit stage, not an empty viewport.
m=$(convert "$out/turned.png" -crop 250x330+200+25 +repage -colorspace Gray -format "%[fx:mean]" info:)
awk -v m="$m" 'BEGIN { exit !(m > 0.01) }' || fail "the still view is black ($m)"
passed=$((passed + 1))

# Without --turn-frames the view turns every frame: no still line.
line=$("$haze" open "$demo" "${args[@]}" --turntable 5 --frames 6 | grep '^still:' || true)
[ -z "$line" ] || fail "a view that never stopped printed '$line'"
passed=$((passed + 1))

if capture=$(data_path gdtf/mvr/capture_demo_show.mvr); then
  "$haze" import-mvr "$capture" -o "$out/capture.haze.json" >/dev/null 2>&1 || fail "import-mvr $capture"
  # A 1905x739 window leaves the viewport 1280x720 beside the panels.
  line=$("$haze" open "$out/capture.haze.json" --width 1905 --height 739 --quality default --turntable 1 \
         --turn-frames 10-13 --frames 24 | grep -E '^(turntable|still):' || true)
  echo "Capture rig (load $(cut -d' ' -f1 /proc/loadavg)): $line"
  grep -q '^still: the first default frame shown [0-9]* ms' <<<"$line" || fail "no still line on the Capture rig"
  grep -q ' of 1280x720,' <<<"$line" || fail "the Capture rig's viewport is not 1280x720"
  passed=$((passed + 1))
else
  want_data gdtf/mvr/capture_demo_show.mvr || true
fi
echo "$passed passed, 0 failed"
data_exit 0
