#!/usr/bin/env bash
# haze live --multicast on loopback: the npm `sacn` package sends to the groups 239.255.0.1 and
# 239.255.0.2 (universes 1 and 2) through 127.0.0.1; haze joins them and decodes the levels.
# Skips (exit 77, which ctest reports as skipped, never as passed) only when this machine cannot do multicast on loopback at all.
# usage: bash live_multicast.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
need_node
live_start sACN "$ROOT/tests/data/live/live.haze.json" --sacn --sacn-port 0 --multicast \
  --state-json "$TMP/state.json"
if ! grep -q "joined 239.255.0.1 (sACN universe 1)" "$HAZE_ERR"; then
  grep -q "cannot join" "$HAZE_ERR" && { echo "SKIP: no multicast on loopback here"; exit 77; }
  fail "haze did not join the group of universe 1"
fi

STREAMS='[{"universe":1,"cid":5,"name":"mc","slots":{"11":153}},
          {"universe":2,"cid":5,"name":"mc","slots":{"1":0,"2":255,"3":0}}]'
live_sender send_sacn.js "$PORT" 20 "$STREAMS" 0 multicast
if ! wait "$SEND_PID"; then
  SEND_PID=""
  if grep -qE "EADDRNOTAVAIL|ENETUNREACH|EINVAL" "$SEND_ERR"; then
    echo "SKIP: cannot send multicast through loopback here: $(cat "$SEND_ERR")"
    exit 77
  fi
  cat "$SEND_ERR"
  fail "send_sacn.js failed"
fi
SEND_PID=""
live_stop_ok
grep -q 'source sACN .* "mc" universe 2 priority 100' "$HAZE_ERR" || fail "no multicast source on universe 2"

# Fixture 2 (address 11 of universe 1): dimmer 153/255 = 0.6. Par on universe 2: pure green.
expect_state "$TMP/state.json" '{"2": {"intensity": 0.6}, "3": {"intensity": 1, "color": [0, 1, 0]}}' ||
  fail "fixture states differ from what was sent"
echo "PASS live_multicast"
