#!/usr/bin/env bash
# A cue's timing through `haze state --at` (docs/show-format.md, "Timing"): a fan of 0.25 s delays
# across a 12-fixture group (whose order is not the id order) lands each fixture at its own time,
# checked 1 ms before and 1 ms after it; an s-curve fade matches 3p^2 - 2p^3; a sine effect with
# a phase spread of 360 degrees matches 0.5 + 0.25 sin(2 pi (0.5 t + k / 12)); a version-1 show
# with timing is refused at its place. Usage: timing_fan.sh HAZE REPO
set -u
haze=$1
repo=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
passed=0
show=$tmp/fan.haze.json
node -e '
  const ids = [...Array(12).keys()].map(i => 101 + i);
  const order = ids.map((_, i) => 112 - ((i * 5) % 12));
  const all = v => Object.fromEntries(ids.map(id => [String(id), v]));
  console.log(JSON.stringify({
    format: "haze-show", version: 2,
    profiles: { spot: process.argv[1] + "/tests/data/shows/profiles/test-spot.json" },
    fixtures: ids.map(id => ({ id, profile: "spot" })),
    groups: [{ name: "Row", fixtures: order }],
    cue_lists: [{ name: "Main", cues: [
      { number: "1", values: {} },
      { number: "2", delay: 0.5, timing: { fan: { group: "Row", delay: 0.25 } }, values: all({ intensity: 1 }) },
      { number: "3", fade: 4, timing: { curve: "s-curve" }, values: all({ intensity: 0 }) },
      { number: "4", values: all({ intensity: 0.5 }),
        effects: [{ shape: "sine", attribute: "intensity", group: "Row", rate: 0.5, size: 0.25, spread: 360 }] } ] }] }, null, 1));
' "$repo" >"$show"
order=$(node -e 'console.log(require(process.argv[1]).groups[0].fixtures.join(" "))' "$show")

# levels AT: the intensities of the group's fixtures in the group's order, as "0 0 1 ..."
levels() {
  "$haze" state "$show" --cue "$1" --at "$2" --movement instant --json |
    node -e 'const s = JSON.parse(require("fs").readFileSync(0)); console.log(process.argv.slice(1).map(id => s[id].intensity).join(" "))' $order
}

k=0
for id in $order; do
  land=$(node -e "console.log(0.5 + 0.25 * $k)")
  for side in before after; do
    at=$(node -e "console.log(($land + ('$side' === 'before' ? -0.001 : 0.001)).toFixed(3))")
    want=$(node -e "console.log([...Array(12).keys()].map(j => j < $k || ('$side' === 'after' && j === $k) ? 1 : 0).join(' '))")
    got=$(levels 2 "$at")
    if [ "$got" = "$want" ]; then passed=$((passed + 1)); else
      echo "FAIL: fan, fixture $id (place $k) at $at s: expected '$want', got '$got'"
      fail=$((fail + 1))
    fi
  done
  k=$((k + 1))
done

# S-curve: all twelve fall from 1 along 1 - (3p^2 - 2p^3), p = t / 4.
for t in 0.5 1 2 3 3.5; do
  if "$haze" state "$show" --cue 3 --at "$t" --movement instant --json | node -e '
      const s = JSON.parse(require("fs").readFileSync(0)), p = Number(process.argv[1]) / 4;
      const want = 1 - (3 * p * p - 2 * p * p * p);
      const bad = Object.entries(s).filter(([id, a]) => Math.abs(a.intensity - want) > 1e-6);
      if (bad.length) { console.log("expected " + want + ", got " + bad[0][1].intensity); process.exit(1); }' "$t"; then
    passed=$((passed + 1))
  else
    echo "FAIL: s-curve at $t s"
    fail=$((fail + 1))
  fi
done

# Sine effect: the k-th fixture of the group at 0.5 + 0.25 sin(2 pi (0.5 t + k / 12)).
for t in 0 0.3 1.7 5.25 30.1; do
  if "$haze" state "$show" --cue 4 --at "$t" --movement instant --json | node -e '
      const s = JSON.parse(require("fs").readFileSync(0)), t = Number(process.argv[1]);
      const bad = process.argv.slice(2).map((id, k) => [id, s[id].intensity, 0.5 + 0.25 * Math.sin(2 * Math.PI * (0.5 * t + k / 12))])
        .filter(([id, got, want]) => Math.abs(got - want) > 1e-6);
      if (bad.length) { console.log("fixture " + bad[0][0] + ": expected " + bad[0][2] + ", got " + bad[0][1]); process.exit(1); }' "$t" $order; then
    passed=$((passed + 1))
  else
    echo "FAIL: sine effect at $t s"
    fail=$((fail + 1))
  fi
done

# The fan's group must exist; a version-1 file cannot hold timing.
sed 's/"group": "Row"/"group": "Rwo"/' "$show" >"$tmp/bad.haze.json"
err=$("$haze" state "$tmp/bad.haze.json" --cue 2 2>&1 >/dev/null)
# haze state refuses it with validate's lines, one per problem (the effect names "Rwo" too).
problems=$("$haze" validate "$tmp/bad.haze.json" 2>&1 >/dev/null | grep -c "bad.haze.json:/")
if grep -qF "$tmp/bad.haze.json:/cue_lists/0/cues/1/timing/fan/group: the fan names group \"Rwo\"" <<<"$err" &&
   [ "$(wc -l <<<"$err")" -eq "$problems" ]; then
  passed=$((passed + 1))
else
  echo "FAIL: a fan naming an unknown group: got '$err'"
  fail=$((fail + 1))
fi
sed 's/"version": 2/"version": 1/' "$show" >"$tmp/old.haze.json"
err=$("$haze" validate "$tmp/old.haze.json" 2>&1 >/dev/null)
if grep -qF "$tmp/old.haze.json:/groups: " <<<"$err" && grep -qF "/cue_lists/0/cues/1/timing: \"timing\" needs format version 2" <<<"$err"; then
  passed=$((passed + 1))
else
  echo "FAIL: version 1 with groups and timing: got '$err'"
  fail=$((fail + 1))
fi

echo "timing_fan: $passed passed, $fail failed"
[ $fail -eq 0 ]
