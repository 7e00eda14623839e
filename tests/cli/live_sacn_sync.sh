#!/usr/bin/env bash
# haze live with E1.31 synchronisation, per-slot priority and universe discovery, sent by
# tests/node/send_sacn_raw.js (packets written from the E1.31 tables, independently of haze):
# - universes 1 and 2 synchronised on address 7000 with Force_Synchronization: every round
#   sends both and then the sync packet; a last pair of frames is sent without its sync packet
#   and must never show (both universes keep the last synchronised look);
# - two sources on universe 1 at priority 100, one of them with per-slot priorities (0xDD):
#   150 on fixture 2's dimmer (it wins that channel though its level is lower), 0 on pan
#   (left to the other source);
# - a universe discovery packet, listed with its universes on exit.
# usage: bash live_sacn_sync.sh HAZE_BINARY REPO_ROOT
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

"$HAZE" live "$ROOT/tests/data/live/live.haze.json" --sacn --sacn-port 0 --movement instant \
  --state-json "$TMP/state.json" 2>"$TMP/err" &
HAZE_PID=$!
PORT=""
for _ in $(seq 600); do
  PORT=$(sed -n 's/^haze live: sACN on 127\.0\.0\.1:\([0-9][0-9]*\)$/\1/p' "$TMP/err")
  [ -n "$PORT" ] && break
  kill -0 "$HAZE_PID" 2>/dev/null || fail "haze live exited before listening"
  sleep 0.1
done
[ -n "$PORT" ] || fail "haze live did not report its sACN port"

# Options 32 = Force_Synchronization. Fixture 1's dimmer is slot 1 of universe 1, the par's red
# slot 1 of universe 2; fixture 2 starts at slot 11 (Dimmer, Pan, Pan fine, ...).
ROUND='[
 {"data": {"universe": 1, "cid": 1, "name": "desk", "sync": 7000, "options": 32, "slots": {"1": 200}}},
 {"data": {"universe": 2, "cid": 1, "name": "desk", "sync": 7000, "options": 32, "slots": {"1": 255}}},
 {"sync": {"address": 7000, "cid": 1}},
 {"data": {"universe": 1, "cid": 2, "name": "main", "slots": {"11": 200, "12": 200, "13": 200}}},
 {"data": {"universe": 1, "cid": 3, "name": "backup", "start": 221, "slots": {"11": 150, "12": 0, "13": 0}}},
 {"data": {"universe": 1, "cid": 3, "name": "backup", "slots": {"11": 50, "12": 255, "13": 255}}},
 {"discovery": {"cid": 1, "name": "desk", "page": 0, "last": 0, "universes": [1, 2]}}
]'
LAST='[
 {"data": {"universe": 1, "cid": 1, "name": "desk", "sync": 7000, "options": 32, "slots": {"1": 10}}},
 {"data": {"universe": 2, "cid": 1, "name": "desk", "sync": 7000, "options": 32, "slots": {"1": 10}}}
]'
(cd "$NODE_DIR" && node send_sacn_raw.js "$PORT" 15 "$ROUND" "$LAST" >"$TMP/sent" 2>"$TMP/send_err") &
SEND_PID=$!
for _ in $(seq 600); do
  grep -q ready "$TMP/sent" 2>/dev/null && break
  kill -0 "$SEND_PID" 2>/dev/null || { cat "$TMP/send_err"; fail "send_sacn_raw.js exited early"; }
  sleep 0.1
done
grep -q ready "$TMP/sent" || fail "send_sacn_raw.js never got ready"
sleep 0.3  # the last datagrams reach haze's socket

kill -INT "$HAZE_PID"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"
[ -f "$TMP/state.json" ] || fail "no state JSON written"

grep -q 'synchronisation: 15 sync packets, 32 frames held for them, 0 superseded before their sync, 2 still held' "$TMP/err" ||
  fail "the synchronisation counts are not 15 sync packets, 32 held (2 a round, and the last 2 still held)"
grep -q 'discovered sACN source 01010101-0101-0101-0101-010101010101 "desk" universes 1,2 (1 of 1 pages)' "$TMP/err" ||
  fail "the discovered source is not listed with its universes"
grep -q 'source sACN 03030303-.* "backup" universe 1 priority 100 (per-slot priorities)$' "$TMP/err" ||
  fail "the per-slot priority source is not listed as such and winning"

# Fixture 1: 200/255 = 0.78431 (the unsynchronised 10 never shows); the par: red 255 -> full,
# not 10/255. Fixture 2: the dimmer from backup's 50 at per-slot 150 = 0.19608; pan from main's
# 0xC8C8 (backup leaves pan to it): -270 + 540 * 51400 / 65535 = 153.52941.
node -e '
const s = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
const want = {"1": {intensity: 0.78431}, "2": {intensity: 0.19608, pan: 153.52941}, "3": {intensity: 1, color: [1, 0, 0]}};
let bad = 0;
for (const [id, attrs] of Object.entries(want))
  for (const [k, v] of Object.entries(attrs)) {
    const got = s[id][k];
    const ok = Array.isArray(v) ? v.every((x, i) => Math.abs(got[i] - x) < 1e-3) : Math.abs(got - v) < 1e-3;
    if (!ok) { console.error("fixture " + id + " " + k + ": got " + JSON.stringify(got) + ", want " + JSON.stringify(v)); bad++; }
  }
process.exit(bad ? 1 : 0);
' "$TMP/state.json" || fail "fixture states differ from what was sent"
echo "PASS live_sacn_sync"
