#!/usr/bin/env bash
# `haze sheet`: the demo's review sheet, read back by poppler (not by haze's writer): the PDF
# has the cue pages and the patch page; on the pages rendered to images (pdftoppm) every
# cue's thumbnail is where the layout puts it and matches `haze render` of that cue and camera
# (and not the next cue's); every cue's number and label, and the patch, are in the text.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
show="$root/examples/demo/demo.haze.json"

"$haze" sheet "$show" --camera FOH --camera Side --quality draft -o "$tmp/sheet.pdf" >/dev/null
pages=$(pdfinfo "$tmp/sheet.pdf" | awk '/^Pages:/ { print $2 }')
cues=$(grep -c '"number"' "$show")
check "pages: $pages = ceil($cues / 4) cue pages + 1 patch page" '[ "$pages" -eq $(( (cues + 3) / 4 + 1 )) ]'
pdftoppm -r 144 -png "$tmp/sheet.pdf" "$tmp/page"  # 144 dpi: 2 pixels per point, the thumbnails' own 320x180

numbers=$(python3 -c 'import json,sys; [print(c["number"]) for c in json.load(open(sys.argv[1]))["cue_lists"][0]["cues"]]' "$show")
labels=$(python3 -c 'import json,sys; [print(c["label"]) for c in json.load(open(sys.argv[1]))["cue_lists"][0]["cues"]]' "$show")
# SheetLayout (renderer/output/sheet_pdf.h): 4 rows a page, thumbnails 160x90 pt at
# x = 176 + 168 c, y = 88 + 104 (row % 4); twice that in pixels at 144 dpi.
thumb() {  # cue index, camera column, output
  local page=$(( $1 / 4 + 1 )) x=$(( 2 * (176 + 168 * $2) )) y=$(( 2 * (88 + 104 * ($1 % 4)) ))
  convert "$tmp/page-$page.png" -crop "320x180+$x+$y" +repage -scale 25% "$3"
}
# Both sides are compared at a quarter size (box filter): poppler places an image up to half a
# pixel off, which costs 5-10 dB at full size on these sharp beams and nothing at 80x45.
small() { convert "$1" -scale 25% "$2"; }
psnr() { compare -metric PSNR "$1" "$2" null: 2>&1 | cut -d' ' -f1; }
i=0
for n in $numbers; do
  "$haze" render "$show" --cue "$n" --camera FOH --width 320 --height 180 --quality draft -o "$tmp/full$i.png"
  small "$tmp/full$i.png" "$tmp/cue$i.png"
  thumb $i 0 "$tmp/thumb$i.png"
  i=$((i + 1))
done
for ((i = 0; i < cues; i++)); do
  p=$(psnr "$tmp/thumb$i.png" "$tmp/cue$i.png")
  echo "cue index $i: thumbnail vs its render $p dB"
  check "cue index $i: the page's FOH thumbnail is its render (PSNR $p dB > 28)" 'awk -v p="$p" "BEGIN { exit !(p > 28) }"'
  # The cue number is drawn at the row's left (18 pt bold from x 36, baseline 22 pt below the
  # row's top line): ink there on the image.
  page=$(( i / 4 + 1 )) top=$(( 2 * (84 + 104 * (i % 4)) ))
  ink=$(convert "$tmp/page-$page.png" -crop "120x44+72+$((top + 4))" +repage -colorspace gray -format "%[fx:mean]" info:)
  check "cue index $i: its number is drawn (mean grey $ink < 0.97)" 'awk -v m="$ink" "BEGIN { exit !(m < 0.97) }"'
  j=$(( (i + 1) % cues ))
  q=$(psnr "$tmp/thumb$i.png" "$tmp/cue$j.png")
  check "cue index $i: and not cue index $j's (PSNR $q dB, 10 below $p)" 'awk -v p="$p" -v q="$q" "BEGIN { exit !(q < p - 10) }"'
done
# The Side camera's column, for the first cue.
first=$(head -n 1 <<<"$numbers")
"$haze" render "$show" --cue "$first" --camera Side --width 320 --height 180 --quality draft -o "$tmp/side-full.png"
small "$tmp/side-full.png" "$tmp/side.png"
thumb 0 1 "$tmp/side-thumb.png"
p=$(psnr "$tmp/side-thumb.png" "$tmp/side.png")
check "the Side column holds the Side camera (PSNR $p dB > 28)" 'awk -v p="$p" "BEGIN { exit !(p > 28) }"'

pdftotext -layout "$tmp/sheet.pdf" "$tmp/sheet.txt"
while read -r n; do
  check "cue number $n in the text" 'grep -qE "^$n( |$)" "$tmp/sheet.txt"'
done <<<"$numbers"
while read -r l; do
  check "label '$l' in the text" 'grep -qF "$l" "$tmp/sheet.txt"'
done <<<"$labels"
pdftotext -layout -f "$pages" -l "$pages" "$tmp/sheet.pdf" "$tmp/patch.txt"
check "patch page: 101 Spot 1, spot, Standard, universe 1, address 1" 'grep -qE "^101 Spot 1 +spot +Standard +1 +1$" "$tmp/patch.txt"'
check "patch page: every fixture" '[ "$(grep -cE "^[0-9]+ " "$tmp/patch.txt")" -eq "$(grep -c "\"patch\"" "$show")" ]'

expect_error() {  # name, expected text, command...
  local name=$1 want=$2; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  if [ $rc -ne 0 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "$want" "$tmp/err"; then pass=$((pass + 1))
  else fail=$((fail + 1)); echo "FAIL $name: rc=$rc:"; cat "$tmp/err"; fi
}
touch "$tmp/not-a-folder"
expect_error unwritable "not-a-folder/s.pdf" "$haze" sheet "$show" --quality draft -o "$tmp/not-a-folder/s.pdf"
expect_error not-pdf "PDF" "$haze" sheet "$show" -o "$tmp/s.png"
expect_error unknown-camera "Balcony" "$haze" sheet "$show" --camera Balcony -o "$tmp/s.pdf"
check "no sheet left by the failures" '[ ! -e "$tmp/s.pdf" ] && [ ! -e "$tmp/s.png" ] && ! compgen -G "$tmp/.*tmp*" >/dev/null'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
