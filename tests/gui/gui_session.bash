# Sourced by GUI tests: starts haze under Xvfb on a show and drives it with real X input events
# (xdotool, through XTEST): clicks, key taps, and keys held for a few frames where an ImGui
# widget reads them (ImGui 1.86 sees a key only if it is down at a frame, and a frame on
# llvmpipe can take longer than a tap). Window screenshots with ImageMagick's import.
# Nothing here sleeps for a guessed time and hopes the GUI kept up: haze writes the number of
# frames it has presented to $HAZE_GUI_FRAME_FILE, and every input is followed by settle, which
# waits for four more frames: one polls the event, and what it starts can take a frame or two
# more to show (a click selects on the release, a popup focuses its field the frame after it
# opens). On a
# loaded machine frames get slow and the tests wait longer; they fail only if haze draws nothing
# for 300 s (an import on a loaded machine holds one frame for long).
# Sourcing it starts the test's own Xvfb and makes $tmp (removed on exit, with haze, the Xvfb and
# any pids a test puts in $GUI_KILL). Needs: $haze, $root.
. "$root/tests/gui/xvfb.bash"
start_xvfb
tmp=$(mktemp -d)
export XDG_CONFIG_HOME="$tmp/config"   # recent files go here, not to the user's
pid=""
GUI_KILL=""
trap 'kill $pid $GUI_KILL 2>/dev/null; kill $XVFB_PID 2>/dev/null; rm -rf "$tmp"' EXIT
for tool in xdotool import compare convert; do
  command -v $tool >/dev/null || { echo "FAIL: $tool is not installed (make deps installs it)"; exit 1; }
done
pass=0; fail=0
# Paths are typed into haze's own popup, whatever dialog program the machine has
# (tests/gui/file_dialog.sh unsets this to test the desktop's dialog).
export HAZE_FILE_DIALOG=typed
check() { if eval "$2"; then pass=$((pass + 1)); echo "ok: $1"; else fail=$((fail + 1)); echo "FAIL: $1"; fi; }
finish() { echo "$pass passed, $fail failed"; [ $fail -eq 0 ]; }

# start_haze NAME-IN-TITLE ARGS...: runs haze, waits for its window to be mapped (focusing a
# window not yet mapped is an X error, BadMatch), gives it the input focus.
frames() { local n; n=$(cat "$HAZE_GUI_FRAME_FILE" 2>/dev/null); echo "${n:-0}"; }
# settle [N]: waits until haze has presented N (default 4) more frames, or has exited.
settle() {
  local target=$(( $(frames) + ${1:-4} )) end=$((SECONDS + 300))
  while [ "$(frames)" -lt $target ]; do
    kill -0 $pid 2>/dev/null || return 0
    [ $SECONDS -lt $end ] || { echo "FAIL: haze presented no new frame for 300 s (at frame $(frames))"; exit 1; }
    sleep 0.05
  done
}
# wait_until SECONDS CONDITION: re-checks CONDITION (a shell expression) after every frame.
wait_until() {
  local end=$((SECONDS + $1))
  until eval "$2"; do
    [ $SECONDS -lt $end ] || return 1
    kill -0 $pid 2>/dev/null || { eval "$2"; return; }
    settle 1
  done
}

start_haze() {
  local name=$1; shift
  export HAZE_GUI_FRAME_FILE="$tmp/frames"
  rm -f "$HAZE_GUI_FRAME_FILE"
  "$haze" open "$@" >"$tmp/haze.out" 2>&1 &
  pid=$!
  win=""
  for _ in $(seq 150); do
    win=$(xdotool search --onlyvisible --name "$name" 2>/dev/null | head -1)
    [ -n "$win" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.2
  done
  [ -n "$win" ] || { echo "FAIL: no window named '$name'"; cat "$tmp/haze.out"; exit 1; }
  # No window manager under Xvfb: nothing gives the window the keyboard unless asked.
  xdotool windowfocus --sync "$win"
  settle 3
}
click() { xdotool mousemove --window "$win" "$1" "$2"; settle; xdotool click 1; settle; }
tap() { xdotool key "$@"; settle; }
# A key an ImGui widget reads must be down when a frame starts: held over four frames.
hold() { xdotool keydown "$1"; settle; xdotool keyup "$1"; settle; }
type_text() { xdotool type --delay 60 "$1"; settle; }
# A screenshot of a frame begun after the call (what came before it has been drawn).
shot() {
  settle
  import -window "$win" "$tmp/$1.png" 2>/dev/null
  [ -n "${HAZE_GUI_SHOTS:-}" ] && cp "$tmp/$1.png" "$HAZE_GUI_SHOTS/"
  true
}
title() { xdotool getwindowname "$win"; }
# RMSE (0..1) between two shots, optionally of a region WxH+X+Y.
difference() {
  local a="$tmp/$1.png" b="$tmp/$2.png"
  if [ -n "${3:-}" ]; then
    convert "$a" -crop "$3" +repage "$tmp/_a.png"; convert "$b" -crop "$3" +repage "$tmp/_b.png"
    a="$tmp/_a.png"; b="$tmp/_b.png"
  fi
  compare -metric RMSE "$a" "$b" null: 2>&1 | sed 's/.*(\(.*\))/\1/'
}
# How many pixels of a region WxH+X+Y are the selection's yellow (255, 220, 40).
yellow_pixels() {
  convert "$tmp/$1.png" -crop "$2" +repage -fuzz 12% -fill white -opaque "rgb(255,220,40)" \
    -fill black +opaque white -format "%[fx:mean*w*h]" info: | cut -d. -f1
}
# Waits up to 120 s for haze to exit (it may be mid-frame on a loaded machine); sets rc.
wait_exit() {
  for _ in $(seq 600); do kill -0 $pid 2>/dev/null || break; sleep 0.2; done
  if kill -0 $pid 2>/dev/null; then rc=timeout; else wait $pid; rc=$?; fi
}

# demo_copy OUT: the demo show written to OUT with its venue and profile paths made absolute, so
# the copy works from the test's own folder. Python on stdin (may be empty) edits `show`, the
# parsed JSON, before it is written.
demo_copy() {
  local edit
  edit=$(cat)
  python3 - "$root/examples/demo/demo.haze.json" "$1" "$edit" <<'PY' || { echo "FAIL: could not write the show"; exit 1; }
import json, os, sys
src, out, edit = sys.argv[1:4]
show = json.load(open(src))
base = os.path.dirname(os.path.abspath(src))
show["venue"]["gltf"] = os.path.normpath(os.path.join(base, show["venue"]["gltf"]))
for k, v in show["profiles"].items():
    if isinstance(v, str):
        show["profiles"][k] = os.path.join(base, v)
exec(edit)
json.dump(show, open(out, "w"), indent=2)
PY
}
