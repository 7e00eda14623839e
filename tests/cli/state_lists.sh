#!/usr/bin/env bash
# `haze state --play`: several cue lists at once (docs/shows.md, "Several cue lists at once").
# Intensity merges HTP with each list's master, pan LTP by the order of the GOs (and a list
# taking pan over fades it from what was on stage). Every expected value is worked out by hand
# from tests/data/shows/playbacks.haze.json:
#   Main      1 (snap)    1: intensity 0.6, pan 30    2: intensity 0.2
#             2 (fade 4)  1: intensity 0.3
#   Specials  1 (fade 2)  1: intensity 0.5, pan 90    2: intensity 0.8
#             2 (snap)    2: tilt 45, color blue
# Usage: state_lists.sh HAZE REPO
set -u
haze=$1
repo=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
show=$repo/tests/data/shows/playbacks.haze.json
fail=0
passed=0

# expect "ARGS" 'JSON subset': every listed attribute must match (numbers within 1e-5).
expect() {
  local args=$1 want=$2 out
  if ! out=$("$haze" state "$show" $args --json 2>&1); then
    echo "FAIL: haze state $args exited non-zero: $out"
    fail=$((fail + 1))
    return
  fi
  printf '%s' "$out" >"$tmp/state.json"
  if node "$repo/tests/node/expect_state.js" "$tmp/state.json" "$want" 1e-5 "haze state $args: fixture"; then
    passed=$((passed + 1))
  else
    echo "FAIL: haze state $args"
    fail=$((fail + 1))
  fi
}
i="--movement instant"

# Both GO at 0 (Specials last); 1 s into Specials' 2 s fade: max(0.6, 0.25), max(0.2, 0.4), and
# pan half way from Main's 30 to 90. Fixture 3 is in no list: its defaults.
expect "--play Main=1 --play Specials=1 --at 1 $i" \
  '{"1": {"intensity": 0.6, "pan": 60}, "2": {"intensity": 0.4}, "3": {"intensity": 0, "pan": 0, "tilt": 0}}'
# Fades done: HTP max(0.6, 0.5) and max(0.2, 0.8); pan from the list that GOed last.
expect "--play Main=1 --play Specials=1 $i" '{"1": {"intensity": 0.6, "pan": 90}, "2": {"intensity": 0.8}}'
expect "--play Specials=1 --play Main=1 $i" '{"1": {"intensity": 0.6, "pan": 30}, "2": {"intensity": 0.8}}'
# Masters scale intensity only: max(0.6, 0.5 x 0.5), max(0.2, 0.5 x 0.8); then max(0.25 x 0.6, 0.25),
# max(0.25 x 0.2, 0.4); a list at master 0 keeps its pan.
expect "--play Main=1 --play Specials=1@0.5 $i" '{"1": {"intensity": 0.6, "pan": 90}, "2": {"intensity": 0.4}}'
expect "--play Main=1@0.25 --play Specials=1@0.5 $i" '{"1": {"intensity": 0.25}, "2": {"intensity": 0.4}}'
expect "--play Main=1 --play Specials=1@0 $i" '{"1": {"intensity": 0.6, "pan": 90}, "2": {"intensity": 0.2}}'
# GO times: Main GOes at 3 s, after Specials; before then it is not on stage.
expect "--play Main=1+3 --play Specials=1 --at 2 $i" '{"1": {"intensity": 0.5, "pan": 90}, "2": {"intensity": 0.8}}'
expect "--play Main=1+3 --play Specials=1 --at 3 $i" '{"1": {"intensity": 0.6, "pan": 30}, "2": {"intensity": 0.8}}'
# Main=2 stands in cue 1 from 0 and GOes into cue 2 (0.6 -> 0.3 over 4 s: 0.45 at 2 s); cue 2 holds
# no pan, so Specials' later GO keeps it.
expect "--play Main=2 --play Specials=1 --at 2 $i" '{"1": {"intensity": 0.5, "pan": 90}, "2": {"intensity": 0.8}}'
expect "--play Main=2 --play Specials=1 --at 5 $i" '{"1": {"intensity": 0.5}}'
expect "--play Main=2 --at 2 $i" '{"1": {"intensity": 0.45, "pan": 30}, "2": {"intensity": 0.2}}'
# Specials=2: cue 1's state tracked, cue 2's tilt and colour on top.
expect "--play Specials=2 $i" '{"1": {"intensity": 0.5, "pan": 90}, "2": {"intensity": 0.8, "tilt": 45, "color": [0, 0, 1]}}'
# Real movement (the default) ends where the command does once the heads have arrived.
expect "--play Main=1 --play Specials=1" '{"1": {"intensity": 0.6, "pan": 90}, "2": {"intensity": 0.8}}'

# Bad arguments: one line on stderr, non-zero exit, nothing on stdout; the line says what.
bad() {
  local want=$1 out err rc
  shift
  out=$("$haze" "$@" 2>/tmp/haze-lists-err.$$)
  rc=$?
  err=$(cat /tmp/haze-lists-err.$$)
  rm -f /tmp/haze-lists-err.$$
  if [ $rc -ne 0 ] && [ -z "$out" ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && [[ $err == *"$want"* ]]; then
    passed=$((passed + 1))
  else
    echo "FAIL: haze $* should fail with one line saying '$want' (rc $rc, stdout '$out', stderr '$err')"
    fail=$((fail + 1))
  fi
}
bad 'the show'"'"'s lists are "Main", "Specials"' state "$show" --play Nope=1 --json
bad 'has no cue "9"' state "$show" --play Main=9 --json
bad "the master after '@' must be a level 0..1" state "$show" --play Main=1@2 --json
bad "expected LIST=CUE" state "$show" --play Main --json
bad "the GO time after '+'" state "$show" --play Main=1+soon --json
bad "expected no --cue or --list" state "$show" --play Main=1 --cue 1 --json
bad "played twice" state "$show" --play Main=1 --play Main=2 --json
bad "expected no --video" render "$show" --play Main=1 --video out.mp4

echo "state_lists: $passed passed, $fail failed"
[ $fail -eq 0 ]
