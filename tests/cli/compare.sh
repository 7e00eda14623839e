#!/usr/bin/env bash
# `haze compare` on PFMs small enough to check by hand: identical images give 0, one pixel 10 %
# off among four gives 0.025, --max-error turns that into exit 0 or 3, --threshold moves the
# mask, and a dark reference, a missing file, a size mismatch or a file that is not a PFM each
# give exit 1 with one line naming the file. The metric is haze's; python only writes the inputs.
set -uo pipefail
haze=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

pfm() {  # pfm FILE W H R G B R G B ... (top row first, as haze's images are)
  python3 -c '
import struct, sys
w, h = int(sys.argv[2]), int(sys.argv[3])
v = [float(x) for x in sys.argv[4:]]
assert len(v) == w * h * 3
rows = [v[y * w * 3:(y + 1) * w * 3] for y in range(h)][::-1]  # PFM stores the bottom row first
open(sys.argv[1], "wb").write(b"PF\n%d %d\n-1.0\n" % (w, h) + b"".join(struct.pack("<%df" % len(r), *r) for r in rows))
' "$@"
}
field() { sed -n "s/^ *\"$1\": *\([^,]*\),\{0,1\}$/\1/p" "$2"; }  # a number from haze's --json
near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; exit !(d < 1e-6 && d > -1e-6) }'; }
run() { "$haze" compare "$@" >"$tmp/out" 2>"$tmp/err"; echo $?; }
one_error_line() { [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "$1" "$tmp/err"; }

pfm "$tmp/ref.pfm" 2 2 1 1 1  1 1 1  1 1 1  1 1 1
pfm "$tmp/off.pfm" 2 2 1 1 1  1.1 1.1 1.1  1 1 1  1 1 1
pfm "$tmp/dark.pfm" 2 2 0 0 0  0 0 0  0 0 0  0 0 0
pfm "$tmp/wide.pfm" 4 1 1 1 1  1 1 1  1 1 1  1 1 1
printf 'P6\n2 2\n255\n............' >"$tmp/notpfm.pfm"

rc=$(run "$tmp/ref.pfm" "$tmp/ref.pfm" --json)
check "identical images: exit 0 (got $rc)" '[ "$rc" -eq 0 ]'
check "identical images: error 0 over 12 values" \
  'near "$(field mean_relative_error "$tmp/out")" 0 && [ "$(field values_compared "$tmp/out")" = 12 ]'

rc=$(run "$tmp/off.pfm" "$tmp/ref.pfm" --json)
check "one pixel 10 % off among 4: exit 0 (got $rc)" '[ "$rc" -eq 0 ]'
check "one pixel 10 % off among 4: mean 0.025, max 0.1 ($(field mean_relative_error "$tmp/out"))" \
  'near "$(field mean_relative_error "$tmp/out")" 0.025 && near "$(field max_relative_error "$tmp/out")" 0.1'
rc=$(run "$tmp/off.pfm" "$tmp/ref.pfm")
check "text output names the error and the count" 'grep -q "mean relative error 0.025000 over 12 values" "$tmp/out"'
rc=$(run "$tmp/off.pfm" "$tmp/ref.pfm" --max-error 0.03)
check "--max-error 0.03 passes 0.025 (exit $rc)" '[ "$rc" -eq 0 ]'
rc=$(run "$tmp/off.pfm" "$tmp/ref.pfm" --max-error 0.02)
check "--max-error 0.02 fails 0.025 with exit 3 (got $rc)" '[ "$rc" -eq 3 ] && one_error_line "above --max-error"'
rc=$(run "$tmp/off.pfm" "$tmp/ref.pfm" --max-error 0.02 --json)
check "--json says whether it was within" '[ "$rc" -eq 3 ] && grep -q "\"within_max_error\": false" "$tmp/out"'

# The mask is the reference's: its dim pixel (under 1 % of its maximum 100) is left out of the
# error however far off the image is there, and shows up as leak instead.
pfm "$tmp/dimref.pfm" 2 1 100 100 100  0.5 0.5 0.5
pfm "$tmp/dimoff.pfm" 2 1 100 100 100  1 1 1
rc=$(run "$tmp/dimoff.pfm" "$tmp/dimref.pfm" --json)
check "the default threshold (1 %) leaves the dim pixel out: 0 over 3 values, leak seen" \
  '[ "$rc" -eq 0 ] && near "$(field mean_relative_error "$tmp/out")" 0 && [ "$(field values_compared "$tmp/out")" = 3 ] &&
   near "$(field leak "$tmp/out")" 0.005'
rc=$(run "$tmp/dimoff.pfm" "$tmp/dimref.pfm" --threshold 0.001 --json)
check "--threshold 0.001 takes it in: 3 values off by 100 % among 6 -> 0.5" \
  '[ "$rc" -eq 0 ] && near "$(field mean_relative_error "$tmp/out")" 0.5 && [ "$(field values_compared "$tmp/out")" = 6 ]'

rc=$(run "$tmp/ref.pfm" "$tmp/dark.pfm")
check "a dark reference compares nothing: exit 1 naming it (got $rc)" '[ "$rc" -eq 1 ] && one_error_line "dark.pfm"'
rc=$(run "$tmp/ref.pfm" "$tmp/missing.pfm")
check "a missing file: exit 1 naming it (got $rc)" '[ "$rc" -eq 1 ] && one_error_line "missing.pfm"'
rc=$(run "$tmp/wide.pfm" "$tmp/ref.pfm")
check "different sizes: exit 1 naming both (got $rc)" \
  '[ "$rc" -eq 1 ] && one_error_line "wide.pfm" && grep -q "ref.pfm" "$tmp/err"'
rc=$(run "$tmp/notpfm.pfm" "$tmp/ref.pfm")
check "not a PFM: exit 1 naming it (got $rc)" '[ "$rc" -eq 1 ] && one_error_line "notpfm.pfm"'
rc=$(run "$tmp/ref.pfm")
check "one file only: a usage error, exit 2 (got $rc)" '[ "$rc" -eq 2 ] && one_error_line "REFERENCE"'
rc=$(run "$tmp/ref.pfm" "$tmp/ref.pfm" --threshold 2)
check "a threshold outside 0..1: a usage error, exit 2 (got $rc)" '[ "$rc" -eq 2 ] && one_error_line "--threshold"'
rc=$(run "$tmp/ref.pfm" "$tmp/ref.pfm" --frobnicate)
check "an unknown option: a usage error, exit 2 (got $rc)" '[ "$rc" -eq 2 ] && one_error_line "--frobnicate"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
