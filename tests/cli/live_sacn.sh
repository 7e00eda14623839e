#!/usr/bin/env bash
# haze live with sACN from the npm `sacn` package (tests/node/send_sacn.js) on 127.0.0.1:
# priorities (a priority-50 backup sending full loses), HTP between two priority-100 sources,
# 16-bit pan/tilt, CMY, gobo slot, zoom, an RGB par on universe 2, malformed packets counted,
# and SIGINT ending the run. Expected values are worked out by hand below.
# usage: bash live_sacn.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
need_node

# Port 0: haze picks a free port and prints it, so parallel test runs never collide.
live_start sACN "$ROOT/tests/data/live/live.haze.json" --sacn --sacn-port 0 --state-json "$TMP/state.json"

# Universe 1 (fixture 1 at 1, fixture 2 at 11; Dimmer, Pan, Pan fine, Tilt, Tilt fine, C, M, Y,
# Gobo, Zoom): main sets fixture 1; htp raises fixture 2's dimmer; backup (priority 50) sends
# everything at full and must not show. Universe 2: the RGB par (fixture 3) at 1.
STREAMS='[
 {"universe":1,"priority":100,"cid":1,"name":"main",
  "slots":{"1":255,"2":192,"3":0,"4":64,"5":0,"6":0,"7":255,"8":0,"9":150,"10":128,"11":51}},
 {"universe":1,"priority":100,"cid":3,"name":"htp","slots":{"11":102}},
 {"universe":1,"priority":50,"cid":2,"name":"backup",
  "slots":{"1":255,"2":255,"3":255,"4":255,"5":255,"6":255,"7":255,"8":255,"9":255,"10":255,
           "11":255,"12":255,"13":255,"14":255,"15":255,"16":255,"17":255,"18":255,"19":255,"20":255}},
 {"universe":2,"priority":100,"cid":1,"name":"main","slots":{"1":255,"2":128,"3":0}}
]'
live_send_ready send_sacn.js "$PORT" 60 "$STREAMS" 3

# Stop haze while every source is still sending (SIGINT: the Ctrl-C path).
live_stop_ok
[ -f "$TMP/state.json" ] || fail "no state JSON written"

grep -q "malformed sacn.bad_priority: 3" "$HAZE_ERR" || fail "the 3 bad-priority packets were not counted"
grep -q 'source sACN .* "backup" universe 1 priority 50 (outranked)' "$HAZE_ERR" ||
  fail "the backup source is not listed as outranked"

# Pan 0xC000: -270 + 540 * 49152 / 65535 = 135.00618; tilt 0x4000: -135 + 270 * 16384 / 65535
# = -67.49897; magenta full: [1, 0, 1]; gobo 150 of 4 evenly spread slots: Stars (128-191);
# zoom 128: 8 + 32 * 128 / 255 = 24.06275. Fixture 2: HTP of 51 and 102 = 0.4. Par: [1, 128/255, 0]
# at full. Fixture 4 is unpatched: defaults, zoom = the profile's field angle 20.
expect_state "$TMP/state.json" '{
  "1": {"intensity": 1, "pan": 135.00618, "tilt": -67.49897, "color": [1, 0, 1], "zoom": 24.06275,
        "gobo": "Stars", "gobo_rotation": 0, "iris": 1},
  "2": {"intensity": 0.4, "pan": -270, "tilt": -135, "color": [1, 1, 1], "zoom": 8, "gobo": "Open"},
  "3": {"intensity": 1, "color": [1, 0.50196, 0]},
  "4": {"intensity": 0, "pan": 0, "tilt": 0, "color": [1, 1, 1], "zoom": 20, "gobo": "Open", "iris": 1}
}' || fail "fixture states differ from what was sent"
echo "PASS live_sacn"
