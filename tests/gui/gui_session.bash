# Sourced by GUI tests: starts haze under Xvfb on a show and drives it with real X input events
# (xdotool, through XTEST): clicks, key taps, and keys held for a few frames where an ImGui
# widget reads them (ImGui 1.86 sees a key only if it is down at a frame, and a frame on
# llvmpipe can take longer than a tap). Window screenshots with ImageMagick's import.
# Needs: $root, $tmp; tests/gui/xvfb.bash sourced and start_xvfb run.
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
start_haze() {
  local name=$1; shift
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
  sleep 1.5
}
click() { xdotool mousemove --window "$win" "$1" "$2"; sleep 0.3; xdotool click 1; sleep 1.5; }
tap() { xdotool key "$@"; sleep 0.6; }
hold() { xdotool keydown "$1"; sleep 0.5; xdotool keyup "$1"; sleep 0.5; }
type_text() { xdotool type --delay 60 "$1"; sleep 0.5; }
shot() { import -window "$win" "$tmp/$1.png" 2>/dev/null; [ -n "${HAZE_GUI_SHOTS:-}" ] && cp "$tmp/$1.png" "$HAZE_GUI_SHOTS/"; true; }
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
# Waits up to 10 s for haze to exit; sets rc.
wait_exit() {
  for _ in $(seq 50); do kill -0 $pid 2>/dev/null || break; sleep 0.2; done
  if kill -0 $pid 2>/dev/null; then rc=timeout; else wait $pid; rc=$?; fi
}
