#!/usr/bin/env bash
# haze live warns at start, in one line, when another program already listens on the port and
# address it binds (as olad or a second visualiser does, with SO_REUSEADDR): unicast Art-Net
# (or sACN) to that address then reaches only one of the two sockets. The listener is this
# test's own, on a 127.0.0.0/8 address of its own (loopback only, so parallel tests and the
# real 127.0.0.1:6454 are left alone), on the real ports 6454 and 5568, since the port-0 runs of
# the other live tests never share. No warning without the listener, nor for one on another
# loopback address (which shares nothing); a listener that does not allow sharing makes haze
# refuse the port, in one line.
# usage: bash live_port_shared.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
show="$ROOT/tests/data/live/live.haze.json"
# 127.100-199.x.y: away from 127.0.0.1 and 127.77.0.x (tests/cli/live_ola.sh).
addr="127.$((100 + RANDOM % 100)).$((1 + RANDOM % 250)).$((1 + RANDOM % 250))"
other="${addr%.*}.$(( (${addr##*.} % 250) + 1 ))"

LISTEN_PID=""
# listen ADDR PORT REUSE: a UDP socket held open in the background (LISTEN_PID) until stopped.
listen() {
  local ready="$TMP/listen.$1.$2.$3"
  rm -f "$ready"
  python3 -c '
import socket, sys, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
if sys.argv[3] == "reuse":
    s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind((sys.argv[1], int(sys.argv[2])))
open(sys.argv[4], "w").write("ready")
time.sleep(120)' "$1" "$2" "$3" "$ready" 2>"$TMP/listen.err" &
  LISTEN_PID=$!
  for _ in $(seq 100); do
    [ -s "$ready" ] && return 0
    kill -0 "$LISTEN_PID" 2>/dev/null || fail "the test's listener on $1:$2 did not start: $(cat "$TMP/listen.err")"
    sleep 0.1
  done
  fail "the test's listener on $1:$2 was not ready within 10 s"
}
unlisten() { kill "$LISTEN_PID" 2>/dev/null; wait "$LISTEN_PID" 2>/dev/null; LISTEN_PID=""; }
trap 'unlisten; _live_cleanup' EXIT
warnings() { grep -c "warning: another program already listens on" "$HAZE_ERR"; }

# Art-Net: the listener first, then haze on the same address for a bounded second.
listen "$addr" 6454 reuse
live_run "$show" --artnet --bind "$addr" --duration 1 || fail "haze live exited with $?"
grep -qF "haze live: warning: another program already listens on $addr:6454: Art-Net sent unicast to this address reaches only one of the two" "$HAZE_ERR" ||
  fail "no warning naming $addr:6454 and the consequence"
[ "$(warnings)" -eq 1 ] || fail "$(warnings) warnings, expected one line"
grep -q "docs/live.md" "$HAZE_ERR" || fail "the warning does not say where the remedy is documented"
# A listener on another loopback address of the same port shares nothing.
live_run "$show" --artnet --bind "$other" --duration 0.2 || fail "haze live exited with $?"
[ "$(warnings)" -eq 0 ] || fail "a warning for $other, which no one else holds"
unlisten
# Without the listener: no warning.
live_run "$show" --artnet --bind "$addr" --duration 0.2 || fail "haze live exited with $?"
[ "$(warnings)" -eq 0 ] || fail "a warning with no other listener"

# sACN on its port: the same warning, naming sACN.
listen "$addr" 5568 reuse
live_run "$show" --sacn --bind "$addr" --duration 0.2 || fail "haze live exited with $?"
grep -qF "warning: another program already listens on $addr:5568: sACN sent unicast" "$HAZE_ERR" ||
  fail "no warning naming $addr:5568 and sACN"
unlisten

# A listener that does not share the port (no SO_REUSEADDR): haze cannot bind and says so, once.
listen "$addr" 6454 exclusive
live_run "$show" --artnet --bind "$addr" --duration 0.2
status=$?
[ "$status" -eq 1 ] || fail "haze live exited with $status beside an exclusive listener, expected 1"
grep -qF "cannot listen for Art-Net on $addr:6454" "$HAZE_ERR" || fail "no error naming $addr:6454"
unlisten
echo "ok: shared-port warnings for Art-Net and sACN on $addr, none without a listener or on $other"
