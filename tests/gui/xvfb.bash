# Sourced by GUI tests: starts Xvfb on a free display number and stops it on exit.
start_xvfb() {
  command -v Xvfb >/dev/null || { echo "FAIL: Xvfb is not installed (make deps installs xvfb)"; exit 1; }
  for n in $(seq 90 140); do
    [ -e /tmp/.X$n-lock ] && continue
    Xvfb :$n -screen 0 1280x800x24 -nolisten tcp >/dev/null 2>&1 &
    XVFB_PID=$!
    for _ in $(seq 50); do
      [ -e /tmp/.X11-unix/X$n ] && break
      sleep 0.1
    done
    if kill -0 $XVFB_PID 2>/dev/null && [ -e /tmp/.X11-unix/X$n ]; then
      export DISPLAY=:$n
      trap 'kill $XVFB_PID 2>/dev/null' EXIT
      return 0
    fi
  done
  echo "FAIL: could not start Xvfb"
  exit 1
}
