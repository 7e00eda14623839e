#!/usr/bin/env bash
# haze live --mtc: MIDI Time Code through the ALSA sequencer fires the cues of
# tests/data/live/cues.haze.json (cue 1 at 00:00:01:00, 2 at 02:00, fades 0). The sender is
# alsa-utils' amidi writing raw MIDI bytes, hand-encoded from the MTC spec, into a snd-virmidi
# port (whose sequencer client haze connects from): a Full Frame locate to 00:00:00:00, quarter
# frames spelling 00:00:00:23 (read two frames on: 00:00:01:00, cue 1 fires), 00:00:01:23
# (cue 2 fires), then a Full Frame jump back to 00:00:01:12 (chases to cue 1).
# Where the machine has no sequencer (/dev/snd/seq absent) it checks that `haze live --mtc`
# refuses in one line naming it, and exits 77 (skipped), as without a snd-virmidi port.
# usage: bash live_mtc.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"
SHOW="$ROOT/tests/data/live/cues.haze.json"

if [ ! -e /dev/snd/seq ]; then
  live_run "$SHOW" --artnet --artnet-port 0 --mtc --duration 1 && fail "--mtc without a sequencer was accepted"
  [ "$(grep -c -- '--mtc' "$HAZE_ERR")" -eq 1 ] && grep -q -- '--mtc: ALSA sequencer: .*/dev/snd/seq' "$HAZE_ERR" ||
    fail "no one-line error naming /dev/snd/seq"
  echo "SKIP live_mtc: no ALSA sequencer (/dev/snd/seq is absent; modprobe snd-seq snd-virmidi to run it)"
  exit 77
fi
command -v amidi >/dev/null && command -v aconnect >/dev/null || {
  echo "SKIP live_mtc: amidi and aconnect (alsa-utils) are not installed"
  exit 77
}
read -r device name < <(amidi -l | awk '/Virtual Raw MIDI/ { d = $2; $1 = ""; $2 = ""; sub(/^ +/, ""); print d, $0; exit }')
if [ -z "${device:-}" ]; then
  echo "SKIP live_mtc: no snd-virmidi port (modprobe snd-virmidi to run it)"
  exit 77
fi
client=$(aconnect -l | sed -n "s/^client \([0-9]*\): '$name'.*/\1/p" | head -1)
[ -n "$client" ] || fail "no sequencer client for $name"

live_start MTC "$SHOW" --artnet --artnet-port 0 --mtc-from "$client:0" --movement instant --state-json "$TMP/state.json"
# Full Frame: F0 7F 7F 01 01 hr mn sc fr F7, hr = 25 fps (1) << 5 | hours.
amidi -p "$device" -S 'F0 7F 7F 01 01 20 00 00 00 F7' || fail "amidi failed"
# Quarter frames F1 0n, pieces 0..7: frames low/high, seconds low/high, minutes, hours, and
# piece 7 = hours bit 4 | rate 1 << 1 = 2. 00:00:00:23: frames 23 = 0x17.
amidi -p "$device" -S 'F1 07 F1 11 F1 20 F1 30 F1 40 F1 50 F1 60 F1 72' || fail "amidi failed"
amidi -p "$device" -S 'F1 07 F1 11 F1 21 F1 30 F1 40 F1 50 F1 60 F1 72' || fail "amidi failed"
amidi -p "$device" -S 'F0 7F 7F 01 01 20 00 01 0C F7' || fail "amidi failed"
for _ in $(seq 100); do
  grep -q 'MTC 00:00:01:12' "$HAZE_ERR" && break
  sleep 0.1
done
live_stop_ok
grep '^haze live: MTC [0-9]' "$HAZE_ERR" >"$TMP/fired"
cat >"$TMP/want" <<'WANT'
haze live: MTC 00:00:01:00: fired cue 1
haze live: MTC 00:00:02:00: fired cue 2
haze live: MTC 00:00:01:12: chased to cue 1
WANT
diff "$TMP/want" "$TMP/fired" || fail "cues did not fire at their MIDI timecodes"
grep -q 'haze live: MTC: 16 quarter frames, 2 full frames, 0 broken cycles, 0 bad times' "$HAZE_ERR" ||
  fail "the MTC messages were not all counted"
expect_state "$TMP/state.json" '{"1": {"intensity": 0.2}}' || fail "the stage is not cue 1's after the chase"
echo "PASS live_mtc"
