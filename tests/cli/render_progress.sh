#!/usr/bin/env bash
# Progress lines on stderr: none into a pipe or file unless --progress is given; with it, a last
# "N/N ... (100 %) ... done in" line for a video's frames, --all-cues' cues and the reference's
# rows; on a terminal (a pty from script(1)) without --progress, redrawn in place with \r.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; cat "$tmp/err"; fi; }
show="$root/examples/demo/demo.haze.json"
small=(--width 64 --height 36)

"$haze" render "$show" --video "$tmp/a.mp4" --duration 0.5 --fps 4 "${small[@]}" >/dev/null 2>"$tmp/err"
check "no progress into a file without --progress" '[ ! -s "$tmp/err" ]'
"$haze" render "$show" --video "$tmp/b.mp4" --duration 0.5 --fps 4 "${small[@]}" --progress >/dev/null 2>"$tmp/err"
check "video: last line 2/2 frames, done" 'tail -n 1 "$tmp/err" | grep -qE "^haze render: 2/2 frames \(100 %\), [0-9.]+ frames/s, done in [0-9]+ s$"'
"$haze" render "$show" --all-cues --quality draft "${small[@]}" --progress -o "$tmp/cues/" >"$tmp/out" 2>"$tmp/err"
cues=$(grep -c '"number"' "$show")
check "--all-cues: last line $cues/$cues cues" 'tail -n 1 "$tmp/err" | grep -qE "^haze render: $cues/$cues cues \(100 %\)"'
check "--all-cues still lists its files on stdout" '[ "$(wc -l <"$tmp/out")" -eq "$cues" ]'
"$haze" render "$show" --quality reference --width 32 --height 18 --progress -o "$tmp/r.pfm" >/dev/null 2>"$tmp/err"
check "reference: last line 18/18 rows" 'tail -n 1 "$tmp/err" | grep -qE "^haze render \(reference\): 18/18 rows \(100 %\)"'
if command -v script >/dev/null; then
  script -qec "\"$haze\" render \"$show\" --video \"$tmp/c.mp4\" --duration 0.5 --fps 4 ${small[*]}" /dev/null \
    >"$tmp/err" 2>&1
  check "on a terminal: drawn without --progress, in place" 'grep -q $'"'"'\r'"'"'"haze render: 2/2 frames (100 %)" "$tmp/err"'
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
