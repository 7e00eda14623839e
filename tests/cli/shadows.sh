#!/usr/bin/env bash
# Soft and hard shadows from the command line (docs/physics.md, "Soft shadows"): `haze render
# --shadows soft|hard` gives different images of a demo cue, a show saying "shadows": "hard"
# renders as --shadows hard does, no flag follows the show (soft by default), a bad value is one
# clear line, and `haze bench --shadows compare` reports the soft shadows' cost ratio.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

show="$root/examples/demo/demo.haze.json"
size=(--cue 2 --width 96 --height 54 --quality draft)
"$haze" render "$show" "${size[@]}" --shadows soft -o "$tmp/soft.pfm"
"$haze" render "$show" "${size[@]}" --shadows hard -o "$tmp/hard.pfm"
"$haze" render "$show" "${size[@]}" -o "$tmp/default.pfm"
check "soft and hard images written" '[ -s "$tmp/soft.pfm" ] && [ -s "$tmp/hard.pfm" ]'
check "soft and hard shadows differ" '! cmp -s "$tmp/soft.pfm" "$tmp/hard.pfm"'
check "without --shadows the show's default (soft)" 'cmp -s "$tmp/soft.pfm" "$tmp/default.pfm"'
# The demo with "shadows": "hard" in its atmosphere, next to its profiles and venue.
mkdir -p "$tmp/show"
cp -r "$root/examples/demo/." "$tmp/show/"
sed 's#"atmosphere": {#"atmosphere": { "shadows": "hard",#' "$show" >"$tmp/show/demo.haze.json"
check "the edited show names hard shadows" 'grep -q "\"shadows\": \"hard\"" "$tmp/show/demo.haze.json"'
"$haze" render "$tmp/show/demo.haze.json" "${size[@]}" -o "$tmp/show-hard.pfm"
check "a show with hard shadows renders as --shadows hard" 'cmp -s "$tmp/hard.pfm" "$tmp/show-hard.pfm"'
"$haze" render "$show" --shadows fuzzy -o "$tmp/x.png" >"$tmp/out" 2>"$tmp/err"; rc=$?
check "--shadows fuzzy is one line naming the option" '[ $rc -ne 0 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "--shadows" "$tmp/err"'
sed 's#"atmosphere": {#"atmosphere": { "shadows": "fuzzy",#' "$show" >"$tmp/show/bad.haze.json"
"$haze" render "$tmp/show/bad.haze.json" "${size[@]}" -o "$tmp/x.png" >"$tmp/out" 2>"$tmp/err"; rc=$?
check "a bad atmosphere.shadows names its place" '[ $rc -ne 0 ] && grep -q "/atmosphere/shadows" "$tmp/err"'
"$haze" bench --fixtures 2 --width 64 --height 36 --frames 1 --quality draft --shadows compare --json >"$tmp/bench.json"
check "bench --shadows compare gives the ratio" 'grep -q "\"ratio_frame\"" "$tmp/bench.json" && grep -q "\"median_frame_ms_hard\"" "$tmp/bench.json"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
