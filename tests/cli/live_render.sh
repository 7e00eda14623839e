#!/usr/bin/env bash
# haze live --render: the state received over Art-Net is what gets rendered. One run gets
# fixture 1 at full from the npm `artnet` package, one run gets nothing (every fixture dark);
# both write a PNG, and the two images must differ.
# usage: bash live_render.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
need_node
SHOW="$ROOT/tests/data/live/live.haze.json"
RENDER=(--width 160 --height 90 --quality draft)

# Dark: nothing is sent, every fixture keeps its default (intensity 0).
live_run "$SHOW" --artnet --artnet-port 0 --duration 0.5 --render "$TMP/dark.png" "${RENDER[@]}" ||
  fail "haze live (dark) failed"

# Lit: fixture 1 at full, pan and tilt near 0 (0x8000), zoom wide.
live_start Art-Net "$SHOW" --artnet --artnet-port 0 --render "$TMP/lit.png" "${RENDER[@]}"
live_send_all send_artnet.js "$PORT" 10 '{"0":[255,128,0,128,0,0,0,0,0,255]}'
live_stop_ok
# The `artnet` package sends once more when the levels are set: 10 rounds are 10 or 11 datagrams.
good=$(sed -n 's/^haze live: [0-9.]* s: .* \([0-9][0-9]*\) good .*/\1/p' "$HAZE_ERR")
[ "${good:-0}" -ge 10 ] || fail "haze counted ${good:-no} good datagrams of the 10 rounds sent"

for f in dark lit; do
  [ -s "$TMP/$f.png" ] || fail "$f.png was not written"
  [ "$(head -c 4 "$TMP/$f.png" | od -An -tx1 | tr -d ' \n')" = "89504e47" ] || fail "$f.png is not a PNG"
done
cmp -s "$TMP/dark.png" "$TMP/lit.png" && fail "the lit fixture did not change the render"
echo "PASS live_render"
