#!/usr/bin/env bash
# `haze import-mvr` through the binary: the shared theatre MVR imports into a temp folder with
# its GDTF folder and venue, `haze validate` accepts the result, warnings carry their XML place;
# a file that is not an MVR is one error line and exit 1; an existing show is not overwritten.
# Usage: import_mvr.sh HAZE REPO
set -u
haze=$1
repo=$2
data=$repo/../shared/data/gdtf/mvr
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
passed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); else echo "FAIL: $1"; fail=$((fail + 1)); fi
}

"$haze" import-mvr "$data/scene_objects.mvr" -o "$tmp/theatre.haze.json" >"$tmp/out" 2>"$tmp/err"
rc=$?
check "import-mvr exits 0 (got $rc): $(head -3 "$tmp/err")" $rc
grep -q "72 fixtures" "$tmp/out"; check "summary names 72 fixtures: $(cat "$tmp/out")" $?
test -f "$tmp/theatre_venue.gltf" -a -f "$tmp/theatre_venue.bin"; check "venue .gltf and .bin written" $?
ls "$tmp/theatre_gdtf/"*.gdtf >/dev/null 2>&1; check "GDTF folder written" $?
grep -q "GeneralSceneDescription.xml line [0-9]* <" "$tmp/err"; check "warnings carry their XML place" $?
"$haze" validate "$tmp/theatre.haze.json" >"$tmp/vout" 2>"$tmp/verr"
rc=$?
check "haze validate accepts the imported show (rc $rc): $(head -5 "$tmp/verr")" $rc

"$haze" import-mvr "$data/basic_fixture.mvr" -o "$tmp/theatre.haze.json" >/dev/null 2>"$tmp/err2"
rc=$?
test $rc -eq 1; check "an existing show is refused with exit 1 (got $rc)" $?
grep -q "already exists" "$tmp/err2"; check "the refusal says why" $?

echo "not a zip" >"$tmp/bad.mvr"
"$haze" import-mvr "$tmp/bad.mvr" -o "$tmp/bad.haze.json" >/dev/null 2>"$tmp/err3"
rc=$?
test $rc -eq 1; check "a non-MVR exits 1 (got $rc)" $?
test "$(wc -l <"$tmp/err3")" -eq 1; check "a non-MVR gives one error line: $(cat "$tmp/err3")" $?
test ! -e "$tmp/bad.haze.json"; check "nothing written for a non-MVR" $?

"$haze" import-mvr "$data/basic_fixture.mvr" >/dev/null 2>&1
rc=$?
test $rc -eq 2; check "missing -o exits 2 (got $rc)" $?

echo "$passed passed, $fail failed"
[ "$fail" -eq 0 ]
