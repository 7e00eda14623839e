#!/usr/bin/env bash
# The program built without the GUI, under ASan and UBSan: it validates and renders a demo cue
# through llvmpipe, and `haze open` says plainly that this build has no GUI. Mesa's own
# allocations are not ours to account for, so leak checking is off here (the unit suites keep it).
set -euo pipefail
haze=$1
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$haze" validate "$root/examples/demo/demo.haze.json"
"$haze" render "$root/examples/demo/demo.haze.json" --cue 2 --width 160 --height 90 --quality draft -o "$out/cue2.pfm"
[ -s "$out/cue2.pfm" ] || { echo "FAIL: no image from the headless build"; exit 1; }
if "$haze" open "$root/examples/demo/demo.haze.json" 2> "$out/err.txt"; then
  echo "FAIL: haze open succeeded in a build without the GUI"; exit 1
fi
grep -q 'without the GUI' "$out/err.txt" || { echo "FAIL: haze open did not say the GUI is missing: $(cat "$out/err.txt")"; exit 1; }
echo "headless build: validate, render and the no-GUI message all behave"
