#!/usr/bin/env bash
# haze live --timecode: ArtTimeCode from tests/node/send_artnet_timecode.js (EBU 25 fps, one
# packet a frame) fires the cues of tests/data/live/cues.haze.json at their timecodes: cue 1 at
# 00:00:01:00, 2 at 00:00:02:00, 3 at 00:00:03:00, each logged with the frame that fired it
# (so "+-1 frame" is checked exactly: the firing frame must be the cue's own). Then a jump back
# to 00:00:01:12 chases to cue 1, and running on fires cue 2 again at its frame.
# usage: bash live_timecode.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
need_node

live_start Art-Net "$ROOT/tests/data/live/cues.haze.json" --artnet --artnet-port 0 --timecode \
  --state-json "$TMP/state.json"

live_send_ready send_artnet_timecode.js "$PORT" 00:00:00:00+80 00:00:01:12+16
sleep 0.3

live_stop_ok

grep '^haze live: timecode [0-9]' "$HAZE_ERR" >"$TMP/fired"
cat >"$TMP/want" <<'WANT'
haze live: timecode 00:00:01:00: fired cue 1
haze live: timecode 00:00:02:00: fired cue 2
haze live: timecode 00:00:03:00: fired cue 3
haze live: timecode 00:00:01:12: chased to cue 1
haze live: timecode 00:00:02:00: fired cue 2
WANT
diff "$TMP/want" "$TMP/fired" || fail "cues did not fire at their timecodes"
grep -q 'haze live: timecode: 96 ArtTimeCode packets, 5 cue firings or chases' "$HAZE_ERR" ||
  fail "not all 96 timecode packets were counted"

# After the run: cue 2 (fixture 1 at 0.4, the par tracked from cue 1).
expect_state "$TMP/state.json" '{"1": {"intensity": 0.4}, "3": {"intensity": 1}}' 1e-6 ||
  fail "the stage is not that of cue 2"
echo "PASS live_timecode"
