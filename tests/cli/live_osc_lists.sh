#!/usr/bin/env bash
# haze live --osc with several cue lists (docs/live.md, "Remote control"): /haze/list/NAME/go,
# /back and /master drive a second list beside the played one, intensity merging HTP with the
# master; an unknown list is refused with the show's list names. The show is
# tests/data/live/cues.haze.json with a list "Specials" added (cue 1: fixture 4 at 0.8 and
# fixture 1 at 0.5, pan 45; cue 2: fixture 4 at 0.2); every cue a snap.
# usage: bash live_osc_lists.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
command -v oscsend >/dev/null || fail "oscsend (Debian liblo-tools) is not installed; tools/install-deps.sh installs it"

python3 - "$ROOT/tests/data/live/cues.haze.json" "$TMP/lists.haze.json" <<'PY' || fail "could not write the two-list show"
import json, os, sys
src, out = sys.argv[1], sys.argv[2]
show = json.load(open(src))
base = os.path.dirname(os.path.abspath(src))
show["venue"]["gltf"] = os.path.normpath(os.path.join(base, show["venue"]["gltf"]))
for k, v in show["profiles"].items():
    if isinstance(v, str):
        show["profiles"][k] = os.path.join(base, v)
show["cue_lists"].append({"name": "Specials", "cues": [
    {"number": "1", "values": {"4": {"intensity": 0.8}, "1": {"intensity": 0.5, "pan": 45}}},
    {"number": "2", "values": {"4": {"intensity": 0.2}}}]})
json.dump(show, open(out, "w"), indent=2)
PY

live_start OSC "$TMP/lists.haze.json" --sacn --sacn-port 0 --osc 0 --movement instant --state-json "$TMP/state.json"

osc_send 'OSC /haze/go from .*: cue 1$' /haze/go                                   # Main 1: 1 at 0.2, 3 red at 1
osc_send 'OSC /haze/list/Specials/go from .*: cue list "Specials": cue 1$' /haze/list/Specials/go
osc_send 'OSC /haze/list/Specials/go from .*: cue list "Specials": cue 2$' /haze/list/Specials/go
osc_send 'OSC /haze/list/Specials/back from .*: cue list "Specials": cue 1$' /haze/list/Specials/back
osc_send 'OSC /haze/list/Specials/master from .*: cue list "Specials": master 0.5$' /haze/list/Specials/master f 0.5
osc_send 'OSC /haze/go from .*: cue 2$' /haze/go                                   # Main 2: 1 at 0.4
osc_send 'OSC from .* refused: .*its lists are "Main", "Specials"' /haze/list/Nope/go
osc_send 'OSC from .* refused: .*0..1' /haze/list/Specials/master f 2

live_stop_ok
grep -q 'haze live: OSC: 6 commands done, 2 refused' "$HAZE_ERR" || fail "the OSC counts are not 6 done, 2 refused"
# 1: max(Main 0.4, 0.5 x 0.5) and Specials' pan 45 (Main's cue 2 holds no pan); 3: Main's red at
# full; 4: Specials' cue 1 again, 0.5 x 0.8.
expect_state "$TMP/state.json" '{"1": {"intensity": 0.4, "pan": 45}, "3": {"intensity": 1, "color": [1, 0, 0]},
  "4": {"intensity": 0.4}}' 1e-6 || fail "the merged state differs from the hand-worked one"
echo "PASS live_osc_lists"
