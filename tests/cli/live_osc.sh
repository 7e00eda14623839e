#!/usr/bin/env bash
# haze live --osc: remote control from liblo's oscsend (liblo-tools, an OSC implementation other
# than haze's use of liblo's decoder: it encodes) and from a few hand-encoded datagrams in
# Python (to read the replies). GO, GO, BACK, GOTO 3 and a fixture attribute, checked in the log
# and in the final state (cues of tests/data/live/cues.haze.json have fades of 0); malformed
# messages are refused with a reply and counted.
# usage: bash live_osc.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
command -v oscsend >/dev/null || fail "oscsend (Debian liblo-tools) is not installed; tools/install-deps.sh installs it"

# OSC on the Art-Net port would share it (SO_REUSEPORT) and split the datagrams: refused.
live_run "$ROOT/tests/data/live/cues.haze.json" --osc 6454 --duration 1 &&
  fail "--osc on the Art-Net port was accepted"
grep -q "expected a port of its own" "$HAZE_ERR" || fail "no clear message for --osc on the Art-Net port"

live_start OSC "$ROOT/tests/data/live/cues.haze.json" --sacn --sacn-port 0 --osc 0 --movement instant \
  --state-json "$TMP/state.json"

# Each command waits for haze to log it, so the order on stage is the order sent.
osc_send 'OSC /haze/go from .*: cue 1$' /haze/go
osc_send 'OSC /haze/go from .*: cue 2$' /haze/go
osc_send 'OSC /haze/back from .*: cue 1$' /haze/back
osc_send 'OSC /haze/cue from .*: cue 3$' /haze/cue s 3
osc_send 'OSC /haze/fixture/2/intensity from .*: fixture 2$' /haze/fixture/2/intensity f 0.5
osc_send 'OSC /haze/fixture/2/color from .*: fixture 2$' /haze/fixture/2/color fff 0 1 0.25

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

live_stop_ok
grep -q 'haze live: OSC: 7 commands done, 3 refused' "$HAZE_ERR" || fail "the OSC counts are not 7 done, 3 refused"

# Cue 3 tracks cue 1's par (red at full) and sets fixture 1 to 0.6 at pan 90; fixture 2 is
# the programmer's: 0.5, green with a little blue.
expect_state "$TMP/state.json" '{"1": {"intensity": 0.6, "pan": 90}, "2": {"intensity": 0.5, "color": [0, 1, 0.25]},
  "3": {"intensity": 1, "color": [1, 0, 0]}}' 1e-6 || fail "fixture states differ from the cues and the programmer"

# /haze/camera: the live render is seen through the show's camera the message names, the same
# picture as `haze render --cue 3 --camera Side`; an unknown name is refused with /haze/error.
live_start OSC "$ROOT/tests/data/live/cues.haze.json" --sacn --sacn-port 0 --osc 0 --movement instant \
  --width 64 --height 36 --quality draft --render "$TMP/live.pfm"
osc_send 'OSC /haze/cue from .*: cue 3$' /haze/cue s 3
osc_send 'OSC /haze/camera from .*: camera "Side"$' /haze/camera s Side
python3 - "$PORT" <<'PY' || fail "the /haze/camera replies were not as expected"
import socket, sys
port = int(sys.argv[1])
def s(x):
    b = x.encode() + b'\0'
    return b + b'\0' * (-len(b) % 4)
sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sock.settimeout(10)
def ask(b):
    sock.sendto(b, ('127.0.0.1', port))
    return [x.decode() for x in sock.recv(2048).split(b'\0') if x]
got = ask(s('/haze/camera') + s(',s') + s('Balcony'))
assert got[0] == '/haze/error' and got[2] == '/haze/camera' and 'no camera' in got[3] and '"FOH", "Side"' in got[3], got
got = ask(s('/haze/camera') + s(','))
assert got[0] == '/haze/error' and 'camera name' in got[3], got
PY
live_stop_ok
grep -q 'haze live: OSC: 2 commands done, 2 refused' "$HAZE_ERR" || fail "the OSC counts are not 2 done, 2 refused"
"$HAZE" render "$ROOT/tests/data/live/cues.haze.json" --cue 3 --camera Side --width 64 --height 36 --quality draft \
  -o "$TMP/side.pfm" || fail "haze render --camera Side failed"
"$HAZE" render "$ROOT/tests/data/live/cues.haze.json" --cue 3 --width 64 --height 36 --quality draft \
  -o "$TMP/foh.pfm" || fail "haze render (FOH) failed"
cmp -s "$TMP/live.pfm" "$TMP/side.pfm" || fail "the live render after /haze/camera Side is not the Side camera's picture"
cmp -s "$TMP/live.pfm" "$TMP/foh.pfm" && fail "the Side and FOH cameras give the same picture"
echo "PASS live_osc"
