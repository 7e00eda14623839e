#!/usr/bin/env bash
# schemas/show.schema.json (JSON Schema draft 2020-12) checked with ajv: every bundled example
# show and the valid test shows conform; broken test shows that the schema can see (a newer
# version, a negative fade, a wrong type) do not, so the check can fail. Needs the test tools in
# tests/node/node_modules (npm ci there); without them this fails, it does not skip.
# Usage: show_schema.sh HAZE REPO (HAZE is unused: the schema needs no binary)
set -u
repo=$2
ajv=$repo/tests/node/node_modules/.bin/ajv
schema=$repo/schemas/show.schema.json
if [ ! -x "$ajv" ] || [ ! -d "$repo/tests/node/node_modules/ajv-formats" ]; then
  echo "FAIL: ajv and ajv-formats are missing from tests/node/node_modules; run 'npm ci' in tests/node"
  exit 1
fi
fail=0
passed=0

check() {  # check valid|invalid FILE
  local want=$1 file=$2 out rc
  out=$("$ajv" validate --spec=draft2020 -c ajv-formats --strict=true -s "$schema" -d "$file" 2>&1)
  rc=$?
  if printf '%s\n' "$out" | grep -q "strict mode"; then
    echo "FAIL: the schema has strict-mode warnings: $out"
    fail=$((fail + 1))
  elif { [ "$want" = valid ] && [ $rc -eq 0 ]; } || { [ "$want" = invalid ] && [ $rc -ne 0 ] && printf '%s\n' "$out" | grep -q "invalid"; }; then
    passed=$((passed + 1))
  else
    echo "FAIL: $file should be $want by the schema; ajv said (exit $rc):"
    echo "$out"
    fail=$((fail + 1))
  fi
}

examples=0
while IFS= read -r file; do
  check valid "$file"
  examples=$((examples + 1))
done < <(find "$repo/examples" -name '*.haze.json' | sort)
if [ $examples -eq 0 ]; then
  echo "FAIL: no example shows (*.haze.json) found under examples/"
  fail=$((fail + 1))
fi
check valid "$repo/tests/data/shows/valid.haze.json"
check valid "$repo/tests/data/shows/broken/overlap.haze.json"  # only haze validate sees overlaps
check invalid "$repo/tests/data/shows/broken/newer-version.haze.json"
check invalid "$repo/tests/data/shows/broken/bad-cues.haze.json"
check valid "$repo/tests/data/shows/optics.haze.json"
check valid "$repo/tests/data/shows/palettes.haze.json"
check valid "$repo/tests/data/shows/playbacks.haze.json"
check valid "$repo/tests/data/shows/broken/bad-palettes.haze.json"  # only haze validate sees dangling names
check invalid "$repo/tests/data/shows/broken/palette-in-palette.haze.json"  # a palette cannot refer to one
check invalid "$repo/tests/data/shows/broken/bad-optics.haze.json"  # a 500 Hz strobe, three blades

echo "show_schema: $passed passed, $fail failed"
[ $fail -eq 0 ]
