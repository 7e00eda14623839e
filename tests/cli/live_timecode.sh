#!/usr/bin/env bash
# haze live --timecode: ArtTimeCode from tests/node/send_artnet_timecode.js (EBU 25 fps, one
# packet a frame) fires the cues of tests/data/live/cues.haze.json at their timecodes: cue 1 at
# 00:00:01:00, 2 at 00:00:02:00, 3 at 00:00:03:00, each logged with the frame that fired it
# (so "+-1 frame" is checked exactly: the firing frame must be the cue's own). Then a jump back
# to 00:00:01:12 chases to cue 1, and running on fires cue 2 again at its frame.
# usage: bash live_timecode.sh HAZE_BINARY REPO_ROOT
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

"$HAZE" live "$ROOT/tests/data/live/cues.haze.json" --artnet --artnet-port 0 --timecode \
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

(cd "$NODE_DIR" && node send_artnet_timecode.js "$PORT" 00:00:00:00+80 00:00:01:12+16 >"$TMP/sent" 2>"$TMP/send_err") &
SEND_PID=$!
for _ in $(seq 600); do
  grep -q ready "$TMP/sent" 2>/dev/null && break
  kill -0 "$SEND_PID" 2>/dev/null || { cat "$TMP/send_err"; fail "send_artnet_timecode.js exited early"; }
  sleep 0.1
done
grep -q ready "$TMP/sent" || fail "send_artnet_timecode.js never got ready"
sleep 0.3

kill -INT "$HAZE_PID"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"

grep '^haze live: timecode [0-9]' "$TMP/err" >"$TMP/fired"
cat >"$TMP/want" <<'WANT'
haze live: timecode 00:00:01:00: fired cue 1
haze live: timecode 00:00:02:00: fired cue 2
haze live: timecode 00:00:03:00: fired cue 3
haze live: timecode 00:00:01:12: chased to cue 1
haze live: timecode 00:00:02:00: fired cue 2
WANT
diff "$TMP/want" "$TMP/fired" || fail "cues did not fire at their timecodes"
grep -q 'haze live: timecode: 96 ArtTimeCode packets, 5 cue firings or chases' "$TMP/err" ||
  fail "not all 96 timecode packets were counted"

# After the run: cue 2 (fixture 1 at 0.4, the par tracked from cue 1).
node -e '
const s = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
if (Math.abs(s["1"].intensity - 0.4) > 1e-6 || Math.abs(s["3"].intensity - 1) > 1e-6) {
  console.error("fixture 1 at " + s["1"].intensity + ", par at " + s["3"].intensity + "; want 0.4 and 1 (cue 2)");
  process.exit(1);
}' "$TMP/state.json" || fail "the stage is not cue 2's"
echo "PASS live_timecode"
