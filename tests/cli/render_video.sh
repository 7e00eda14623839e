#!/usr/bin/env bash
# `haze render --video`: 3 s of the demo's fade from cue 1 into cue 2 at 320x180, decoded by
# FFmpeg's command-line tools (not haze): frame count, size, frame rate, codec, and the frame at
# 1.5 s against the still `haze render --cue 2 --at 1.5` within the codec's error (PSNR > 35 dB,
# measured 39.5 dB). Image sequences (PNG bit-exact with the still, EXR against the PFM). Bad
# input (unwritable path, missing cue, missing codec, Ctrl-C): one line, non-zero exit, and no
# file under the final name.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
show="$root/examples/demo/demo.haze.json"
size=(--width 320 --height 180)
# Frames are compared with stills, which are metered each on its own: the videos here are metered
# per frame too (a video holds one exposure by default: render_exposure_fade.sh).
vsize=(--width 320 --height 180 --exposure-mode per-frame)

# 12 fps puts a frame exactly at 1.5 s (frame 18).
"$haze" render "$show" --video "$tmp/fade.mp4" --from 2 --to 2 --duration 3 --fps 12 "${vsize[@]}" >/dev/null
probe() { ffprobe -v error -select_streams v:0 -count_frames -show_entries "stream=$1" -of default=nw=1:nk=1 "$tmp/fade.mp4"; }
check "36 frames ($(probe nb_read_frames))" '[ "$(probe nb_read_frames)" = 36 ]'
check "320x180 ($(probe width)x$(probe height))" '[ "$(probe width)x$(probe height)" = 320x180 ]'
check "12 fps ($(probe r_frame_rate))" '[ "$(probe r_frame_rate)" = 12/1 ]'
check "H.264 ($(probe codec_name))" '[ "$(probe codec_name)" = h264 ]'
"$haze" render "$show" --cue 2 --at 1.5 "${size[@]}" -o "$tmp/still.png"
ffmpeg -v error -i "$tmp/fade.mp4" -vf 'select=eq(n\,18),scale=in_color_matrix=bt709:in_range=tv:out_range=pc' \
  -frames:v 1 -y "$tmp/frame18.png"
psnr=$(compare -metric PSNR "$tmp/still.png" "$tmp/frame18.png" null: 2>&1)
echo "PSNR of the frame at 1.5 s against the still: $psnr dB"
check "frame at 1.5 s vs the still: PSNR $psnr dB > 35" 'awk -v p="$psnr" "BEGIN { exit !(p > 35) }"'
# The frame before is another moment of the fade: the comparison can tell them apart.
ffmpeg -v error -i "$tmp/fade.mp4" -vf 'select=eq(n\,6),scale=in_color_matrix=bt709:in_range=tv:out_range=pc' \
  -frames:v 1 -y "$tmp/frame6.png"
psnr6=$(compare -metric PSNR "$tmp/still.png" "$tmp/frame6.png" null: 2>&1)
check "frame at 0.5 s differs from the still at 1.5 s (PSNR $psnr6 dB < 35)" 'awk -v p="$psnr6" "BEGIN { exit !(p < 35) }"'

# Image sequences: one file per frame, numbered from 0.
"$haze" render "$show" --video "$tmp/seq-%05d.png" --from 2 --to 2 --duration 0.5 --fps 4 "${vsize[@]}" >/dev/null
check "2 PNGs for 0.5 s at 4 fps" '[ "$(ls "$tmp"/seq-*.png | wc -l)" -eq 2 ] && [ -f "$tmp/seq-00001.png" ]'
"$haze" render "$show" --cue 2 --at 0.25 "${size[@]}" -o "$tmp/still025.png"
check "PNG frame 1 is the still at 0.25 s" 'cmp -s "$tmp/seq-00001.png" "$tmp/still025.png"'
# Cue 3 waits 2 s (its delay) before moving: frame 1 repeats frame 0's picture without drawing
# it, and must still be the stage at 0.5 s.
"$haze" render "$show" --video "$tmp/delay-%d.png" --from 3 --to 3 --duration 1 --fps 2 "${vsize[@]}" >/dev/null
"$haze" render "$show" --cue 3 --at 0.5 "${size[@]}" -o "$tmp/still3.png"
check "a repeated frame of a delay is the still of its moment" 'cmp -s "$tmp/delay-1.png" "$tmp/still3.png"'
# --caption: the band in the bottom-left (captionBand: 192x12 at 320x180) carries white text on
# a dark ground; every pixel above it is the uncaptioned frame's.
"$haze" render "$show" --video "$tmp/cap-%05d.png" --from 2 --to 2 --duration 0.5 --fps 4 --caption "${vsize[@]}" >/dev/null
convert "$tmp/cap-00001.png" -crop 320x168+0+0 +repage "$tmp/cap-top.png"
convert "$tmp/still025.png" -crop 320x168+0+0 +repage "$tmp/still-top.png"
check "caption: the frame above the band is untouched" '[ "$(compare -metric AE "$tmp/cap-top.png" "$tmp/still-top.png" null: 2>&1)" = 0 ]'
white=$(convert "$tmp/cap-00001.png" -crop 192x12+0+168 +repage -colorspace gray -format "%[fx:maxima]" info:)
check "caption: white text in the band (brightest $white > 0.9)" 'awk -v m="$white" "BEGIN { exit !(m > 0.9) }"'
"$haze" render "$show" --video "$tmp/seq-%03d.exr" --from 2 --to 2 --duration 0.25 --fps 4 --width 64 --height 36 >/dev/null
"$haze" render "$show" --cue 2 --at 0 --width 64 --height 36 -o "$tmp/still0.pfm"
ffmpeg -v error -i "$tmp/seq-000.exr" -f rawvideo -pix_fmt gbrpf32le -y "$tmp/seq-000.raw"
python3 "$root/tests/cli/exr_vs_pfm.py" "$tmp/seq-000.exr" "$tmp/seq-000.raw" "$tmp/still0.pfm" half >"$tmp/exrcheck" 2>&1; rc=$?
check "EXR frame 0 is the PFM at 0 s: $(tail -n 1 "$tmp/exrcheck")" '[ $rc -eq 0 ] && grep -q "frame 0 at 0.000 s, cue 2" "$tmp/exrcheck"'

