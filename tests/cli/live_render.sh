#!/usr/bin/env bash
# haze live --render: the state received over Art-Net is what gets rendered. One run gets
# fixture 1 at full from the npm `artnet` package, one run gets nothing (every fixture dark);
# both write a PNG, and the two images must differ.
# usage: bash live_render.sh HAZE_BINARY REPO_ROOT
set -u
HAZE=$1
ROOT=$2
NODE_DIR="$ROOT/tests/node"
SHOW="$ROOT/tests/data/live/live.haze.json"
TMP=$(mktemp -d)
HAZE_PID=""
cleanup() {
  [ -n "$HAZE_PID" ] && kill "$HAZE_PID" 2>/dev/null
  rm -rf "$TMP"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; echo "--- haze stderr:"; cat "$TMP/err" 2>/dev/null; exit 1; }
command -v node >/dev/null || fail "node is not installed"
RENDER=(--width 160 --height 90 --quality draft)

# Dark: nothing is sent, every fixture keeps its default (intensity 0).
"$HAZE" live "$SHOW" --artnet --artnet-port 0 --duration 0.5 --render "$TMP/dark.png" "${RENDER[@]}" \
  2>"$TMP/err" || fail "haze live (dark) failed"

# Lit: fixture 1 at full, pan and tilt near 0 (0x8000), zoom wide.
"$HAZE" live "$SHOW" --artnet --artnet-port 0 --render "$TMP/lit.png" "${RENDER[@]}" 2>"$TMP/err" &
HAZE_PID=$!
PORT=""
for _ in $(seq 600); do
  PORT=$(sed -n 's/^haze live: Art-Net on 127\.0\.0\.1:\([0-9][0-9]*\) .*$/\1/p' "$TMP/err")
  [ -n "$PORT" ] && break
  kill -0 "$HAZE_PID" 2>/dev/null || fail "haze live exited before listening"
  sleep 0.1
done
[ -n "$PORT" ] || fail "haze live did not report its Art-Net port"
(cd "$NODE_DIR" && node send_artnet.js "$PORT" 10 '{"0":[255,128,0,128,0,0,0,0,0,255]}' >"$TMP/sent" 2>&1) ||
  fail "send_artnet.js failed: $(cat "$TMP/sent")"
kill -INT "$HAZE_PID"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live (lit) exited with $STATUS"

for f in dark lit; do
  [ -s "$TMP/$f.png" ] || fail "$f.png was not written"
  [ "$(head -c 4 "$TMP/$f.png" | od -An -tx1 | tr -d ' \n')" = "89504e47" ] || fail "$f.png is not a PNG"
done
cmp -s "$TMP/dark.png" "$TMP/lit.png" && fail "the lit fixture did not change the render"
echo "PASS live_render"
