#!/usr/bin/env bash
# haze live --multicast on loopback: the npm `sacn` package sends to the groups 239.255.0.1 and
# 239.255.0.2 (universes 1 and 2) through 127.0.0.1; haze joins them and decodes the levels.
# Skips (exit 0, says SKIP) only when this machine cannot do multicast on loopback at all.
# usage: bash live_multicast.sh HAZE_BINARY REPO_ROOT
set -u
HAZE=$1
ROOT=$2
NODE_DIR="$ROOT/tests/node"
TMP=$(mktemp -d)
HAZE_PID=""
cleanup() {
  [ -n "$HAZE_PID" ] && kill "$HAZE_PID" 2>/dev/null
  rm -rf "$TMP"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; echo "--- haze stderr:"; cat "$TMP/err" 2>/dev/null; exit 1; }

command -v node >/dev/null || fail "node is not installed"
"$HAZE" live "$ROOT/tests/data/live/live.haze.json" --sacn --sacn-port 0 --multicast \
  --state-json "$TMP/state.json" 2>"$TMP/err" &
HAZE_PID=$!
PORT=""
for _ in $(seq 600); do
  PORT=$(sed -n 's/^haze live: sACN on 127\.0\.0\.1:\([0-9][0-9]*\)$/\1/p' "$TMP/err")
  [ -n "$PORT" ] && break
  kill -0 "$HAZE_PID" 2>/dev/null || fail "haze live exited before listening"
  sleep 0.1
done
[ -n "$PORT" ] || fail "haze live did not report its sACN port"
if ! grep -q "joined 239.255.0.1 (sACN universe 1)" "$TMP/err"; then
  grep -q "cannot join" "$TMP/err" && { echo "SKIP: no multicast on loopback here"; exit 0; }
  fail "haze did not join the group of universe 1"
fi

STREAMS='[{"universe":1,"cid":5,"name":"mc","slots":{"11":153}},
          {"universe":2,"cid":5,"name":"mc","slots":{"1":0,"2":255,"3":0}}]'
if ! (cd "$NODE_DIR" && node send_sacn.js "$PORT" 20 "$STREAMS" 0 multicast >"$TMP/sent" 2>"$TMP/send_err"); then
  if grep -qE "EADDRNOTAVAIL|ENETUNREACH|EINVAL" "$TMP/send_err"; then
    echo "SKIP: cannot send multicast through loopback here: $(cat "$TMP/send_err")"
    exit 0
  fi
  cat "$TMP/send_err"
  fail "send_sacn.js failed"
fi
kill -INT "$HAZE_PID"
wait "$HAZE_PID"
STATUS=$?
HAZE_PID=""
[ "$STATUS" -eq 0 ] || fail "haze live exited with $STATUS"
grep -q 'source sACN .* "mc" universe 2 priority 100' "$TMP/err" || fail "no multicast source on universe 2"

# Fixture 2 (address 11 of universe 1): dimmer 153/255 = 0.6. Par on universe 2: pure green.
node -e '
const s = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
const near = (a, b) => Math.abs(a - b) < 1e-3;
const ok = near(s["2"].intensity, 0.6) && near(s["3"].intensity, 1) &&
           [0, 1, 0].every((x, i) => near(s["3"].color[i], x));
if (!ok) { console.error(JSON.stringify({2: s["2"], 3: s["3"]})); process.exit(1); }
' "$TMP/state.json" || fail "fixture states differ from what was sent"
echo "PASS live_multicast"
