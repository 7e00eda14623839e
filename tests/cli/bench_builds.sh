#!/usr/bin/env bash
# tools/bench_builds.py times variants alternately and gives each one's refined pixels: a
# variant without the refinement shows 0 and the note that the variants refined different
# numbers of pixels; two identical variants give no such note; a variant that fails stops the
# run naming its command.
# Usage: bench_builds.sh HAZE REPO
set -u
haze=$1
repo=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$repo/tests/cli/checks.bash"
tool="$repo/tools/bench_builds.py"
# 1280 wide: the default preset refines from HD up (docs/rendering.md, "Refinement").
bench=(--fixtures 1 --width 1280 --height 720 --frames 1)
refined() { awk -v v="$1" 'index($0, v " ") == 1 { print $NF }' "$2"; }  # refined LABEL FILE

python3 "$tool" --rounds 1 "tree=$haze" "no refinement=$haze --refine 0" -- "${bench[@]}" >"$tmp/out" 2>&1
grep -q "^no refinement " "$tmp/out"; check "two variants run: $(tail -2 "$tmp/out")" $?
head -1 "$tmp/out" | grep -q "refined$"; check "the table has a refined column" $?
[ "$(refined tree "$tmp/out")" -gt 0 ]; check "the tree refined some pixels" $?
[ "$(refined "no refinement" "$tmp/out")" -eq 0 ]; check "--refine 0 refined none" $?
grep -q "^note: the variants refined different numbers" "$tmp/out"; check "the difference is noted" $?

python3 "$tool" --rounds 1 "a=$haze" "b=$haze" -- "${bench[@]}" >"$tmp/same" 2>&1
grep -q "^b " "$tmp/same"; check "identical variants run" $?
! grep -q "^note:" "$tmp/same"; check "identical variants give no note" $?

python3 "$tool" --rounds 1 "a=$haze" "bad=$haze --no-such-option" -- "${bench[@]}" >"$tmp/bad" 2>&1; rc=$?
[ $rc -ne 0 ] && grep -q "no-such-option" "$tmp/bad"; check "a failing variant stops the run naming it" $?

echo "$passed passed, $fail failed"
[ "$fail" -eq 0 ]
