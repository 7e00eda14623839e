#!/usr/bin/env bash
# The live soak: `haze live` under a sustained 44 Hz sACN stream on 8 patched universes while
# sources come and go (tests/node/soak_sacn.js: a winning source that leaves with
# stream-terminated and returns, one that goes silent and times out), for SECONDS (30 in
# ctest, 600 in `make soak`). It holds when every datagram sent is counted as received and none
# as late or malformed, and haze's resident memory stays flat: after the first fifth of the run
# the largest sample is within 5 % of the smallest. Prints the figures.
# usage: live_soak.sh HAZE REPO [SECONDS]
set -u
haze=$1
root=$2
seconds=${3:-30}
tmp=$(mktemp -d)
hpid=""; spid=""
trap 'kill $spid $hpid 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; echo "--- haze stderr:"; cat "$tmp/err" 2>/dev/null; exit 1; }
command -v node >/dev/null || fail "node is not installed"

# The demo's twelve fixtures, spread over universes 1-8 (its venue and profiles by absolute path).
python3 "$root/tests/show_copy.py" "$root/examples/demo/demo.haze.json" "$tmp/soak.haze.json" --spread-universes 8

"$haze" live "$tmp/soak.haze.json" --sacn --sacn-port 0 --no-preview --duration $((seconds + 5)) 2>"$tmp/err" &
hpid=$!
port=""
for _ in $(seq 600); do
  port=$(sed -n 's/^haze live: sACN on 127\.0\.0\.1:\([0-9][0-9]*\)$/\1/p' "$tmp/err")
  [ -n "$port" ] && break
  kill -0 $hpid 2>/dev/null || fail "haze live exited before listening"
  sleep 0.1
done
[ -n "$port" ] || fail "haze live did not report its sACN port"

node "$root/tests/node/soak_sacn.js" "$port" "$seconds" >"$tmp/sent" 2>"$tmp/senderr" &
spid=$!
: >"$tmp/rss"
while kill -0 $spid 2>/dev/null; do
  awk '/^VmRSS:/ { print $2 }' /proc/$hpid/status >>"$tmp/rss" 2>/dev/null
  sleep 1
done
wait $spid || fail "the sender failed: $(cat "$tmp/senderr")"
spid=""
wait $hpid; rc=$?
hpid=""
[ $rc -eq 0 ] || fail "haze live exited $rc"

sent=$(sed -n 's/.*"sent":\([0-9]*\).*/\1/p' "$tmp/sent")
report=$(grep -E '^haze live: [0-9.]+ s: ' "$tmp/err")
num() { echo "$report" | sed -n "s/.* \([0-9][0-9]*\) $1.*/\1/p"; }
received=$(num datagrams); malformed=$(num malformed); late=$(num late)
samples=$(wc -l <"$tmp/rss")
read -r lo hi < <(awk -v n="$samples" 'NR > n / 5 { if (!lo || $1 < lo) lo = $1; if ($1 > hi) hi = $1 } END { print lo, hi }' "$tmp/rss")
echo "soak: ${seconds} s, $sent datagrams sent, $received received, $late late, $malformed malformed;" \
     "RSS after the first fifth $lo..$hi kB over $samples samples"
grep '^haze live: source' "$tmp/err"
[ -n "$sent" ] && [ "$sent" -gt $((seconds * 44 * 8 * 9 / 10)) ] || fail "the sender sent $sent datagrams, short of 44 Hz on 8 universes"
[ "$received" = "$sent" ] || fail "haze counted $received datagrams of the $sent sent"
[ "$late" = 0 ] && [ "$malformed" = 0 ] || fail "$late late and $malformed malformed on a clean stream"
[ "$samples" -ge 5 ] || fail "only $samples memory samples"
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(hi <= lo * 1.05) }' || fail "memory grew from $lo to $hi kB"
echo "1 passed, 0 failed"
