#!/usr/bin/env bash
# haze live under a flood of bad and chatty input on all three sockets at once: 10,000 Art-Net
# datagrams (ArtPoll, ArtTimeCode beyond 24 h, truncated ArtDmx, ArtSync, random bytes), 10,000
# sACN ones (broken synchronization and discovery packets, per-slot priorities above 200, random
# bytes) and 3,000 malformed OSC messages, from Python. haze must not crash, must still answer
# an OSC command afterwards, must count what it rejected by reason, and its memory must stay
# bounded (resident size measured before and after). The longest pass of its receive loop
# during the flood is printed (a measurement, not a pass/fail limit: this machine is shared).
# usage: bash live_flood.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
live_start OSC "$ROOT/tests/data/live/cues.haze.json" --artnet-port 0 --sacn-port 0 --osc 0 --timecode
ART=$(live_port Art-Net)
SACN=$(live_port sACN)
OSC=$PORT
[ -n "$ART" ] && [ -n "$SACN" ] || fail "haze live did not report its Art-Net and sACN ports"
rss() { sed -n 's/^VmRSS:[[:space:]]*\([0-9][0-9]*\) kB$/\1/p' "/proc/$HAZE_PID/status"; }
RSS_BEFORE=$(rss)
[ -n "$RSS_BEFORE" ] || fail "cannot read haze's resident size from /proc/$HAZE_PID/status" 

python3 - "$ART" "$SACN" "$OSC" <<'PY' || fail "the flood sender failed"
import random, socket, struct, sys, time
art, sacn, osc = (int(x) for x in sys.argv[1:4])
rng = random.Random(16)
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
def artnet(op, body):
    return b'Art-Net\0' + struct.pack('<H', op) + b'\x00\x0e' + body
def root(vector, body):
    size = 38 + len(body)
    return (struct.pack('>HH', 0x10, 0) + b'ASC-E1.17\0\0\0' + struct.pack('>HI', 0x7000 | (size - 16), vector) +
            bytes([0x33] * 16) + body)
def sacn_sync(addr):
    return root(8, struct.pack('>HI', 0x7000 | 11, 1) + bytes([1]) + struct.pack('>H', addr) + b'\0\0')
def sacn_discovery(page, last, universes):
    layer = struct.pack('>HIBB', 0x7000 | (8 + 2 * len(universes)), 1, page, last) + b''.join(struct.pack('>H', u) for u in universes)
    return root(8, struct.pack('>HI', 0x7000 | (74 + len(layer)), 2) + b'flood'.ljust(64, b'\0') + b'\0' * 4 + layer)
def sacn_pap(prios):
    n = len(prios)
    dmp = struct.pack('>HBBHHH', 0x7000 | (11 + n), 2, 0xa1, 0, 1, n + 1) + bytes([0xdd]) + bytes(prios)
    fr = struct.pack('>HI', 0x7000 | (77 + len(dmp)), 2) + b'flood'.ljust(64, b'\0') + bytes([100]) + b'\0\0' + bytes([1, 0]) + struct.pack('>H', 1)
    return root(4, fr + dmp)
arts = [
    lambda: artnet(0x2000, b'\x00\x00'),                                # ArtPoll
    lambda: artnet(0x9700, b'\0\0' + bytes([0, 0, 0, 25 + rng.randrange(200), 1])),  # beyond 24 h
    lambda: artnet(0x5000, b'\x01\x00\x00\x00\x02\x00\x01'),            # says 512, holds 1
    lambda: artnet(0x5200, b'\0\0'),                                    # ArtSync
    lambda: bytes(rng.randrange(256) for _ in range(rng.randrange(1, 600))),
]
sacns = [
    lambda: sacn_sync(rng.choice([0, 64000, rng.randrange(1, 64000)])),
    lambda: sacn_discovery(5, 2, [1]),                                  # page after the last
    lambda: sacn_discovery(0, 0, [0, 70000 % 65536]),
    lambda: sacn_pap([201] * 8),
    lambda: sacn_sync(7)[:40],
    lambda: bytes(rng.randrange(256) for _ in range(rng.randrange(1, 700))),
]
oscs = [
    lambda: b'/haze/go\0\0',
    lambda: b'/haze/fixture/1/intensity\0\0\0,f\0\0' + struct.pack('>f', float('nan')),
    lambda: b'#bundle\0' + bytes(rng.randrange(256) for _ in range(20)),
    lambda: b'/haze/cue\0\0\0,s\0\0' + b'9' * 40,
    lambda: bytes(rng.randrange(256) for _ in range(rng.randrange(1, 300))),
]
for i in range(10000):
    s.sendto(rng.choice(arts)(), ('127.0.0.1', art))
    s.sendto(rng.choice(sacns)(), ('127.0.0.1', sacn))
    if i % 10 < 3:
        s.sendto(rng.choice(oscs)(), ('127.0.0.1', osc))
    if i % 100 == 99:
        time.sleep(0.002)  # leave the kernel's receive buffers room: rejected ones are what is counted
# haze is still there: a well-formed GO is answered.
s.settimeout(20)
s.sendto(b'/haze/go\0\0\0\0,\0\0\0', ('127.0.0.1', osc))
while True:
    data, _ = s.recvfrom(4096)  # ArtPollReplies may still be arriving first
    if data.startswith(b'/haze/ok'):
        break
PY
RSS_AFTER=$(rss)
[ -n "$RSS_AFTER" ] || fail "cannot read haze's resident size after the flood"
kill -INT "$HAZE_PID"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS after the flood"

count() { sed -n "s/^haze live: malformed $1: \([0-9]*\)$/\1/p" "$HAZE_ERR"; }
for reason in artnet.timecode_bad_time artnet.truncated sacn.bad_sync_address sacn.bad_discovery_page \
              sacn.bad_discovery_universe sacn.bad_priority; do
  n=$(count "$reason")
  [ -n "$n" ] && [ "$n" -gt 0 ] || fail "no rejected packets counted as $reason"
done
grep -q "haze live: answered [0-9]* ArtPolls" "$HAZE_ERR" || fail "the ArtPolls were not answered"
grep -Eq "haze live: OSC: 1 commands done, [0-9]{3,} refused" "$HAZE_ERR" || fail "the malformed OSC messages were not refused and counted"
grep -E "^haze live: [0-9.]+ s: |^haze live: OSC: |^haze live: answered " "$HAZE_ERR"
GROWTH=$(( RSS_AFTER - RSS_BEFORE ))
echo "resident size: $RSS_BEFORE kB before, $RSS_AFTER kB after the flood; $(grep 'longest pass' "$HAZE_ERR" | sed 's/^haze live: //')"
[ "$GROWTH" -lt 65536 ] || fail "haze grew by $GROWTH kB during the flood"
echo "PASS live_flood"
