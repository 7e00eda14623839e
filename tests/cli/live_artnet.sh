#!/usr/bin/env bash
# haze live with Art-Net from the npm `artnet` package (tests/node/send_artnet.js) on 127.0.0.1:
# Art-Net Port-Address 0 drives haze universe 1 and Port-Address 1 universe 2 (haze universe =
# Port-Address + 1); the run ends by --duration, and the state JSON holds what was sent.
# usage: bash live_artnet.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
need_node

# A wrong option is a clear one-line error and a non-zero exit.
live_run "$ROOT/tests/data/live/live.haze.json" --bind not-an-address --duration 1 &&
  fail "--bind not-an-address was accepted"
grep -q "not an IPv4 address" "$HAZE_ERR" || fail "no clear message for a bad --bind"

# --duration 4: Art-Net sources stay live 10 s after their last packet, so the run ends with
# the sender's levels whatever the timing; the sender starts as soon as haze listens.
live_start Art-Net "$ROOT/tests/data/live/live.haze.json" --artnet --artnet-port 0 --duration 4 \
  --state-json "$TMP/state.json"

# Port-Address 0: fixture 1 at 1 (Dimmer 204, pan 0x8000, tilt 0xFFFF, cyan 255, gobo 70, zoom 255)
# and fixture 2 at 11 (dimmer 0). Port-Address 1: the RGB par: (0, 0, 51).
UNIVERSES='{"0":[204,128,0,255,255,255,0,0,70,255,0],"1":[0,0,51]}'
live_send_all send_artnet.js "$PORT" 15 "$UNIVERSES"
grep -q ready "$SEND_OUT" || fail "send_artnet.js never got ready"
live_wait_ok
[ -f "$TMP/state.json" ] || fail "no state JSON written"
grep -q "source Art-Net 127.0.0.1:" "$HAZE_ERR" || fail "the Art-Net source is not listed"

# Dimmer 204/255 = 0.8; pan 0x8000: -270 + 540 * 32768 / 65535 = 0.00412; tilt 0xFFFF = 135;
# cyan full: [0, 1, 1]; gobo 70 of 4 evenly spread slots: Dots (64-127); zoom 255 = 40.
# Par (0, 0, 51) without a dimmer channel: intensity 0.2, colour [0, 0, 1].
expect_state "$TMP/state.json" '{
  "1": {"intensity": 0.8, "pan": 0.00412, "tilt": 135, "color": [0, 1, 1], "zoom": 40, "gobo": "Dots"},
  "2": {"intensity": 0, "pan": -270, "tilt": -135},
  "3": {"intensity": 0.2, "color": [0, 0, 1]}
}' || fail "fixture states differ from what was sent"
echo "PASS live_artnet"
