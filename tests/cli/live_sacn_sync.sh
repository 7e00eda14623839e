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
source "$(dirname "$0")/live_session.bash" "$@"
need_node

live_start sACN "$ROOT/tests/data/live/live.haze.json" --sacn --sacn-port 0 --movement instant \
  --state-json "$TMP/state.json"

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
live_send_ready send_sacn_raw.js "$PORT" 15 "$ROUND" "$LAST"
sleep 0.3  # the last datagrams reach haze's socket

live_stop_ok
[ -f "$TMP/state.json" ] || fail "no state JSON written"

grep -q 'synchronisation: 15 sync packets, 32 frames held for them, 0 superseded before their sync, 2 still held' "$HAZE_ERR" ||
  fail "the synchronisation counts are not 15 sync packets, 32 held (2 a round, and the last 2 still held)"
grep -q 'discovered sACN source 01010101-0101-0101-0101-010101010101 "desk" universes 1,2 (1 of 1 pages)' "$HAZE_ERR" ||
  fail "the discovered source is not listed with its universes"
grep -q 'source sACN 03030303-.* "backup" universe 1 priority 100 (per-slot priorities)$' "$HAZE_ERR" ||
  fail "the per-slot priority source is not listed as such and winning"

# Fixture 1: 200/255 = 0.78431 (the unsynchronised 10 never shows); the par: red 255 -> full,
# not 10/255. Fixture 2: the dimmer from backup's 50 at per-slot 150 = 0.19608; pan from main's
# 0xC8C8 (backup leaves pan to it): -270 + 540 * 51400 / 65535 = 153.52941.
expect_state "$TMP/state.json" '{"1": {"intensity": 0.78431}, "2": {"intensity": 0.19608, "pan": 153.52941},
  "3": {"intensity": 1, "color": [1, 0, 0]}}' || fail "fixture states differ from what was sent"
echo "PASS live_sacn_sync"
