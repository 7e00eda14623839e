#!/usr/bin/env bash
# haze live --mvr-xchange against a station written in the test from the specification's text
# (mvr_xchange_station.py, Python: framing and JSON by hand) on loopback: JOIN, REQUEST (the file
# as a file packet), a save of the show sent as COMMIT, a COMMIT from the station requested and
# imported byte for byte (sha256), LEAVE, and hostile packets each logged in one line with the
# connection closed and nothing written. Then two haze processes: a save in one is imported by
# the other. No Avahi daemon is needed: haze says in one line that mDNS is unavailable.
# usage: bash mvr_xchange.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
export XDG_CONFIG_HOME="$TMP/config"  # the station uuid haze keeps between runs
mkdir -p "$TMP/a" "$TMP/in" "$TMP/in2"
cp -r "$ROOT/examples/demo/." "$TMP/a/"

live_start MVR-xchange "$TMP/a/demo.haze.json" --artnet-port 0 --sacn-port 0 --mvr-xchange --mvr-xchange-port 0 \
  --accept-commits "$TMP/in"
grep -q "MVR-xchange: .*mDNS" "$HAZE_ERR" || fail "haze said nothing about mDNS"
python3 "$ROOT/tests/cli/mvr_xchange_station.py" "$PORT" "$TMP/a/demo.haze.json" "$HAZE_ERR" "$TMP/in" >"$TMP/station.out" ||
  { cat "$TMP/station.out"; fail "the test station's exchange with haze failed"; }
grep '^ok:' "$TMP/station.out"
imported=$(sed -n 's/^SHOW //p' "$TMP/station.out")
"$HAZE" validate "$imported" || fail "the imported show $imported does not validate"
# Every refusal is one line.
for words in "not an MVR-xchange packet" "over the limit of 1 MiB" "truncated packet"; do
  [ "$(grep -c "$words" "$HAZE_ERR")" -ge 1 ] || fail "no line for: $words"
done
grep "MVR-xchange" "$HAZE_ERR" | grep -qv "^haze live: " && fail "a MVR-xchange message spans lines"

# Two haze stations: B dials A directly; a save of A's show reaches B's --accept-commits folder.
A_ERR=$HAZE_ERR
A_PID=$HAZE_PID
mkdir -p "$TMP/b"
cp -r "$ROOT/examples/demo/." "$TMP/b/"
XDG_CONFIG_HOME="$TMP/configB" live_start MVR-xchange "$TMP/b/demo.haze.json" --artnet-port 0 --sacn-port 0 \
  --mvr-xchange --mvr-xchange-peer "127.0.0.1:$(sed -n 's/^haze live: MVR-xchange on [0-9.]*:\([0-9]*\) .*/\1/p' "$A_ERR")" \
  --accept-commits "$TMP/in2"
B_ERR=$HAZE_ERR
for _ in $(seq 300); do grep -q "joined \"haze" "$B_ERR" && break; sleep 0.1; done
grep -q "joined \"haze" "$B_ERR" || fail "haze B did not join haze A"
printf '\n' >>"$TMP/a/demo.haze.json"
for _ in $(seq 300); do grep -q "imported file" "$B_ERR" && break; sleep 0.1; done
grep -q "imported file" "$B_ERR" || fail "haze B did not import haze A's commit"
ls "$TMP/in2"/*.haze.json >/dev/null || fail "nothing in B's --accept-commits folder"
live_stop_ok
grep -q "MVR_LEAVE sent to 1 station" "$B_ERR" || fail "haze B did not leave"
HAZE_PID=$A_PID
HAZE_ERR=$A_ERR
for _ in $(seq 100); do grep -q "MVR_LEAVE from" "$A_ERR" && break; sleep 0.1; done
grep -q "MVR_LEAVE from" "$A_ERR" || fail "haze A did not see B leave"
live_stop_ok
echo "ok: two haze stations exchanged a commit and left"
