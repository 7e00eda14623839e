#!/usr/bin/env bash
# `haze import-mvr` through the binary: the shared theatre MVR imports into a temp folder with
# its GDTF folder and venue, `haze validate` accepts the result, warnings carry their XML place;
# the Capture show's hundreds of warnings fold into a few lines with counts, and --verbose
# prints every one; a file that is not an MVR is one error line and exit 1; an existing show is
# not overwritten. (tests/cli/mvr_render.sh renders every imported MVR.)
# Usage: import_mvr.sh HAZE REPO
set -u
haze=$1
repo=$2
source "$repo/tests/cli/test_data.bash"
data=$(dirname "$(data_path gdtf/mvr/scene_objects.mvr)")  # with basic_fixture.mvr
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$repo/tests/cli/checks.bash"

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

# Folded warnings: one line per kind, the count of the rest on it; --verbose: one line each.
if want_data gdtf/mvr/capture_demo_show.mvr; then
  capture=$(data_path gdtf/mvr/capture_demo_show.mvr)
  "$haze" import-mvr "$capture" -o "$tmp/capture.haze.json" >"$tmp/cout" 2>"$tmp/cerr"
  rc=$?
  check "Capture import exits 0 (got $rc)" $rc
  total=$(sed -n 's/.* \([0-9][0-9]*\) warnings.*/\1/p' "$tmp/cout")
  lines=$(grep -c '^warning: ' "$tmp/cerr")
  test "${total:-0}" -ge 100 -a "$lines" -le 10; check "Capture: $total warnings folded into $lines lines: $(cat "$tmp/cout")" $?
  grep -q "in $lines kinds (--verbose lists each)" "$tmp/cout"; check "the summary says how many kinds: $(cat "$tmp/cout")" $?
  more=$(sed -n 's/.* (and \([0-9][0-9]*\) more like it)$/\1/p' "$tmp/cerr" | awk '{ s += $1 } END { print s + 0 }')
  test $((lines + more)) -eq "${total:-0}"; check "the folded counts add up ($lines lines + $more more = $total)" $?
  grep -q "GeneralSceneDescription.xml line [0-9]* <\|description.xml line [0-9]* <" "$tmp/cerr"; check "folded lines keep their place" $?
  "$haze" import-mvr "$capture" -o "$tmp/capture2.haze.json" --verbose >/dev/null 2>"$tmp/verr2"
  vlines=$(grep -c '^warning: ' "$tmp/verr2")
  test "$vlines" -eq "${total:-0}"; check "--verbose prints every warning ($vlines of $total)" $?
  ! grep -q "more like it" "$tmp/verr2"; check "--verbose folds nothing" $?
fi

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
data_exit "$fail"
