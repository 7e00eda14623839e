#!/usr/bin/env bash
# `haze render --video OUT-%05d.png --frames A-B [--resume]` (docs/output.md, "Rendering on a
# cluster"): ranges rendered apart join, pixel for pixel, into the frames of one run. The demo's
# cue 4 fades in 3 s, follows into cue 4.5 at 5 s, whose 5 s fade sweeps the heads and runs a
# moving effect: at 4 fps the split at frame 24 (6 s) falls inside that fade and that movement.
# The hazers' density field and the dust of the air show are stepped from 0 the same way. Then
# --resume: complete frames are left alone (same inode, same bytes), a cut-short frame and a
# missing one are redone. Bad ranges: one line, no file.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
show="$root/examples/demo/demo.haze.json"
opts=(--from 4 --to 4.5 --duration 8 --fps 4 --width 160 --height 90)

"$haze" render "$show" --video "$tmp/whole-%05d.png" "${opts[@]}" >/dev/null
check "one run: 32 frames" '[ "$(ls "$tmp"/whole-*.png | wc -l)" -eq 32 ]'
"$haze" render "$show" --video "$tmp/part-%05d.png" "${opts[@]}" --frames 24-31 >"$tmp/late.out"
"$haze" render "$show" --video "$tmp/part-%05d.png" "${opts[@]}" --frames 0-23 >/dev/null
check "two ranges: 32 frames" '[ "$(ls "$tmp"/part-*.png | wc -l)" -eq 32 ]'
check "the late range drew 8 frames: $(tail -n 1 "$tmp/late.out")" \
  'grep -qx "frames 24-31: 8, 8 drawn, 0 repeated, 0 complete already" "$tmp/late.out"'
same=0
for f in "$tmp"/whole-*.png; do cmp -s "$f" "${f/whole-/part-}" && same=$((same + 1)); done
check "every frame of the ranges is the one run's, byte for byte ($same of 32)" '[ "$same" -eq 32 ]'
# The split is in the middle of things: the frames either side of it differ, and so do the
# last frame before the follow and the first after it.
check "frames 23 and 24 differ (the fade and the sweep go on across the split)" \
  '! cmp -s "$tmp/whole-00023.png" "$tmp/whole-00024.png"'
check "frames 24 and 25 differ" '! cmp -s "$tmp/whole-00024.png" "$tmp/whole-00025.png"'

# --resume: cut frame 26 short, remove frame 29, and remember the others' inodes.
head -c 900 "$tmp/whole-00026.png" >"$tmp/part-00026.png"
rm "$tmp/part-00029.png"
before=$(stat -c '%i %Y' "$tmp"/part-0002[4-57-8].png "$tmp"/part-0003[01].png)
sleep 1
"$haze" render "$show" --video "$tmp/part-%05d.png" "${opts[@]}" --frames 24-31 --resume >"$tmp/resume.out"
check "--resume redid 2 frames, kept 6: $(tail -n 1 "$tmp/resume.out")" \
  'grep -qx "frames 24-31: 8, 2 drawn, 0 repeated, 6 complete already" "$tmp/resume.out"'
check "the complete frames were not written again" \
  '[ "$before" = "$(stat -c "%i %Y" "$tmp"/part-0002[4-57-8].png "$tmp"/part-0003[01].png)" ]'
check "the cut-short frame is redone, equal to the one run's" 'cmp -s "$tmp/part-00026.png" "$tmp/whole-00026.png"'
check "the missing frame is redone, equal to the one run's" 'cmp -s "$tmp/part-00029.png" "$tmp/whole-00029.png"'
check "no temporary file is left" '[ -z "$(find "$tmp" -name "*.tmp*")" ]'

# EXR frames of a range, and a show whose hazers move the density field and whose dust drifts.
air="$root/examples/demo/air.haze.json"
"$haze" render "$air" --video "$tmp/air-%03d.exr" --duration 1 --fps 4 --width 64 --height 36 >/dev/null
"$haze" render "$air" --video "$tmp/airp-%03d.exr" --duration 1 --fps 4 --width 64 --height 36 --frames 2-3 >/dev/null
"$haze" render "$air" --video "$tmp/airp-%03d.exr" --duration 1 --fps 4 --width 64 --height 36 --frames 0-1 >/dev/null
same=0
for f in "$tmp"/air-*.exr; do cmp -s "$f" "${f/air-/airp-}" && same=$((same + 1)); done
check "hazers: EXR frames of two ranges are the one run's ($same of 4)" '[ "$same" -eq 4 ]'
"$haze" render "$air" --video "$tmp/airpng-%03d.png" --duration 1 --fps 4 --width 64 --height 36 >/dev/null
"$haze" render "$air" --video "$tmp/airpng2-%03d.png" --duration 1 --fps 4 --width 64 --height 36 --frames 3 >/dev/null
check "hazers and dust: a PNG range of one frame is the one run's" 'cmp -s "$tmp/airpng-003.png" "$tmp/airpng2-003.png"'

# Bad ranges and misuse: one line, the right exit status, no file.
"$haze" render "$show" --video "$tmp/bad-%05d.png" "${opts[@]}" --frames 30-40 2>"$tmp/err"; rc=$?
check "a range past the end: exit 1, one line ($(cat "$tmp/err"))" \
  '[ $rc -eq 1 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q "this video has 32 frames (0-31)" "$tmp/err"'
check "no frame written for a bad range" '[ -z "$(ls "$tmp"/bad-* 2>/dev/null)" ]'
"$haze" render "$show" --video "$tmp/bad-%05d.png" "${opts[@]}" --frames 9-3 2>"$tmp/err"; rc=$?
check "a reversed range: exit 2 ($(cat "$tmp/err"))" '[ $rc -eq 2 ] && grep -q "first frame comes after the last" "$tmp/err"'
"$haze" render "$show" --video "$tmp/bad.mp4" "${opts[@]}" --frames 0-3 2>"$tmp/err"; rc=$?
check "--frames of a video file: exit 1 ($(cat "$tmp/err"))" '[ $rc -eq 1 ] && [ ! -e "$tmp/bad.mp4" ]'
"$haze" render "$show" --cue 2 -o "$tmp/bad.png" --resume 2>"$tmp/err"; rc=$?
check "--resume on a still: exit 2" '[ $rc -eq 2 ]'

echo "render_frames: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
