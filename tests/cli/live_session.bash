# What every `haze live` test does, in one copy: start haze, find the port it picked (port 0, so
# parallel tests never collide), run a sender from tests/node until it is ready, stop haze, and
# check the state it wrote. Sourced, not run (ctest registers only *.sh):
#   source "$(dirname "$0")/live_session.bash" "$@"      # the test's HAZE_BINARY REPO_ROOT
# It sets HAZE, ROOT (absolute), NODE_DIR, TMP (removed on exit, with haze and the sender
# stopped), and defines fail, need_node and the live_* functions below.
#
# Every haze run and every sender writes files of its own (err.1, err.2, sent.1, ...). A
# background job opens its redirections only once it runs, so a file that an earlier run wrote
# can be read for a moment before it is truncated: reused, it once gave a test the port of a
# run that had already ended, and the sender's datagrams went nowhere.
set -u
HAZE=$1
ROOT=$(cd "$2" && pwd)
NODE_DIR="$ROOT/tests/node"
TMP=$(mktemp -d)
HAZE_PID=""
HAZE_ERR=""
SEND_PID=""
SEND_OUT=""
SEND_ERR=""
STATUS=""
PORT=""
_live_files=0

_live_cleanup() {
  [ -n "$SEND_PID" ] && kill "$SEND_PID" 2>/dev/null
  [ -n "$HAZE_PID" ] && kill "$HAZE_PID" 2>/dev/null
  rm -rf "$TMP"
}
trap _live_cleanup EXIT

# fail MESSAGE: prints it and the stderr of the last haze run, and ends the test.
fail() {
  echo "FAIL: $*"
  if [ -n "$HAZE_ERR" ] && [ -f "$HAZE_ERR" ]; then
    echo "--- haze stderr:"
    cat "$HAZE_ERR"
  fi
  exit 1
}

need_node() { command -v node >/dev/null || fail "node is not installed"; }

_live_file() {  # _live_file VAR STEM: VAR names a new, empty file in TMP (not a subshell's count)
  _live_files=$((_live_files + 1))
  printf -v "$1" '%s' "$TMP/$2.$_live_files"
  : >"${!1}"
}

# live_run SHOW OPTION...: haze live in the foreground, stderr in HAZE_ERR; returns its status.
live_run() {
  _live_file HAZE_ERR err
  "$HAZE" live "$@" 2>>"$HAZE_ERR"
}

# live_port LISTENER: the port haze printed for LISTENER (Art-Net, sACN or OSC), or nothing.
live_port() {
  sed -n "s/^haze live: $1 on [0-9.]*:\([0-9][0-9]*\)\( .*\)\{0,1\}\$/\1/p" "$HAZE_ERR"
}

# live_start LISTENER SHOW OPTION...: haze live in the background (HAZE_PID; stderr in HAZE_ERR);
# returns once haze has printed LISTENER's port, which is then in PORT. haze prints OSC's port
# after the others, so waiting for OSC waits for all three.
live_start() {
  local listener=$1
  shift
  _live_file HAZE_ERR err
  "$HAZE" live "$@" 2>>"$HAZE_ERR" &
  HAZE_PID=$!
  PORT=""
  for _ in $(seq 600); do
    PORT=$(live_port "$listener")
    [ -n "$PORT" ] && return 0
    kill -0 "$HAZE_PID" 2>/dev/null || fail "haze live exited before listening"
    sleep 0.1
  done
  fail "haze live did not report its $listener port within 60 s"
}

# live_sender SCRIPT ARG...: node tests/node/SCRIPT in the background (SEND_PID, stdout in
# SEND_OUT, stderr in SEND_ERR).
live_sender() {
  local script=$1
  shift
  need_node
  _live_file SEND_OUT sent
  _live_file SEND_ERR send_err
  node "$NODE_DIR/$script" "$@" >>"$SEND_OUT" 2>>"$SEND_ERR" &
  SEND_PID=$!
}

# live_send_ready SCRIPT ARG...: live_sender, then wait until the script prints "ready" (it
# goes on sending until it ends or live_stop stops it).
live_send_ready() {
  live_sender "$@"
  for _ in $(seq 600); do
    grep -q ready "$SEND_OUT" && return 0
    kill -0 "$SEND_PID" 2>/dev/null || fail "$1 exited before it was ready: $(cat "$SEND_ERR")"
    sleep 0.1
  done
  fail "$1 was not ready within 60 s"
}

# live_send_all SCRIPT ARG...: live_sender, then wait for the script to end; it must succeed.
live_send_all() {
  live_sender "$@"
  wait "$SEND_PID" || fail "$1 failed: $(cat "$SEND_ERR")"
  SEND_PID=""
}

_live_stop_sender() {
  [ -n "$SEND_PID" ] || return 0
  kill "$SEND_PID" 2>/dev/null
  wait "$SEND_PID" 2>/dev/null
  SEND_PID=""
}

# live_stop: SIGINT to haze (the Ctrl-C path), wait for it, then stop the sender; haze's exit
# status in STATUS. live_stop_ok: the same, and the status must be 0.
live_stop() {
  kill -INT "$HAZE_PID"
  wait "$HAZE_PID"
  STATUS=$?
  HAZE_PID=""
  _live_stop_sender
}
live_stop_ok() {
  live_stop
  [ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"
}

# live_wait_ok: wait for haze to end by itself (--duration); its status must be 0.
live_wait_ok() {
  wait "$HAZE_PID"
  STATUS=$?
  HAZE_PID=""
  _live_stop_sender
  [ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"
}

# expect_state STATE.json WANT_JSON [TOLERANCE] [WHAT]: tests/node/expect_state.js.
# osc_send WANT ARGS...: oscsend ARGS to the haze started last, then waits (up to 15 s) for haze
# to log a line matching WANT, so commands reach the stage in the order sent.
osc_send() {
  local want=$1
  shift
  oscsend 127.0.0.1 "$PORT" "$@" || fail "oscsend $* failed"
  for _ in $(seq 300); do
    grep -q "$want" "$HAZE_ERR" && return 0
    sleep 0.05
  done
  fail "haze did not log '$want' after oscsend $*"
}

expect_state() {
  need_node
  node "$NODE_DIR/expect_state.js" "$@"
}
