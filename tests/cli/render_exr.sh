#!/usr/bin/env bash
# `haze render -o x.exr` holds the PFM's radiometric L: read back by FFmpeg's EXR decoder (not
# OpenEXR), float is bit-exact and half within half-float rounding; the header has Rec. 709
# chromaticities, whiteLuminance 1 and a comment naming the show and the cue. An unwritable
# path is one line and leaves no file.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

show="$root/examples/demo/demo.haze.json"
size=(--width 160 --height 90)
"$haze" render "$show" --cue 2 --at 1.5 "${size[@]}" -o "$tmp/c2.pfm"
for pixel in half float; do
  "$haze" render "$show" --cue 2 --at 1.5 "${size[@]}" --exr-pixel $pixel -o "$tmp/c2-$pixel.exr"
  check "$pixel EXR written" '[ -s "$tmp/c2-$pixel.exr" ]'
  ffmpeg -v error -i "$tmp/c2-$pixel.exr" -f rawvideo -pix_fmt gbrpf32le -y "$tmp/c2-$pixel.raw"
  python3 "$root/tests/cli/exr_vs_pfm.py" "$tmp/c2-$pixel.exr" "$tmp/c2-$pixel.raw" "$tmp/c2.pfm" $pixel \
    >"$tmp/check-$pixel" 2>&1; rc=$?
  check "$pixel EXR matches the PFM: $(tail -n 1 "$tmp/check-$pixel")" '[ $rc -eq 0 ]'
  grep FAIL "$tmp/check-$pixel"
  check "$pixel EXR comment names show and cue" \
    'grep -q "^comments: haze render of .*demo.haze.json, cue list Main, cue 2 \"Gobos\", 1.5 s after GO" "$tmp/check-$pixel"'
done
check "the half EXR is the smaller" '[ $(stat -c %s "$tmp/c2-half.exr") -lt $(stat -c %s "$tmp/c2-float.exr") ]'

# Unwritable: the folder is a file.
touch "$tmp/not-a-folder"
"$haze" render "$show" "${size[@]}" -o "$tmp/not-a-folder/x.exr" >"$tmp/out" 2>"$tmp/err"; rc=$?
check "unwritable path: rc $rc, one line naming it" '[ $rc -ne 0 ] && [ $(wc -l <"$tmp/err") -eq 1 ] && grep -q "not-a-folder/x.exr" "$tmp/err"'
"$haze" render "$show" "${size[@]}" --exr-pixel double -o "$tmp/x.exr" >"$tmp/out" 2>"$tmp/err"; rc=$?
check "bad --exr-pixel: rc $rc, one line" '[ $rc -ne 0 ] && [ $(wc -l <"$tmp/err") -eq 1 ] && grep -q -- "--exr-pixel" "$tmp/err"'
check "no EXR left behind by the failures" '[ ! -e "$tmp/x.exr" ] && [ -f "$tmp/not-a-folder" ] && [ ! -s "$tmp/not-a-folder" ]'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
