#!/usr/bin/env bash
# tools/bench_builds.py times variants alternately and gives each one's refined pixels: a
# variant without the refinement shows 0 and the note that the variants refined different
# numbers of pixels; two identical variants give no such note; a variant that fails stops the
# run naming its command.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
tool="$root/tools/bench_builds.py"
# 1280 wide: the default preset refines from HD up (docs/rendering.md, "Refinement").
bench=(--fixtures 1 --width 1280 --height 720 --frames 1)

python3 "$tool" --rounds 1 "tree=$haze" "no refinement=$haze --refine 0" -- "${bench[@]}" >"$tmp/out" 2>&1
check "two variants run ($(tail -2 "$tmp/out"))" 'grep -q "^no refinement " "$tmp/out"'
check "the table has a refined column" 'head -1 "$tmp/out" | grep -q "refined$"'
check "the tree refined some pixels" '[ "$(awk "/^tree /{print \$NF}" "$tmp/out")" -gt 0 ]'
check "--refine 0 refined none" '[ "$(awk "/^no refinement /{print \$NF}" "$tmp/out")" -eq 0 ]'
check "the difference is noted" 'grep -q "^note: the variants refined different numbers" "$tmp/out"'

python3 "$tool" --rounds 1 "a=$haze" "b=$haze" -- "${bench[@]}" >"$tmp/same" 2>&1
check "identical variants run" 'grep -q "^b " "$tmp/same"'
check "identical variants give no note" '! grep -q "^note:" "$tmp/same"'

python3 "$tool" --rounds 1 "a=$haze" "bad=$haze --no-such-option" -- "${bench[@]}" >"$tmp/bad" 2>&1; rc=$?
check "a failing variant stops the run naming it" '[ $rc -ne 0 ] && grep -q "no-such-option" "$tmp/bad"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
