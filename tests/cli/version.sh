#!/usr/bin/env bash
# `haze --version` names the project version of CMakeLists.txt, a commit this repository has
# (or "unknown" outside git), and the OpenGL context the renderer gets on this machine.
set -uo pipefail
haze=$1; root=$2
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

out=$("$haze" --version); rc=$?
check "exit status 0 (got $rc)" '[ $rc -eq 0 ]'
first=$(sed -n 1p <<<"$out")
want=$(sed -n 's/^project(haze VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
check "version $want in '$first'" '[[ "$first" == "haze $want (git "* ]]'
describe=$(sed -n 's/^haze [^ ]* (git \(.*\))$/\1/p' <<<"$first")
commit=$(sed -E 's/-dirty$//; s/^.*-g([0-9a-f]+)$/\1/' <<<"$describe")
if [ "$describe" = unknown ] || ! git -C "$root" rev-parse --git-dir >/dev/null 2>&1; then
  check "no git: 'unknown' ($describe)" '[ "$describe" = unknown ]'
else
  check "commit '$commit' is in the repository" 'git -C "$root" cat-file -e "$commit^{commit}" 2>/dev/null'
fi
check "renderer line names OpenGL" 'grep -q "^renderer: OpenGL [0-9]" <<<"$out"'
want_av=$(pkg-config --modversion libavcodec 2>/dev/null || echo "[0-9.]*")
check "output line names OpenEXR, libavcodec $want_av, cairo" 'grep -qE "^output: OpenEXR [0-9.]+, libavcodec $want_av, libavformat [0-9.]+, cairo [0-9.]+$" <<<"$out"'
"$haze" --version extra >/dev/null 2>&1; rc=$?
check "an argument is a usage error (rc $rc)" '[ $rc -eq 2 ]'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
