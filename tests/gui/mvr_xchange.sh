#!/usr/bin/env bash
# File > MVR-xchange under Xvfb with real X input events: on a saved copy of the demo, Start makes
# haze a station on 127.0.0.1 (no Avahi daemon needed: the window says mDNS is unavailable); a
# station written in the test (mvr_xchange_peer.py) joins announcing one MVR; the window lists it,
# and its Request button fetches the file, imported beside the open show byte for byte (its
# SHOW_source.mvr); Commit sends the saved show to the station; Stop sends MVR_LEAVE; Ctrl+Q
# exits cleanly. 800x450, draft quality.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

python3 "$root/tests/show_copy.py" "$root/examples/demo/demo.haze.json" "$tmp/rig.haze.json"
mkdir "$tmp/peer"
python3 "$root/tests/show_copy.py" "$root/examples/demo/demo.haze.json" "$tmp/peer/p.haze.json"
"$haze" export-mvr "$tmp/peer/p.haze.json" -o "$tmp/peer.mvr" >/dev/null 2>&1 || { echo "FAIL: export-mvr"; exit 1; }
start_haze "haze - rig.haze.json" "$tmp/rig.haze.json" --width 800 --height 450 --quality draft
click 18 9                 # File
click 50 118               # MVR-xchange...
click 89 143               # Start (group Default, bind 127.0.0.1)
wait_until 60 'grep -q "MVR-xchange on 127.0.0.1:" "$tmp/haze.out"'
port=$(sed -n 's/^haze live: MVR-xchange on 127.0.0.1:\([0-9]*\) .*/\1/p' "$tmp/haze.out")
check "Start made a station (port $port)" '[ -n "$port" ]'
python3 "$root/tests/gui/mvr_xchange_peer.py" "$port" "$tmp/peer.mvr" & GUI_KILL=$!
wait_until 60 'grep -q "MVR_JOIN from \"gui test station\"" "$tmp/haze.out"'
check "the station joined" 'grep -q "MVR_JOIN from \"gui test station\"" "$tmp/haze.out"'
click 446 136              # Request, on the station's row
wait_until 120 'grep -q "imported file" "$tmp/haze.out"'
check "Request imported the station's file ($(grep -o 'imported file.*' "$tmp/haze.out"))" \
  'grep -q "imported file" "$tmp/haze.out"'
check "beside the open show, byte for byte" 'cmp -s "$tmp/peer.mvr" "$tmp/fromguitest_source.mvr"'
check "the open show is untouched (title '$(title)')" '[[ "$(title)" == "haze - rig.haze.json" ]]'
click 310 97               # Commit
wait_until 60 'grep -q "MVR_COMMIT sent to 1 station" "$tmp/haze.out"'
check "Commit sent the saved show to the station" 'grep -q "MVR_COMMIT sent to 1 station" "$tmp/haze.out"'
click 361 97               # Stop
wait_until 60 'grep -q "MVR_LEAVE sent to 1 station" "$tmp/haze.out"'
check "Stop left the group" 'grep -q "MVR_LEAVE sent to 1 station" "$tmp/haze.out"'
tap ctrl+q
sleep 1
wait_exit
check "Ctrl+Q exits cleanly (status $rc)" '[ "$rc" = 0 ]'
finish
