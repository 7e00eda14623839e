#!/usr/bin/env bash
# `haze validate` through the binary: the bundled demo show and the test show are valid (exit 0);
# each broken test show exits 1 and names every expected problem by its JSON pointer, one line
# each ("file:pointer: sentence"). Usage: validate_shows.sh HAZE REPO
set -u
haze=$1
repo=$2
data=$repo/tests/data/shows
fail=0
passed=0

valid() {
  local out
  if out=$("$haze" validate "$1" 2>&1); then
    passed=$((passed + 1))
  else
    echo "FAIL: $1 should be valid; haze validate said:"
    echo "$out"
    fail=$((fail + 1))
  fi
}

# broken FILE POINTER...: exit status 1, and a line "FILE:POINTER: ..." for each pointer.
broken() {
  local file=$data/broken/$1 err rc
  shift
  err=$("$haze" validate "$file" 2>&1 >/dev/null)
  rc=$?
  if [ $rc -ne 1 ]; then
    echo "FAIL: haze validate $file exited $rc, expected 1"
    fail=$((fail + 1))
    return
  fi
  for pointer in "$@"; do
    if printf '%s\n' "$err" | grep -qF -- "$file:$pointer: "; then
      passed=$((passed + 1))
    else
      echo "FAIL: $file: no problem reported at $pointer; got:"
      echo "$err"
      fail=$((fail + 1))
    fi
  done
}

if [ -f "$repo/examples/demo/demo.haze.json" ]; then
  valid "$repo/examples/demo/demo.haze.json"
  # The demo's rig in air that is not uniform (docs/shows.md, "Density").
  valid "$repo/examples/demo/air.haze.json"
  # A room lit by the sun through its window (docs/shows.md, "The sun").
  valid "$repo/examples/demo/sun.haze.json"
else
  echo "FAIL: the bundled demo show examples/demo/demo.haze.json is missing"
  fail=$((fail + 1))
fi
valid "$data/valid.haze.json"
valid "$data/palettes.haze.json"

broken overlap.haze.json /fixtures/1/patch/address /fixtures/2/patch/address
broken bad-cues.haze.json /cue_lists/0/cues/1/fade /cue_lists/0/cues/3/delay /cue_lists/0/cues/3/follow \
  /cue_lists/0/cues/0/values/1/gobo /cue_lists/0/cues/1/values/1/pan /cue_lists/0/cues/2/number \
  /cue_lists/0/cues/2/values/7 /cue_lists/0/cues/3/number
broken unknown-profile.haze.json /profiles/spot /venue/gltf /fixtures/0/profile /fixtures/1/id
broken newer-version.haze.json /version
# A group naming an unknown fixture, a reference to a palette that is not there.
broken bad-palettes.haze.json /groups/0/fixtures/2 /cue_lists/0/cues/0/values/1/palettes/position
broken palette-in-palette.haze.json /palettes/0/fixtures/2/palettes
broken not-json.haze.json "line 4, column 12"

# Usage errors exit 2 with one line on stderr.
for args in "" "--bogus $data/valid.haze.json" "$data/valid.haze.json $data/valid.haze.json"; do
  err=$("$haze" validate $args 2>&1 >/dev/null)
  rc=$?
  if [ $rc -eq 2 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ]; then
    passed=$((passed + 1))
  else
    echo "FAIL: haze validate $args: expected exit 2 and one line, got $rc: $err"
    fail=$((fail + 1))
  fi
done

echo "validate_shows: $passed passed, $fail failed"
[ $fail -eq 0 ]
