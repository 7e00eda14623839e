#!/usr/bin/env bash
# The imported Capture rig answers the console: its stub GDTFs name every slot Dimmer1..n, and
# those are its dimmers (docs/live.md, "What the console drives"). Driven over sACN with its MVR
# patch (every slot of each patched universe at 0, then at 255, from the npm `sacn` package), every
# fixture's intensity in the state JSON is 0, then 1. At start haze says, per universe, that it
# drives every patched fixture. Skips without ../shared/data.
# usage: bash live_capture.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
mvr="$ROOT/../shared/data/gdtf/mvr/capture_demo_show.mvr"
[ -f "$mvr" ] || { echo "SKIP: $mvr is absent (the project's shared data)"; exit 77; }
need_node

"$HAZE" import-mvr "$mvr" -o "$TMP/capture.haze.json" >/dev/null 2>"$TMP/import.err" ||
  fail "import-mvr failed: $(head -3 "$TMP/import.err")"
show="$TMP/capture.haze.json"

# Every patched universe, all 512 slots at LEVEL, as send_sacn.js streams; and the wanted state:
# every patched fixture at INTENSITY.
streams() {
  python3 - "$show" "$1" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
universes = sorted({f["patch"]["universe"] for f in show["fixtures"] if f.get("patch")})
slots = {str(s): int(sys.argv[2]) for s in range(1, 513)}
print(json.dumps([{"universe": u, "priority": 100, "cid": 7, "name": "desk", "slots": slots} for u in universes]))
PY
}
want() {
  python3 - "$show" "$1" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
print(json.dumps({str(f["id"]): {"intensity": float(sys.argv[2])} for f in show["fixtures"] if f.get("patch")}))
PY
}
patched=$(python3 -c 'import json,sys; print(sum(1 for f in json.load(open(sys.argv[1]))["fixtures"] if f.get("patch")))' "$show")
[ "$patched" -ge 50 ] || fail "expected the Capture rig's patched fixtures (about 76), got $patched"

for level in 0 255; do
  live_start sACN "$show" --sacn --sacn-port 0 --state-json "$TMP/state-$level.json"
  live_send_ready send_sacn.js "$PORT" 40 "$(streams $level)"
  live_stop_ok
  intensity=$([ $level -eq 0 ] && echo 0 || echo 1)
  expect_state "$TMP/state-$level.json" "$(want $intensity)" 1e-6 "DMX $level: fixture" ||
    fail "with every dimmer at $level the rig is not at intensity $intensity"
  drives=$(grep -c "^haze live: universe [0-9]*: drives " "$HAZE_ERR")
  [ "$drives" -ge 1 ] || fail "no per-universe line at start"
  ! grep -q "cannot drive\|intensity stays at full\|drives no fixture" "$HAZE_ERR" ||
    fail "haze says it cannot drive part of the Capture rig: $(grep 'cannot drive\|stays at full\|drives no' "$HAZE_ERR" | head -3)"
  total=$(sed -n 's/^haze live: universe [0-9]*: drives \([0-9]*\) of \([0-9]*\) patched.*/\1 \2/p' "$HAZE_ERR" |
          awk '{d += $1; p += $2} END {print d " " p}')
  [ "$total" = "$patched $patched" ] || fail "the start lines say '$total' driven of patched; expected $patched $patched"
done
echo "PASS live_capture ($patched fixtures)"
