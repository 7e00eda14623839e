#!/usr/bin/env bash
# The program built without the GUI, under ASan and UBSan, through every command on the demo:
# validate, state, render (llvmpipe), fixture info, live (one Art-Net frame sent from Python,
# decoded and rendered), and `haze open` saying plainly that this build has no GUI. Mesa's own
# allocations are not ours to account for, so leak checking is off here (the unit suites keep it).
set -euo pipefail
haze=$1
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$haze" validate "$root/examples/demo/demo.haze.json"
"$haze" render "$root/examples/demo/demo.haze.json" --cue 2 --width 160 --height 90 --quality draft -o "$out/cue2.pfm"
[ -s "$out/cue2.pfm" ] || { echo "FAIL: no image from the headless build"; exit 1; }
"$haze" state "$root/examples/demo/demo.haze.json" --cue 2 --at 1.5 --json > "$out/state.json"
grep -q '"intensity"' "$out/state.json" || { echo "FAIL: haze state gave no fixture state"; exit 1; }
"$haze" fixture info "$root/examples/demo/profiles/profile-spot.json" --json > "$out/info.json"
"$haze" live "$root/examples/demo/demo.haze.json" --artnet --artnet-port 0 --duration 3 --no-preview \
  --state-json "$out/live.json" --render "$out/live.pfm" --width 96 --height 54 --quality draft 2> "$out/live.txt" &
live=$!
port=""
for _ in $(seq 100); do
  port=$(sed -n 's/^haze live: Art-Net on 127\.0\.0\.1:\([0-9]*\) .*/\1/p' "$out/live.txt")
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { echo "FAIL: haze live did not listen: $(cat "$out/live.txt")"; exit 1; }
# ArtDmx (Art-Net 4): ID, OpCode 0x5000 little-endian, protocol 14, sequence, physical,
# Port-Address 0 (haze universe 1), length 512 big-endian; slot 1 (fixture 101's dimmer) full.
python3 -c "
import socket, struct, sys
dmx = bytes([255]) + bytes(511)
packet = b'Art-Net\\0' + struct.pack('<H', 0x5000) + struct.pack('>H', 14) + bytes([1, 0]) + struct.pack('<H', 0) + struct.pack('>H', 512) + dmx
socket.socket(socket.AF_INET, socket.SOCK_DGRAM).sendto(packet, ('127.0.0.1', int(sys.argv[1])))
" "$port"
wait $live
grep -q ' 1 good' "$out/live.txt" || { echo "FAIL: haze live did not decode the frame: $(cat "$out/live.txt")"; exit 1; }
python3 -c "import json, sys; sys.exit(0 if json.load(open(sys.argv[1]))['101']['intensity'] > 0.99 else 1)" "$out/live.json" \
  || { echo "FAIL: fixture 101 is not at full after the frame: $(head -c 300 "$out/live.json")"; exit 1; }
[ -s "$out/live.pfm" ] || { echo "FAIL: haze live rendered nothing"; exit 1; }
if "$haze" open "$root/examples/demo/demo.haze.json" 2> "$out/err.txt"; then
  echo "FAIL: haze open succeeded in a build without the GUI"; exit 1
fi
grep -q 'without the GUI' "$out/err.txt" || { echo "FAIL: haze open did not say the GUI is missing: $(cat "$out/err.txt")"; exit 1; }
echo "headless build: validate, state, render, fixture info, live and the no-GUI message all behave"
