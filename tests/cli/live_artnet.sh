#!/usr/bin/env bash
# haze live with Art-Net from the npm `artnet` package (tests/node/send_artnet.js) on 127.0.0.1:
# Art-Net Port-Address 0 drives haze universe 1 and Port-Address 1 universe 2 (haze universe =
# Port-Address + 1); the run ends by --duration, and the state JSON holds what was sent.
# usage: bash live_artnet.sh HAZE_BINARY REPO_ROOT
set -u
HAZE=$1
ROOT=$2
NODE_DIR="$ROOT/tests/node"
TMP=$(mktemp -d)
HAZE_PID=""
SEND_PID=""
cleanup() {
  [ -n "$SEND_PID" ] && kill "$SEND_PID" 2>/dev/null
  [ -n "$HAZE_PID" ] && kill "$HAZE_PID" 2>/dev/null
  rm -rf "$TMP"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; echo "--- haze stderr:"; cat "$TMP/err" 2>/dev/null; exit 1; }

command -v node >/dev/null || fail "node is not installed"

# A wrong option is a clear one-line error and a non-zero exit.
if "$HAZE" live "$ROOT/tests/data/live/live.haze.json" --bind not-an-address --duration 1 2>"$TMP/err"; then
  fail "--bind not-an-address was accepted"
fi
grep -q "not an IPv4 address" "$TMP/err" || fail "no clear message for a bad --bind"

# --duration 4: Art-Net sources stay live 10 s after their last packet, so the run ends with
# the sender's levels whatever the timing; the sender starts as soon as haze listens.
"$HAZE" live "$ROOT/tests/data/live/live.haze.json" --artnet --artnet-port 0 --duration 4 \
  --state-json "$TMP/state.json" 2>"$TMP/err" &
HAZE_PID=$!
PORT=""
for _ in $(seq 600); do
  PORT=$(sed -n 's/^haze live: Art-Net on 127\.0\.0\.1:\([0-9][0-9]*\) .*$/\1/p' "$TMP/err")
  [ -n "$PORT" ] && break
  kill -0 "$HAZE_PID" 2>/dev/null || fail "haze live exited before listening"
  sleep 0.1
done
[ -n "$PORT" ] || fail "haze live did not report its Art-Net port"

# Port-Address 0: fixture 1 at 1 (Dimmer 204, pan 0x8000, tilt 0xFFFF, cyan 255, gobo 70, zoom 255)
# and fixture 2 at 11 (dimmer 0). Port-Address 1: the RGB par: (0, 0, 51).
UNIVERSES='{"0":[204,128,0,255,255,255,0,0,70,255,0],"1":[0,0,51]}'
(cd "$NODE_DIR" && node send_artnet.js "$PORT" 15 "$UNIVERSES" >"$TMP/sent" 2>"$TMP/send_err") &
SEND_PID=$!
wait "$SEND_PID" || { cat "$TMP/send_err"; fail "send_artnet.js failed"; }
SEND_PID=""
grep -q ready "$TMP/sent" || fail "send_artnet.js never got ready"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"
[ -f "$TMP/state.json" ] || fail "no state JSON written"
grep -q "source Art-Net 127.0.0.1:" "$TMP/err" || fail "the Art-Net source is not listed"

# Dimmer 204/255 = 0.8; pan 0x8000: -270 + 540 * 32768 / 65535 = 0.00412; tilt 0xFFFF = 135;
# cyan full: [0, 1, 1]; gobo 70 of 4 evenly spread slots: Dots (64-127); zoom 255 = 40.
# Par (0, 0, 51) without a dimmer channel: intensity 0.2, colour [0, 0, 1].
node -e '
const s = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
const want = {
  "1": {intensity: 0.8, pan: 0.00412, tilt: 135, color: [0, 1, 1], zoom: 40, gobo: "Dots"},
  "2": {intensity: 0, pan: -270, tilt: -135},
  "3": {intensity: 0.2, color: [0, 0, 1]},
};
let bad = 0;
for (const [id, attrs] of Object.entries(want)) {
  if (!s[id]) { console.error("fixture " + id + " missing"); bad++; continue; }
  for (const [k, v] of Object.entries(attrs)) {
    const got = s[id][k];
    const ok = Array.isArray(v) ? Array.isArray(got) && v.every((x, i) => Math.abs(got[i] - x) < 1e-3)
             : typeof v === "string" ? got === v : Math.abs(got - v) < 1e-3;
    if (!ok) { console.error("fixture " + id + " " + k + ": got " + JSON.stringify(got) + ", want " + JSON.stringify(v)); bad++; }
  }
}
process.exit(bad ? 1 : 0);
' "$TMP/state.json" || fail "fixture states differ from what was sent"
echo "PASS live_artnet"
