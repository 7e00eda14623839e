#!/usr/bin/env bash
# Every MVR of the test data (gdtf/mvr: ../shared/data's when present, else tests/data/shared's),
# imported, validated and rendered with the import's own camera ("MVR overview") and cue ("MVR
# focus" 1, every fixture at full), shows its rig: at least 10 % of the pixels above 1 cd/m^2 and
# the brightest above 10. The import's ambient is 0.02 on a 0.6 grey (0.012 cd/m^2), so an image
# lit by ambient light alone, such as a camera outside the venue's walls, fails.
# Usage: mvr_render.sh HAZE REPO
set -u
haze=$1
repo=$2
source "$repo/tests/cli/test_data.bash"
data=$(data_dir gdtf/mvr)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$repo/tests/cli/checks.bash"

count=0
for mvr in "$data"/*.mvr; do
  name=$(basename "$mvr" .mvr)
  count=$((count + 1))
  "$haze" import-mvr "$mvr" -o "$tmp/$name.haze.json" >/dev/null 2>"$tmp/$name.err"
  check "$name: import-mvr exits 0: $(head -2 "$tmp/$name.err")" $?
  "$haze" validate "$tmp/$name.haze.json" >/dev/null 2>"$tmp/$name.verr"
  check "$name: haze validate accepts the import: $(head -2 "$tmp/$name.verr")" $?
  "$haze" render "$tmp/$name.haze.json" --camera "MVR overview" --list "MVR focus" --cue 1 \
    --width 320 --height 180 -o "$tmp/$name.pfm" >/dev/null 2>"$tmp/$name.rerr"
  check "$name: render exits 0: $(head -2 "$tmp/$name.rerr")" $?
  [ -f "$tmp/$name.pfm" ] || continue
  # PFM: "PF", "W H", a scale (negative: little-endian floats), then RGB floats bottom row first.
  header=$(head -c 40 "$tmp/$name.pfm" | head -n 3 | wc -c)
  dims=$(head -c 40 "$tmp/$name.pfm" | sed -n 2p)
  scale=$(head -c 40 "$tmp/$name.pfm" | sed -n 3p)
  check "$name: a 320x180 little-endian RGB PFM (got \"$dims\", scale $scale)" \
    "$([ "$(head -c 2 "$tmp/$name.pfm")" = "PF" ] && [ "$dims" = "320 180" ] && [ "${scale:0:1}" = "-" ]; echo $?)"
  # Per pixel, the mean of its three channels (cd/m^2).
  stats=$(od -A n -t f4 -v -j "$header" "$tmp/$name.pfm" | tr -s ' ' '\n' | grep -v '^$' |
    awk '{ s += $1; if (NR % 3 == 0) { n++; if (s / 3 > 1.0) lit++; if (s / 3 > max) max = s / 3; s = 0 } }
         END { printf "%d %d %.4f", n, lit, max }')
  read -r pixels lit max <<<"$stats"
  check "$name: 320x180 pixels read (got $pixels)" "$([ "$pixels" = 57600 ]; echo $?)"
  check "$name: at least 10% of the pixels above 1 cd/m^2 (got $lit of $pixels)" "$([ "$lit" -ge 5760 ]; echo $?)"
  check "$name: the brightest pixel above 10 cd/m^2 (got $max)" "$(awk -v m="$max" 'BEGIN { exit !(m > 10) }'; echo $?)"
  echo "$name: $lit of $pixels pixels above 1 cd/m^2, brightest $max"
done
# Three MVRs in ../shared/data, two of them in the repository (tests/data/shared/SOURCES.md).
want_data gdtf/mvr/capture_demo_show.mvr && expected=3 || expected=2
check "the $expected MVR files were found (got $count)" "$([ "$count" -ge "$expected" ]; echo $?)"

echo "$passed passed, $fail failed"
data_exit "$fail"
