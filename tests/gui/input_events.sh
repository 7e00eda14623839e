#!/usr/bin/env bash
# The GUI under Xvfb driven by real X input events (xdotool, XTEST): the demo opens on cue 1;
# a click on GO fades to cue 2 (window screenshots differ far more than a still cue's refinement
# noise); a click on cue 1 in the list goes back to its look; File > Quit exits with status 0.
# Coordinates are the default ImGui layout at 640x360 (File menu, Playback window at 10,30).
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/xvfb.bash"
start_xvfb
for tool in xdotool import compare; do
  command -v $tool >/dev/null || { echo "FAIL: $tool is not installed (make deps installs it)"; exit 1; }
done
tmp=$(mktemp -d)
trap 'kill $pid 2>/dev/null; kill $XVFB_PID 2>/dev/null; rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

"$haze" open "$root/examples/demo/demo.haze.json" --width 640 --height 360 >"$tmp/out" 2>&1 &
pid=$!
win=""
for _ in $(seq 150); do
  win=$(xdotool search --name "haze - demo" 2>/dev/null | head -1)
  [ -n "$win" ] && break
  sleep 0.2
done
check "the window appears" '[ -n "$win" ]'
[ -n "$win" ] || { echo "$pass passed, $fail failed"; exit 1; }
click() { xdotool mousemove --window "$win" "$1" "$2" click 1; }
shot() { import -window "$win" "$tmp/$1.png" 2>/dev/null; }
difference() { compare -metric RMSE "$tmp/$1.png" "$tmp/$2.png" null: 2>&1 | sed 's/.*(\(.*\))/\1/'; }

sleep 8          # cue 1 (5 s fade from dark) has arrived
shot cue1a
sleep 2
shot cue1b
# Two pictures of the same still cue differ by refinement noise and the frame-time text only.
noise=$(difference cue1a cue1b)
click 29 100     # GO: cue 2 (gobos, deep blue wash) fades in over 6 s
sleep 9
shot cue2
go=$(difference cue1a cue2)
check "GO changes the stage (difference $go, still-cue noise $noise)" \
  'awk -v d="$go" -v n="$noise" "BEGIN { exit !(d > 3 * n && d > 0.02) }"'
click 60 120     # cue 1 in the cue list
sleep 8
shot back1
back=$(difference cue1a back1)
check "selecting cue 1 in the list brings its look back (difference $back)" \
  'awk -v d="$back" -v g="$go" "BEGIN { exit !(d < 0.5 * g) }"'
click 20 9       # File
sleep 1
click 25 105     # Quit
for _ in $(seq 50); do kill -0 $pid 2>/dev/null || break; sleep 0.2; done
if kill -0 $pid 2>/dev/null; then
  check "File > Quit ends the program" 'false'
else
  wait $pid; rc=$?
  check "clean exit (status $rc)" '[ $rc -eq 0 ]'
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
