#!/usr/bin/env bash
# `haze bench --show` times a show's cue with the same figures as the bench scene: the demo's
# fixtures are counted, its lit beams draw (plane fragments, beams in view), a named camera and
# cue are taken, and wrong combinations fail with one line.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

show="$root/examples/demo/demo.haze.json"
fixtures=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['fixtures']))" "$show")
"$haze" bench --show "$show" --cue 2 --camera Side --width 160 --height 90 --quality draft --frames 1 --json \
  >"$tmp/b.json" 2>"$tmp/err"
check "bench --show exits 0 ($(cat "$tmp/err"))" '[ -s "$tmp/b.json" ]'
check "counts the show's $fixtures fixtures" '[ "$(field "$tmp/b.json" fixtures)" -eq "$fixtures" ]'
check "its beams draw" '[ "$(field "$tmp/b.json" plane_fragments)" -gt 0 ] && [ "$(field "$tmp/b.json" beams_in_view)" -gt 0 ]'
check "pass times are measured" 'python3 -c "import json,sys; t=json.load(open(sys.argv[1]))[\"pass_ms\"]; sys.exit(not t[\"surfaces\"] > 0)" "$tmp/b.json"'
check "no warnings" '[ "$(field "$tmp/b.json" warnings)" = "[]" ]'
"$haze" bench --show "$show" --camera Nowhere --frames 1 2>"$tmp/err" >/dev/null; rc=$?
check "an unknown camera fails naming it" '[ $rc -ne 0 ] && grep -q "Nowhere" "$tmp/err" && [ "$(wc -l <"$tmp/err")" -eq 1 ]'
"$haze" bench --show "$show" --fixtures 4 --frames 1 2>"$tmp/err" >/dev/null; rc=$?
check "--fixtures with --show fails" '[ $rc -ne 0 ] && grep -q "exclude" "$tmp/err"'
"$haze" bench --cue 2 --frames 1 2>"$tmp/err" >/dev/null; rc=$?
check "--cue without --show fails" '[ $rc -ne 0 ] && grep -q "need --show" "$tmp/err"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
