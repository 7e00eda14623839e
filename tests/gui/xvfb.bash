# Sourced by GUI tests: starts Xvfb on a display number of its own choosing (-displayfd, so GUI
# tests that run in parallel never share a display and drive each other's windows) and stops
# it on exit.
start_xvfb() {
  command -v Xvfb >/dev/null || { echo "FAIL: Xvfb is not installed (make deps installs xvfb)"; exit 1; }
  local dfile
  dfile=$(mktemp)
  Xvfb -displayfd 9 -screen 0 1280x800x24 -nolisten tcp 9>"$dfile" >/dev/null 2>&1 &
  XVFB_PID=$!
  trap 'kill $XVFB_PID 2>/dev/null' EXIT
  for _ in $(seq 100); do
    [ -s "$dfile" ] && break
    kill -0 $XVFB_PID 2>/dev/null || break
    sleep 0.1
  done
  local n
  n=$(tr -dc '0-9' <"$dfile")
  rm -f "$dfile"
  if [ -z "$n" ] || ! kill -0 $XVFB_PID 2>/dev/null; then
    echo "FAIL: could not start Xvfb"
    exit 1
  fi
  export DISPLAY=:$n
}
