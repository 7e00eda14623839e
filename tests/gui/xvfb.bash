# Sourced by GUI tests: start_xvfb starts an Xvfb of the test's own and stops it on exit.
# Xvfb picks a free display itself (-displayfd writes its number once it listens), so any number
# of GUI tests, or twenty copies of one, run side by side without sharing a display or driving
# each other's windows.
# -noreset: an X server resets itself whenever its last client disconnects, and refuses
# connections while it does. The tests' xdotool calls are short-lived clients, so without it a
# haze starting while an xdotool call closed failed with "X11: Failed to open display" (the GUI
# tests' intermittent failure: it came from the server's reset, not from haze).
# -r: no key auto-repeat. A key the tests hold over a few frames (Ctrl+A in a path field) was
# repeated by the server; on a loaded machine a repeat of "a" could fall between xdotool's
# release of Ctrl and of "a", and typed a stray "a" into the path (20 copies side by side: a
# Save as to "a/tmp/...", 10 of 20 walkthroughs failed).
# XVFB_SCREEN: the screen's WxHxDEPTH for a test whose window is larger than 1280x800.
start_xvfb() {
  command -v Xvfb >/dev/null || { echo "FAIL: Xvfb is not installed (make deps installs xvfb)"; exit 1; }
  local dfile n=""
  dfile=$(mktemp)
  Xvfb -displayfd 3 -screen 0 "${XVFB_SCREEN:-1280x800x24}" -nolisten tcp -noreset -r 3>"$dfile" >/dev/null 2>&1 &
  XVFB_PID=$!
  trap 'kill $XVFB_PID 2>/dev/null' EXIT
  for _ in $(seq 200); do
    read -r n < "$dfile" && [ -n "$n" ] && break   # a whole line: the server is listening
    n=""
    kill -0 $XVFB_PID 2>/dev/null || break
    sleep 0.05
  done
  rm -f "$dfile"
  [ -n "$n" ] || { echo "FAIL: could not start Xvfb"; exit 1; }
  export DISPLAY=":$n"
  # Ready when a client can connect (xdotool asks the server for the screen size).
  for _ in $(seq 100); do
    xdotool getdisplaygeometry >/dev/null 2>&1 && return 0
    kill -0 $XVFB_PID 2>/dev/null || break
    sleep 0.1
  done
  echo "FAIL: Xvfb on :$n does not answer"
  exit 1
}