# --timeline: GO cue 2 at 0, then cue 4 at 0.5 s: frame 0 is cue 2's start, frame 2 (1 s) is no
# longer cue 2's fade at 1 s but cue 4 fading in.
echo '{"go": [{"cue": "2", "at": 0}, {"cue": "4", "at": 0.5}], "end": 1.5}' >"$tmp/timeline.json"
"$haze" render "$show" --video "$tmp/tl-%d.png" --timeline "$tmp/timeline.json" --fps 2 "${vsize[@]}" >/dev/null
"$haze" render "$show" --cue 2 --at 0 "${size[@]}" -o "$tmp/c2at0.png"
"$haze" render "$show" --cue 2 --at 1 "${size[@]}" -o "$tmp/c2at1.png"
check "timeline: 3 frames for end 1.5 s at 2 fps" '[ "$(ls "$tmp"/tl-*.png | wc -l)" -eq 3 ]'
check "timeline: frame 0 is cue 2 at 0 s" 'cmp -s "$tmp/tl-0.png" "$tmp/c2at0.png"'
check "timeline: frame 2 is not cue 2 at 1 s (cue 4 was GOne at 0.5 s)" '! cmp -s "$tmp/tl-2.png" "$tmp/c2at1.png"'
echo '{"go": [{"cue": "2", "at": 1}, {"cue": "3", "at": 0.5}]}' >"$tmp/backwards.json"
echo '{"go": [{"cue": "77", "at": 0}]}' >"$tmp/nocue.json"

expect_error() {  # name, expected text, final file that must not exist, command...
  local name=$1 want=$2 file=$3; shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  if [ $rc -ne 0 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "$want" "$tmp/err" && [ ! -e "$file" ]; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1)); echo "FAIL $name: rc=$rc, file $( [ -e "$file" ] && echo left || echo absent ), stderr:"; cat "$tmp/err"
  fi
}
touch "$tmp/not-a-folder"
expect_error unwritable "not-a-folder/x.mp4" "$tmp/not-a-folder/x.mp4" \
  "$haze" render "$show" --video "$tmp/not-a-folder/x.mp4" --duration 0.1 "${vsize[@]}"
expect_error missing-cue '"99"' "$tmp/x.mp4" "$haze" render "$show" --video "$tmp/x.mp4" --from 99 "${vsize[@]}"
expect_error backwards-range "comes after" "$tmp/x.mp4" "$haze" render "$show" --video "$tmp/x.mp4" --from 3 --to 2 "${vsize[@]}"
expect_error missing-codec "no-such-encoder" "$tmp/x.mp4" \
  "$haze" render "$show" --video "$tmp/x.mp4" --codec no-such-encoder --duration 0.1 "${vsize[@]}"
expect_error odd-size "even width" "$tmp/x.mp4" "$haze" render "$show" --video "$tmp/x.mp4" --duration 0.1 --width 33 --height 18
expect_error bad-pattern "one frame number" "$tmp/y-0-0.png" "$haze" render "$show" --video "$tmp/y-%d-%d.png" --duration 0.1 "${vsize[@]}"

expect_error timeline-backwards "backwards.json:/go/1/at" "$tmp/x.mp4" \
  "$haze" render "$show" --video "$tmp/x.mp4" --timeline "$tmp/backwards.json" "${vsize[@]}"
expect_error timeline-no-cue 'nocue.json:/go/0/cue.*"77"' "$tmp/x.mp4" \
  "$haze" render "$show" --video "$tmp/x.mp4" --timeline "$tmp/nocue.json" "${vsize[@]}"

# Ctrl-C in the middle: the render stops between frames, says so, and removes its temporary file.
"$haze" render "$show" --video "$tmp/long.mp4" --duration 60 --fps 12 "${vsize[@]}" >/dev/null 2>"$tmp/err" &
pid=$!
for _ in $(seq 600); do compgen -G "$tmp/.long.mp4.tmp-*" >/dev/null && break; sleep 0.1; done
kill -INT $pid; wait $pid; rc=$?
check "Ctrl-C: rc $rc, one line saying so" '[ $rc -ne 0 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q interrupted "$tmp/err"'
check "Ctrl-C: neither the video nor its temporary file is left" '[ ! -e "$tmp/long.mp4" ] && ! compgen -G "$tmp/.long.mp4.tmp-*" >/dev/null'
check "no temporary files left by any failure" '! compgen -G "$tmp/.*.tmp-*" >/dev/null'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
