#!/usr/bin/env bash
# Recording what a console sends, from the GUI (docs/gui.md): haze open --sacn on a copy of the
# demo, an sACN stream from the npm `sacn` package (an encoder independent of haze's) sets the
# first spot to full at pan 0xC000 and tilt 0x4000 and the rest of universe 1 to zero; Ctrl+Shift+R
# records the look as a new cue after the bows, Ctrl+S saves it, and `haze state --cue 6` of the
# saved show has the spot where DMX put it and the washes (full at the bows) out.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"
[ -d "$root/tests/node/node_modules/sacn" ] || { echo "FAIL: the npm sacn package is missing (make node-tools)"; exit 1; }
show="$tmp/demo.haze.json"
python3 "$root/tests/show_copy.py" "$root/examples/demo/demo.haze.json" "$show"
# A loopback address of this test's own (from its unique X display), so copies side by side do
# not share the sACN port.
n=${DISPLAY#:}
addr=127.77.$((n / 250 % 250)).$((n % 250 + 2))

start_haze "haze - demo" "$show" --width 640 --height 360 --quality draft --sacn --bind "$addr"
SACN_HOST=$addr node "$root/tests/node/send_sacn.js" 5568 3000 \
  '[{"universe": 1, "priority": 100, "cid": 7, "name": "console", "slots": {"1": 255, "2": 192, "4": 64}}]' \
  >"$tmp/sent" 2>&1 &
sender=$!
GUI_KILL=$sender
wait_until 60 'grep -q ready "$tmp/sent"' || { echo "FAIL: the sender never got going: $(cat "$tmp/sent")"; exit 1; }
sleep 0.5
tap ctrl+shift+r
check "Ctrl+Shift+R records a cue (title '$(title)')" '[ "$(title)" = "haze - demo.haze.json *" ]'
tap ctrl+s
kill $sender 2>/dev/null; GUI_KILL=""
tap ctrl+q
wait_exit
check "Ctrl+Q exits cleanly (status $rc)" '[ "$rc" = 0 ]'
"$haze" state "$show" --cue 6 --json >"$tmp/cue6.json" 2>"$tmp/state.err"
check "the saved show has cue 6 ($(head -c 200 "$tmp/state.err"))" '[ -s "$tmp/cue6.json" ]'
# Pan 0xC000: -270 + 540 * 49152 / 65535 = 135.00618; tilt 0x4000: -135 + 270 * 16384 / 65535 = -67.49897.
check "cue 6 holds the look DMX set" 'node "$root/tests/node/expect_state.js" "$tmp/cue6.json" \
  "{\"101\": {\"intensity\": 1, \"pan\": 135.00618, \"tilt\": -67.49897}, \"102\": {\"intensity\": 0},
    \"201\": {\"intensity\": 0}, \"204\": {\"intensity\": 0}}" 1e-3 "cue 6: fixture"'
check "the cue is labelled" 'grep -q "\"label\": \"from DMX\"" "$show"'
finish
