#!/usr/bin/env bash
# `haze bench --move DEG [--map-budget MS]` (docs/rendering.md, "Map work spread over frames"):
# every beam turns each frame, so without a budget all 8 shadow maps are drawn every frame; with
# a budget far under one map's time one map a frame is drawn and the other 7 beams wait.
set -uo pipefail
haze=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
move() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['move'][sys.argv[2]])" "$1" "$2"; }

common=(--fixtures 8 --width 64 --height 36 --quality draft --frames 3 --json)
"$haze" bench "${common[@]}" --move 2 >"$tmp/free.json" 2>"$tmp/err"
check "bench --move exits 0 ($(cat "$tmp/err"))" '[ -s "$tmp/free.json" ]'
check "no budget: 8 maps a frame" '[ "$(move "$tmp/free.json" median_maps_per_frame)" = "8.0" ]'
check "no budget: nothing waits" '[ "$(move "$tmp/free.json" most_maps_pending)" -eq 0 ]'
"$haze" bench "${common[@]}" --move 2 --map-budget 0.000001 >"$tmp/tight.json" 2>"$tmp/err"
check "bench --move --map-budget exits 0 ($(cat "$tmp/err"))" '[ -s "$tmp/tight.json" ]'
check "a tiny budget: 1 map a frame" '[ "$(move "$tmp/tight.json" median_maps_per_frame)" = "1.0" ]'
check "a tiny budget: 7 beams wait" '[ "$(move "$tmp/tight.json" most_maps_pending)" -eq 7 ]'
"$haze" bench --fixtures 8 --frames 1 --map-budget 5 2>"$tmp/err" >/dev/null; rc=$?
check "--map-budget without --move fails in one line" '[ $rc -ne 0 ] && grep -q "needs --move" "$tmp/err" && [ "$(wc -l <"$tmp/err")" -eq 1 ]'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
