#!/usr/bin/env bash
# `haze render --quality reference` runs the CPU reference integrator: its PFM of a demo cue
# agrees with the GPU's `high` image of the same cue (`haze compare`, the metric the render
# tests assert on), is not the same file (a different integrator made it), and its PNG is a PNG.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
field() { sed -n "s/^ *\"$1\": *\([^,]*\),\{0,1\}$/\1/p" "$tmp/compare.json"; }  # from haze's --json

show="$root/examples/demo/demo.haze.json"
"$haze" render "$show" --cue 2 --width 96 --height 54 --quality reference -o "$tmp/ref.pfm"
check "reference PFM written" '[ -s "$tmp/ref.pfm" ]'
"$haze" render "$show" --cue 2 --width 96 --height 54 --quality high -o "$tmp/gpu.pfm"
check "the reference is another integrator's image" '! cmp -s "$tmp/ref.pfm" "$tmp/gpu.pfm"'
"$haze" compare "$tmp/gpu.pfm" "$tmp/ref.pfm" --max-error 0.08 --json >"$tmp/compare.json"; rc=$?
# The cue must really be lit (a bright maximum, hundreds of values compared) for the error to mean
# anything.
check "GPU high within 8 % of the reference on cue 2 (haze compare exit $rc, mean relative error \
$(field mean_relative_error) over $(field values_compared) values, reference max $(field reference_max))" \
  '[ $rc -eq 0 ] && awk -v m="$(field reference_max)" -v n="$(field values_compared)" "BEGIN { exit !(m > 1.0 && n > 500) }"'
"$haze" render "$show" --cue 2 --width 96 --height 54 --quality reference -o "$tmp/ref.png"
check "reference PNG written" '[ "$(head -c 4 "$tmp/ref.png" | tail -c 3)" = "PNG" ]'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
