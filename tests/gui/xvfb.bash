# Sourced by GUI tests: start_xvfb N starts Xvfb on display :N and stops it on exit. Each GUI
# test has a display number of its own (input_events 91, import_mvr 92, screenshot_smoke 93,
# walkthrough 94), so tests that run in parallel never share a display or drive each other's
# windows.
# -noreset: an X server resets itself whenever its last client disconnects, and refuses
# connections while it does. The tests' xdotool calls are short-lived clients, so without it a
# haze starting while an xdotool call closed failed with "X11: Failed to open display" (the GUI
# tests' intermittent failure: it came from the server's reset, not from haze).
start_xvfb() {
  local n=$1
  command -v Xvfb >/dev/null || { echo "FAIL: Xvfb is not installed (make deps installs xvfb)"; exit 1; }
  if [ -e "/tmp/.X$n-lock" ] && kill -0 "$(tr -dc '0-9' < "/tmp/.X$n-lock")" 2>/dev/null; then
    echo "FAIL: display :$n is taken by a running X server (pid $(tr -dc '0-9' < "/tmp/.X$n-lock")); stop it to run this test"
    exit 1
  fi
  Xvfb ":$n" -screen 0 1280x800x24 -nolisten tcp -noreset >/dev/null 2>&1 &
  XVFB_PID=$!
  trap 'kill $XVFB_PID 2>/dev/null' EXIT
  export DISPLAY=":$n"
  # Ready when a client can connect (xdotool asks the server for the screen size).
  for _ in $(seq 100); do
    xdotool getdisplaygeometry >/dev/null 2>&1 && return 0
    kill -0 $XVFB_PID 2>/dev/null || break
    sleep 0.1
  done
  echo "FAIL: could not start Xvfb on :$n"
  exit 1
}
