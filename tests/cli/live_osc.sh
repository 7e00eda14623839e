#!/usr/bin/env bash
# haze live --osc: remote control from liblo's oscsend (liblo-tools, an OSC implementation other
# than haze's use of liblo's decoder: it encodes) and from a few hand-encoded datagrams in
# Python (to read the replies). GO, GO, BACK, GOTO 3 and a fixture attribute, checked in the log
# and in the final state (cues of tests/data/live/cues.haze.json have fades of 0); malformed
# messages are refused with a reply and counted.
# usage: bash live_osc.sh HAZE_BINARY REPO_ROOT
set -u
HAZE=$1
ROOT=$2
TMP=$(mktemp -d)
HAZE_PID=""
cleanup() {
  [ -n "$HAZE_PID" ] && kill "$HAZE_PID" 2>/dev/null
  rm -rf "$TMP"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; echo "--- haze stderr:"; cat "$TMP/err" 2>/dev/null; exit 1; }

if ! command -v oscsend >/dev/null; then
  echo "SKIP: oscsend (Debian liblo-tools) is not installed; tools/install-deps.sh installs it"
  exit 0
fi

# OSC on the Art-Net port would share it (SO_REUSEPORT) and split the datagrams: refused.
if "$HAZE" live "$ROOT/tests/data/live/cues.haze.json" --osc 6454 --duration 1 2>"$TMP/err"; then
  fail "--osc on the Art-Net port was accepted"
fi
grep -q "expected a port of its own" "$TMP/err" || fail "no clear message for --osc on the Art-Net port"

"$HAZE" live "$ROOT/tests/data/live/cues.haze.json" --sacn --sacn-port 0 --osc 0 --movement instant \
  --state-json "$TMP/state.json" 2>"$TMP/err" &
HAZE_PID=$!
PORT=""
for _ in $(seq 600); do
  PORT=$(sed -n 's/^haze live: OSC on 127\.0\.0\.1:\([0-9][0-9]*\)$/\1/p' "$TMP/err")
  [ -n "$PORT" ] && break
  kill -0 "$HAZE_PID" 2>/dev/null || fail "haze live exited before listening"
  sleep 0.1
done
[ -n "$PORT" ] || fail "haze live did not report its OSC port"

# Each command waits for haze to log it, so the order on stage is the order sent.
send() {
  local want=$1
  shift
  oscsend 127.0.0.1 "$PORT" "$@" || fail "oscsend $* failed"
  for _ in $(seq 300); do
    grep -q "$want" "$TMP/err" && return 0
    sleep 0.05
  done
  fail "haze did not log '$want' after oscsend $*"
}
send 'OSC /haze/go from .*: cue 1$' /haze/go
send 'OSC /haze/go from .*: cue 2$' /haze/go
send 'OSC /haze/back from .*: cue 1$' /haze/back
send 'OSC /haze/cue from .*: cue 3$' /haze/cue s 3
send 'OSC /haze/fixture/2/intensity from .*: fixture 2$' /haze/fixture/2/intensity f 0.5
send 'OSC /haze/fixture/2/color from .*: fixture 2$' /haze/fixture/2/color fff 0 1 0.25

# Replies, and refusals: a datagram from Python's socket, hand-encoded, with the reply read back.
python3 - "$PORT" <<'PY' || fail "OSC replies were not as expected"
import socket, struct, sys
port = int(sys.argv[1])
def s(x):
    b = x.encode() + b'\0'
    return b + b'\0' * (-len(b) % 4)
def msg(address, tags='', *args):
    out = s(address) + s(',' + tags)
    for t, a in zip(tags, args):
        out += struct.pack('>f', a) if t == 'f' else struct.pack('>i', a) if t == 'i' else s(a)
    return out
def strings(b):
    return [x.decode() for x in b.split(b'\0') if x]
sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sock.settimeout(10)
def ask(b):
    sock.sendto(b, ('127.0.0.1', port))
    return strings(sock.recv(2048))
got = ask(msg('/haze/cue', 's', '3'))
assert got == ['/haze/ok', ',s', '/haze/cue'], got
got = ask(msg('/haze/cue', 's', '9'))
assert got[0] == '/haze/error' and got[2] == '/haze/cue' and 'has no cue "9"' in got[3], got
got = ask(msg('/haze/fixture/1/intensity', 'f', 7.0))
assert got[0] == '/haze/error' and '0..1' in got[3], got
got = ask(b'/haze/go\0\0\0')  # unpadded: not OSC
assert got[0] == '/haze/error' and 'well-formed' in got[3], got
PY

kill -INT "$HAZE_PID"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"
grep -q 'haze live: OSC: 7 commands done, 3 refused' "$TMP/err" || fail "the OSC counts are not 7 done, 3 refused"

# Cue 3 tracks cue 1's par (red at full) and sets fixture 1 to 0.6 at pan 90; fixture 2 is
# the programmer's: 0.5, green with a little blue.
node -e '
const s = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
const want = {"1": {intensity: 0.6, pan: 90}, "2": {intensity: 0.5, color: [0, 1, 0.25]}, "3": {intensity: 1, color: [1, 0, 0]}};
let bad = 0;
for (const [id, attrs] of Object.entries(want))
  for (const [k, v] of Object.entries(attrs)) {
    const got = s[id][k];
    const ok = Array.isArray(v) ? v.every((x, i) => Math.abs(got[i] - x) < 1e-6) : Math.abs(got - v) < 1e-6;
    if (!ok) { console.error("fixture " + id + " " + k + ": got " + JSON.stringify(got) + ", want " + JSON.stringify(v)); bad++; }
  }
process.exit(bad ? 1 : 0);
' "$TMP/state.json" || fail "fixture states differ from the cues and the programmer"
echo "PASS live_osc"
