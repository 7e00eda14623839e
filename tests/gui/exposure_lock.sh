#!/usr/bin/env bash
# The exposure lock under Xvfb with real X keys (docs/gui.md, "Air"; docs/rendering.md,
# "Exposure"): on the demo with one more cue, 4.2, every fixture at 0 in a 6 s fade
# (long enough that a loaded machine drawing a frame a second still samples it several times), GO from cue 4
# (the finale, everything up) fades to black. Unlocked, auto exposure follows the meter, so the EV on screen
# changes during the fade (it brightens what is falling). Locked (E, View > Lock exposure), the
# EV held is the one on screen when E was pressed, for every frame of the fade, and the
# viewport's mean level falls frame after frame. What each frame drew comes from the probe
# (HAZE_GUI_PROBE_FILE): the EV shown and metered, the viewport's mean display level, the clock.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

demo_copy "$tmp/fade.haze.json" <<'PY'
cues = show["cue_lists"][0]["cues"]
at = next(i for i, c in enumerate(cues) if c["number"] == "4")
cues.insert(at + 1, {"number": "4.2", "label": "Black", "fade": 6.0,
                     "values": {str(f["id"]): {"intensity": 0.0} for f in show["fixtures"]}})
PY
export HAZE_GUI_PROBE_FILE="$tmp/probe.json"
probe() {  # probe PYTHON-EXPRESSION: its value on the probe's JSON (p)
  python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$HAZE_GUI_PROBE_FILE" "$1"
}
# record SECONDS FILE: one line per frame for SECONDS of the GUI's clock: clock, EV shown, mean level.
record() {
  local until; until=$(probe "p['clock_s'] + $1")
  : >"$2"
  while :; do
    settle 1
    probe "'%.4f %.5f %.6f' % (p['clock_s'], p['exposure']['ev'], p['view_mean'])" >>"$2"
    [ "$(probe "int(p['clock_s'] >= $until)")" = 1 ] && break
  done
}
# Until the view has settled at cue 4: the EV on screen within 0.01 of where it goes (auto
# glides with a 0.3 s time constant) and the picture unchanged between two frames.
steady() {
  local last="" now
  for _ in $(seq 200); do
    settle 2
    now=$(probe "'%.2f %.3f' % (p['exposure']['ev'], p['view_mean'])")
    [ "$now" = "$last" ] && return 0
    last=$now
  done
  return 1
}

# A draft budget of 0 keeps the frames at the full size: a smaller draft would change the mean.
start_haze "haze - fade" "$tmp/fade.haze.json" --width 640 --height 360 --quality draft --draft-budget 0 --cue 4
check "the view settles at cue 4" steady
check "auto at start (locked: $(probe "p['exposure']['locked']"))" '[ "$(probe "p[\"exposure\"][\"locked\"]")" = False ]'

# Unlocked: GO, the 6 s fade to black, and 1 s after it.
xdotool key space   # no settle: the frames of the fade are what is recorded
record 7 "$tmp/auto.txt"
python3 - "$tmp/auto.txt" <<'PY' && pass=$((pass + 1)) || fail=$((fail + 1))
import sys
rows = [tuple(map(float, l.split())) for l in open(sys.argv[1]) if l.strip()]
evs = [r[1] for r in rows]
# The meter raises the EV as the stage darkens (to its 4 EV ceiling in a blackout); 1 EV is far
# above a still view's noise (the EV is unchanged to 0.01 when settled).
ok = len(rows) >= 3 and max(evs) - min(evs) > 1.0
print(("ok" if ok else "FAIL") + f": unlocked, the EV follows the fade: {len(rows)} frames, EV {min(evs):.2f}..{max(evs):.2f}")
sys.exit(0 if ok else 1)
PY

# Back to cue 4 in full (BACK).
tap BackSpace
check "the view settles at cue 4 again" steady
tap e
check "E locks the exposure (locked: $(probe "p['exposure']['locked']"))" '[ "$(probe "p[\"exposure\"][\"locked\"]")" = True ]'
held=$(probe "p['exposure']['ev']")
xdotool key space
record 7 "$tmp/locked.txt"
python3 - "$tmp/locked.txt" "$held" <<'PY' && pass=$((pass + 1)) || fail=$((fail + 1))
import sys
rows = [tuple(map(float, l.split())) for l in open(sys.argv[1]) if l.strip()]
held = float(sys.argv[2])
evs = [r[1] for r in rows]
means = [r[2] for r in rows]
# Draft frames of one still stage differ by jitter noise well under one 8-bit level of the mean
# (1/255 = 0.0039); a rise of more than half a level is the meter brightening the fade.
rises = [(i, means[i - 1], means[i]) for i in range(1, len(means)) if means[i] > means[i - 1] + 0.002]
ok = (len(rows) >= 3 and max(abs(e - held) for e in evs) < 1e-3 and not rises
      and means[-1] < 0.5 * means[0])
print(("ok" if ok else "FAIL") + f": locked at EV {held:.2f}: {len(rows)} frames, EV {min(evs):.3f}..{max(evs):.3f}, "
      f"mean {means[0]:.4f} -> {means[-1]:.4f}, rises: {rises or 'none'}")
sys.exit(0 if ok else 1)
PY
[ -n "${HAZE_GUI_SHOTS:-}" ] && cp "$tmp/auto.txt" "$tmp/locked.txt" "$HAZE_GUI_SHOTS/"
finish
