#!/usr/bin/env bash
# While the view moves, draft frames are drawn at a share of the viewport's size that keeps them
# near the draft budget (shows/scene/draft_scale.h); when it is still, the full size comes back.
# Timing-free: a budget of a microsecond is never met on any machine, so the draft must shrink to
# its smallest scale (a quarter of the width) and say the budget is not met; with no budget or a
# budget of ten seconds it stays at the viewport's size. And the still view after a shrunken draft
# is the same picture as with no budget: the still renderer was never made smaller.
set -euo pipefail
haze=$1; root=$2
. "$root/tests/gui/xvfb.bash"
start_xvfb
out=$(mktemp -d)
export XDG_CONFIG_HOME="$out/config"  # the GUI's remembered settings: its own, not the user's
trap 'kill $XVFB_PID 2>/dev/null; rm -rf "$out"' EXIT
demo=$root/examples/demo/demo.haze.json
args=(--width 640 --height 360 --cue 2 --quality draft --exposure-mode manual --exposure 0)
fail() { echo "FAIL: $*"; exit 1; }
passed=0

# "turntable: N draft frames, median M ms (...), drawn at WxH of VWxVH, budget B ms[, not met ...]"
turn() { "$haze" open "$demo" "${args[@]}" --turntable 3 --frames 12 --draft-budget "$1" --screenshot "$out/turn$1.png"; }
size_of() { sed -n 's/.*drawn at \([0-9]*\)x\([0-9]*\) of \([0-9]*\)x\([0-9]*\).*/\1 \2 \3 \4/p' <<<"$1"; }

line=$(turn 0.001); echo "$line"
read -r w h vw vh <<<"$(size_of "$line")"
[ -n "${vw:-}" ] || fail "no turntable line"
# A quarter of the viewport's width and height (rounded), and the budget named as not met.
[ $((w * 4 - vw)) -ge -4 ] && [ $((w * 4 - vw)) -le 4 ] && [ $((h * 4 - vh)) -ge -4 ] && [ $((h * 4 - vh)) -le 4 ] ||
  fail "a 1 us budget drew ${w}x${h} of ${vw}x${vh}, not a quarter"
grep -q "not met at the smallest size" <<<"$line" || fail "the unmet budget is not said"
# The stretched draft still shows the stage: not a black viewport.
m=$(convert "$out/turn0.001.png" -crop 250x330+200+25 +repage -colorspace Gray -format "%[fx:mean]" info:)
awk -v m="$m" 'BEGIN { exit !(m > 0.01) }' || fail "the shrunken draft is black ($m)"
passed=$((passed + 1))

for budget in 0 10000; do
  line=$(turn $budget); echo "$line"
  read -r w h vw vh <<<"$(size_of "$line")"
  [ "$w" = "$vw" ] && [ "$h" = "$vh" ] || fail "budget $budget drew ${w}x${h} of ${vw}x${vh}, not the full size"
  grep -q "not met" <<<"$line" && fail "budget $budget said it was not met"
  passed=$((passed + 1))
done

# Still after a shrunken start: the still frames are the full-size picture, as with no budget.
"$haze" open "$demo" "${args[@]}" --frames 6 --draft-budget 0.001 --screenshot "$out/still_tiny.png"
"$haze" open "$demo" "${args[@]}" --frames 6 --draft-budget 0 --screenshot "$out/still_none.png"
# The viewport only: the menu bar prints each frame's time.
for f in still_tiny still_none; do convert "$out/$f.png" -crop 250x330+200+25 +repage "$out/$f.view.png"; done
diff=$(compare -metric AE "$out/still_tiny.view.png" "$out/still_none.view.png" null: 2>&1 || true)
echo "still view after a 1 us draft budget against none: $diff pixels differ"
[ "$diff" = "0" ] || fail "the still view differs ($diff pixels)"
passed=$((passed + 1))
echo "$passed passed, 0 failed"
