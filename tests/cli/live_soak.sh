#!/usr/bin/env bash
# The live soak: `haze live` under a sustained 44 Hz sACN stream on 8 patched universes while
# sources come and go (tests/node/soak_sacn.js: a winning source that leaves with
# stream-terminated and returns, one that goes silent and times out), for SECONDS (30 in
# ctest, 600 in `make soak`). It holds when every datagram sent is counted as received and none
# as late or malformed, and haze's resident memory stays flat: after the first fifth of the run
# the largest sample is within 5 % of the smallest. Prints the figures.
# usage: live_soak.sh HAZE REPO [SECONDS]
seconds=${3:-30}
source "$(dirname "$0")/live_session.bash" "$1" "$2"
need_node

# The demo's twelve fixtures, spread over universes 1-8 (its venue and profiles by absolute path).
python3 "$ROOT/tests/show_copy.py" "$ROOT/examples/demo/demo.haze.json" "$TMP/soak.haze.json" --spread-universes 8

live_start sACN "$TMP/soak.haze.json" --sacn --sacn-port 0 --no-preview --duration $((seconds + 5))

live_sender soak_sacn.js "$PORT" "$seconds"
: >"$TMP/rss"
while kill -0 "$SEND_PID" 2>/dev/null; do
  awk '/^VmRSS:/ { print $2 }' "/proc/$HAZE_PID/status" >>"$TMP/rss" 2>/dev/null
  sleep 1
done
wait "$SEND_PID" || fail "the sender failed: $(cat "$SEND_ERR")"
SEND_PID=""
live_wait_ok

sent=$(sed -n 's/.*"sent":\([0-9]*\).*/\1/p' "$SEND_OUT")
report=$(grep -E '^haze live: [0-9.]+ s: ' "$HAZE_ERR")
num() { echo "$report" | sed -n "s/.* \([0-9][0-9]*\) $1.*/\1/p"; }
received=$(num datagrams); malformed=$(num malformed); late=$(num late)
samples=$(wc -l <"$TMP/rss")
read -r lo hi < <(awk -v n="$samples" 'NR > n / 5 { if (!lo || $1 < lo) lo = $1; if ($1 > hi) hi = $1 } END { print lo, hi }' "$TMP/rss")
echo "soak: ${seconds} s, $sent datagrams sent, $received received, $late late, $malformed malformed;" \
     "RSS after the first fifth $lo..$hi kB over $samples samples"
grep '^haze live: source' "$HAZE_ERR"
[ -n "$sent" ] && [ "$sent" -gt $((seconds * 44 * 8 * 9 / 10)) ] || fail "the sender sent $sent datagrams, short of 44 Hz on 8 universes"
[ "$received" = "$sent" ] || fail "haze counted $received datagrams of the $sent sent"
[ "$late" = 0 ] && [ "$malformed" = 0 ] || fail "$late late and $malformed malformed on a clean stream"
[ "$samples" -ge 5 ] || fail "only $samples memory samples"
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(hi <= lo * 1.05) }' || fail "memory grew from $lo to $hi kB"
echo "1 passed, 0 failed"
