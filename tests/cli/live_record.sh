#!/usr/bin/env bash
# haze live --record-cue: a look built over sACN (npm `sacn` via tests/node/send_sacn.js) is
# recorded as cue 10 of a copy of tests/data/live/cues.haze.json and read back with
# `haze state --cue 10`: the DMX-driven fixtures have the look, the par (universe 2, which the
# console does not send) keeps what it tracks from the cues before. The save leaves the old show
# as .bak; a show edited on disk during the run is refused and left as it was; a run in which
# no DMX arrived records nothing.
# usage: bash live_record.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
need_node

# The copy names the venue and profile by absolute paths, so it works from the temporary folder.
SHOW="$TMP/show.haze.json"
node -e '
const fs = require("fs"), path = require("path");
const dir = path.dirname(process.argv[1]);
const s = JSON.parse(fs.readFileSync(process.argv[1], "utf8"));
s.venue.gltf = path.resolve(dir, s.venue.gltf);
s.profiles.spot = path.resolve(dir, s.profiles.spot);
fs.writeFileSync(process.argv[2], JSON.stringify(s, null, 2) + "\n");
' "$ROOT/tests/data/live/cues.haze.json" "$SHOW"

start_haze() { live_start sACN "$SHOW" --sacn --sacn-port 0 "$@"; }
send_look() {
  # Fixture 1: dimmer full, pan 0xC000; fixture 2: dimmer 51 (0.2).
  live_send_ready send_sacn.js "$PORT" 40 \
    '[{"universe":1,"priority":100,"cid":1,"name":"desk","slots":{"1":255,"2":192,"3":0,"11":51}}]'
}

# 0. A cue number that is not one is refused before anything runs.
live_run "$SHOW" --sacn --sacn-port 0 --duration 0.2 --record-cue 1.2.3 &&
  fail "--record-cue 1.2.3 was accepted"
grep -q "is not a cue number" "$HAZE_ERR" || fail "no clear message for a bad --record-cue"

# 1. Record cue 10.
cp "$SHOW" "$TMP/before.json"
start_haze --record-cue 10 --label "from the desk"
send_look
live_stop
[ "$STATUS" -eq 0 ] || fail "haze live --record-cue exited with $STATUS"
grep -q "haze live: recorded cue 10 from 2 fixtures" "$HAZE_ERR" || fail "no line saying cue 10 was recorded"
cmp -s "$TMP/before.json" "$SHOW.bak" || fail "the previous show was not kept as .bak"
"$HAZE" validate "$SHOW" >/dev/null 2>"$TMP/validate" || { cat "$TMP/validate"; fail "the saved show does not validate"; }
"$HAZE" state "$SHOW" --cue 10 --json >"$TMP/cue10.json" 2>"$TMP/state_err" || { cat "$TMP/state_err"; fail "haze state --cue 10 failed"; }
# Pan 0xC000: -270 + 540 * 49152 / 65535 = 135.00618. The par tracks cue 1: red at full.
node -e '
const fs = require("fs");
const s = JSON.parse(fs.readFileSync(process.argv[1], "utf8"));
const show = JSON.parse(fs.readFileSync(process.argv[2], "utf8"));
const want = {"1": {intensity: 1, pan: 135.00618}, "2": {intensity: 0.2}, "3": {intensity: 1, color: [1, 0, 0]}};
let bad = 0;
for (const [id, attrs] of Object.entries(want))
  for (const [k, v] of Object.entries(attrs)) {
    const got = s[id][k];
    const ok = Array.isArray(v) ? v.every((x, i) => Math.abs(got[i] - x) < 1e-3) : Math.abs(got - v) < 1e-3;
    if (!ok) { console.error("cue 10 fixture " + id + " " + k + ": got " + JSON.stringify(got) + ", want " + JSON.stringify(v)); bad++; }
  }
const cues = show.cue_lists[0].cues;
const c10 = cues[cues.length - 1];
if (c10.number !== "10" || c10.label !== "from the desk") { console.error("cue 10 is not last with its label"); bad++; }
// Tracking: only what differs from cue 4 (fixture 1 at 0.8, pan 90 from cue 3) is stored.
if (c10.values["3"]) { console.error("the par, untouched by DMX, was recorded"); bad++; }
if (c10.values["1"].color !== undefined) { console.error("fixture 1 colour (open, as tracked) was stored"); bad++; }
if (c10.values["1"].pan === undefined) { console.error("fixture 1 pan (135, tracked 90) was not stored"); bad++; }
process.exit(bad ? 1 : 0);
' "$TMP/cue10.json" "$SHOW" || fail "cue 10 does not hold the recorded look"

# 2. The show is edited on disk while haze runs: the record is refused, the edit kept.
start_haze --record-cue 11
send_look
node -e 'const fs = require("fs"); const s = JSON.parse(fs.readFileSync(process.argv[1])); s.cameras[0].fov_y = 55; fs.writeFileSync(process.argv[1], JSON.stringify(s, null, 1));' "$SHOW"
cp "$SHOW" "$TMP/edited.json"
live_stop
[ "$STATUS" -ne 0 ] || fail "recording over a show changed on disk succeeded"
grep -q "changed on disk" "$HAZE_ERR" || fail "no clear message about the show changing on disk"
cmp -s "$TMP/edited.json" "$SHOW" || fail "the show edited on disk was overwritten"

# 3. No DMX at all: nothing is recorded and the show is untouched.
live_run "$SHOW" --sacn --sacn-port 0 --duration 0.5 --record-cue 12 &&
  fail "a record without DMX succeeded"
grep -q "no fixture received DMX; nothing recorded" "$HAZE_ERR" || fail "no clear message for a record without DMX"
cmp -s "$TMP/edited.json" "$SHOW" || fail "a record without DMX changed the show"
echo "PASS live_record"
