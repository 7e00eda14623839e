#!/usr/bin/env bash
# haze live with sACN from the npm `sacn` package (tests/node/send_sacn.js) on 127.0.0.1:
# priorities (a priority-50 backup sending full loses), HTP between two priority-100 sources,
# 16-bit pan/tilt, CMY, gobo slot, zoom, an RGB par on universe 2, malformed packets counted,
# and SIGINT ending the run. Expected values are worked out by hand below.
# usage: bash live_sacn.sh HAZE_BINARY REPO_ROOT
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

# Port 0: haze picks a free port and prints it, so parallel test runs never collide.
"$HAZE" live "$ROOT/tests/data/live/live.haze.json" --sacn --sacn-port 0 \
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
(cd "$NODE_DIR" && node send_sacn.js "$PORT" 60 "$STREAMS" 3 >"$TMP/sent" 2>"$TMP/send_err") &
SEND_PID=$!
for _ in $(seq 600); do
  grep -q ready "$TMP/sent" 2>/dev/null && break
  kill -0 "$SEND_PID" 2>/dev/null || { cat "$TMP/send_err"; fail "send_sacn.js exited early"; }
  sleep 0.1
done
grep -q ready "$TMP/sent" || fail "send_sacn.js never got ready"

# Stop haze while every source is still sending (SIGINT: the Ctrl-C path).
kill -INT "$HAZE_PID"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"
[ -f "$TMP/state.json" ] || fail "no state JSON written"

grep -q "malformed sacn.bad_priority: 3" "$TMP/err" || fail "the 3 bad-priority packets were not counted"
grep -q 'source sACN .* "backup" universe 1 priority 50 (outranked)' "$TMP/err" ||
  fail "the backup source is not listed as outranked"

# Pan 0xC000: -270 + 540 * 49152 / 65535 = 135.00618; tilt 0x4000: -135 + 270 * 16384 / 65535
# = -67.49897; magenta full: [1, 0, 1]; gobo 150 of 4 evenly spread slots: Stars (128-191);
# zoom 128: 8 + 32 * 128 / 255 = 24.06275. Fixture 2: HTP of 51 and 102 = 0.4. Par: [1, 128/255, 0]
# at full. Fixture 4 is unpatched: defaults, zoom = the profile's field angle 20.
node -e '
const s = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
const want = {
  "1": {intensity: 1, pan: 135.00618, tilt: -67.49897, color: [1, 0, 1], zoom: 24.06275,
        gobo: "Stars", gobo_rotation: 0, iris: 1},
  "2": {intensity: 0.4, pan: -270, tilt: -135, color: [1, 1, 1], zoom: 8, gobo: "Open"},
  "3": {intensity: 1, color: [1, 0.50196, 0]},
  "4": {intensity: 0, pan: 0, tilt: 0, color: [1, 1, 1], zoom: 20, gobo: "Open", iris: 1},
};
let bad = 0;
for (const [id, attrs] of Object.entries(want)) {
  if (!s[id]) { console.error("fixture " + id + " missing"); bad++; continue; }
  for (const [k, v] of Object.entries(attrs)) {
    const got = s[id][k];
    const ok = Array.isArray(v) ? Array.isArray(got) && v.every((x, i) => Math.abs(got[i] - x) < 1e-3)
             : typeof v === "string" ? got === v : Math.abs(got - v) < 1e-3;
    if (!ok) { console.error("fixture " + id + " " + k + ": got " + JSON.stringify(got) + ", want " + JSON.stringify(v)); bad++; }
  }
}
process.exit(bad ? 1 : 0);
' "$TMP/state.json" || fail "fixture states differ from what was sent"
echo "PASS live_sacn"
