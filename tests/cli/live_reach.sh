#!/usr/bin/env bash
# haze live says at start what the console can drive, per universe: a fixture whose mode has no
# channel haze reads is named with why, one whose mode has no dimmer is named as staying at full;
# and a universe that receives DMX but drives nothing is warned about once (a patched one whose
# fixtures cannot be driven, and one nothing is patched on).
# usage: bash live_reach.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
need_node
python3 - "$ROOT/tests/data/live/live.haze.json" "$TMP/reach.haze.json" "$ROOT/tests/data/live" <<'PY'
import json, os, sys
show = json.load(open(sys.argv[1]))
here = sys.argv[3]
show.pop("venue", None)  # the test needs no venue
show["profiles"]["spot"] = os.path.join(here, show["profiles"]["spot"])
show["profiles"]["control"] = {"inline": {"format": "haze-fixture", "version": 1, "name": "Control box",
    "photometry": {"beam_angle": 20, "field_angle": 30, "peak_candela": 1000},
    "modes": [{"name": "Control", "channels": ["Lamp control", "Reset"]}]}}
show["profiles"]["mover"] = {"inline": {"format": "haze-fixture", "version": 1, "name": "Dimmerless mover",
    "photometry": {"beam_angle": 20, "field_angle": 30, "peak_candela": 1000},
    "pan": {"min": -270, "max": 270}, "tilt": {"min": -135, "max": 135},
    "modes": [{"name": "Moves", "channels": ["Pan", "Tilt"]}]}}
show["fixtures"] += [
    {"id": 5, "name": "Box", "profile": "control", "mode": "Control", "position": [0, 6, 3], "patch": {"universe": 4, "address": 1}},
    {"id": 6, "name": "Mover", "profile": "mover", "mode": "Moves", "position": [0, 6, 4], "patch": {"universe": 2, "address": 10}}]
json.dump(show, open(sys.argv[2], "w"), indent=1)
PY
"$HAZE" validate "$TMP/reach.haze.json" >/dev/null 2>"$TMP/validate.err" || fail "the test show is not valid: $(cat "$TMP/validate.err")"

live_start sACN "$TMP/reach.haze.json" --sacn --sacn-port 0 --state-json "$TMP/state.json"
STREAMS='[{"universe":1,"cid":1,"name":"desk","slots":{"1":255}},
          {"universe":2,"cid":1,"name":"desk","slots":{"10":128,"11":128}},
          {"universe":4,"cid":1,"name":"desk","slots":{"1":255,"2":255}},
          {"universe":9,"cid":1,"name":"desk","slots":{"1":255}}]'
live_send_ready send_sacn.js "$PORT" 30 "$STREAMS"
live_stop_ok

line() { grep -qF -- "$1" "$HAZE_ERR" || fail "no line '$1'"; }
line 'haze live: universe 1: drives 2 of 2 patched fixtures: 1-2'
line 'haze live: universe 2: drives 2 of 2 patched fixtures: 3, 6'
line 'haze live: universe 2: fixture 6: mode "Moves" has no dimmer channel; intensity stays at full whatever DMX sends'
line 'haze live: universe 4: drives 0 of 1 patched fixtures'
line 'haze live: universe 4: cannot drive fixture 5: none of the 2 channels of mode "Control" is one haze reads'
for u in 4 9; do
  n=$(grep -c "^haze live: warning: universe $u receives DMX" "$HAZE_ERR")
  [ "$n" -eq 1 ] || fail "expected one warning for universe $u, got $n"
done
n=$(grep -c "^haze live: warning: universe 1 receives DMX" "$HAZE_ERR")
[ "$n" -eq 0 ] || fail "universe 1 drives its fixtures but was warned about"
expect_state "$TMP/state.json" '{"1": {"intensity": 1}, "6": {"intensity": 1}}' || fail "states differ"
echo "PASS live_reach"
