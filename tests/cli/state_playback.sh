#!/usr/bin/env bash
# `haze state` through the binary: tracking over 7 cues, delay then fade, fade 0 after a delay,
# the gobo switch at the start of a fade, a follow chain, BACK-like and GOTO-like jumps are the
# player's (unit tests); here each expected value follows by hand from
# tests/data/shows/valid.haze.json and docs/show-format.md. Usage: state_playback.sh HAZE REPO
set -u
haze=$1
repo=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
show=$repo/tests/data/shows/valid.haze.json
fail=0
passed=0

# expect "ARGS" 'JSON subset': every listed attribute must match (numbers within 1e-4). These are
# the commanded values of the tracking model (--movement instant); the heads' own speeds are
# tests/cli/movement.sh's.
expect() {
  local args=$1 want=$2 out
  if ! out=$("$haze" state "$show" $args --movement instant --json 2>&1); then
    echo "FAIL: haze state $args exited non-zero: $out"
    fail=$((fail + 1))
    return
  fi
  printf '%s' "$out" >"$tmp/state.json"
  if node "$repo/tests/node/expect_state.js" "$tmp/state.json" "$want" 1e-4 "haze state $args: fixture"; then
    passed=$((passed + 1))
  else
    echo "FAIL: haze state $args"
    fail=$((fail + 1))
  fi
}

# Tracking: 101's colour from cue 1 is still there in cue 5; its intensity changed in cue 3 and
# tracked after; defaults where nothing was ever set (zoom = the profile's field angle).
expect "--cue 1" '{"101": {"intensity": 1, "color": [1, 0.8, 0.6], "gobo": "Dots", "zoom": 25}, "201": {"pan": 0, "iris": 1, "zoom": 50}}'
expect "--cue 2" '{"101": {"intensity": 1, "pan": 90, "zoom": 18}}'
expect "--cue 3" '{"101": {"intensity": 0.25, "color": [1, 0.8, 0.6], "gobo": "Star"}}'
expect "--cue 5" '{"101": {"intensity": 0.25, "color": [1, 0.8, 0.6], "pan": 90, "iris": 0.5}, "201": {"intensity": 0, "color": [0, 0, 1]}}'
expect "--cue 10" '{"101": {"pan": -90, "intensity": 0.25, "tilt": 20}}'
# Delay 1 s then a 4 s fade: nothing moves during the delay, then linear.
expect "--cue 2 --at 0.5" '{"101": {"pan": 0, "zoom": 25}, "102": {"tilt": 0, "gobo": "Open"}}'
expect "--cue 2 --at 3" '{"101": {"pan": 45, "zoom": 21.5}, "102": {"tilt": -22.5}}'
expect "--cue 2 --at 9" '{"101": {"pan": 90, "zoom": 18}}'
# The gobo switches when the fade starts (t = delay), before the continuous part has moved.
expect "--cue 2 --at 1" '{"102": {"gobo": "Star", "tilt": 0}}'
# Fade 0 is a snap, after the 0.5 s delay.
expect "--cue 3 --at 0.4" '{"101": {"intensity": 1, "gobo": "Dots"}, "201": {"color": [1, 0, 0]}}'
expect "--cue 3 --at 0.5" '{"101": {"intensity": 0.25, "gobo": "Star"}, "201": {"color": [0, 0, 1]}}'
# Colour fades per channel: white to red, a quarter of the way at 0.5 s of 2 s.
expect "--cue 1 --at 0.5" '{"201": {"color": [1, 0.75, 0.75], "intensity": 0.25}}'
# Without --follow, S past delay + fade is the cue's full state; with it, the chain runs:
# 3.5 (fade 2, follow 1) -> 4 at 3 s (fade 1, follow 0.5) -> 5 at 4.5 s (fade 3).
expect "--cue 3.5 --at 10" '{"101": {"iris": 1}, "102": {"intensity": 1, "gobo_rotation": 180}, "201": {"intensity": 1}}'
expect "--cue 3.5 --at 3.5 --follow" '{"101": {"iris": 0.75}, "201": {"intensity": 1}}'
expect "--cue 3.5 --at 6 --follow" '{"101": {"iris": 0.5}, "201": {"intensity": 0.5}}'
expect "--cue 3.5 --at 60 --follow" '{"201": {"intensity": 0}}'
# Another list.
expect "--cue 1 --list Effects" '{"102": {"intensity": 0.3}, "101": {"intensity": 0}}'

# Bad arguments: one line on stderr, non-zero exit, nothing on stdout.
bad() {
  local out err rc
  out=$("$haze" state "$@" 2>/tmp/haze-state-err.$$)
  rc=$?
  err=$(cat /tmp/haze-state-err.$$)
  rm -f /tmp/haze-state-err.$$
  if [ $rc -ne 0 ] && [ -z "$out" ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && [ -n "$err" ]; then
    passed=$((passed + 1))
  else
    echo "FAIL: haze state $* should fail with one line on stderr (rc $rc, stdout '$out', stderr '$err')"
    fail=$((fail + 1))
  fi
}
bad "$show" --cue 7 --json
bad "$show" --json
bad "$show" --cue 1 --at -2 --json
bad "$show" --cue 1 --at soon --json
bad "$show" --cue 1 --list Nope --json
bad "$show" --cue 1 --bogus
bad "$repo/tests/data/shows/no-such.haze.json" --cue 1 --json
bad --cue 1

# A full state (no --at) whose effect keeps the heads moving still returns: the demo's cue 4.5
# circles the beams, so its heads never settle on the command.
if timeout 60 "$haze" state "$repo/examples/demo/demo.haze.json" --cue 4.5 --json >"$tmp/effect.json" 2>&1 &&
   grep -q '"101"' "$tmp/effect.json"; then
  passed=$((passed + 1))
else
  fail=$((fail + 1))
  echo "FAIL: haze state --cue 4.5 (a running effect, real movement) did not return within 60 s: $(head -c 200 "$tmp/effect.json")"
fi

echo "state_playback: $passed passed, $fail failed"
[ $fail -eq 0 ]
