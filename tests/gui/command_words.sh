#!/usr/bin/env bash
# The console's attribute and time words typed into the GUI's command line with real X keys
# (docs/gui-commands.md, "Attributes and times on the command line"), on a copy of the demo at
# cue 5 (the bows: the spots 101-104 dark): "101 thru 104 @ 70", "color #ff8800", "gobo Dots",
# "record cue 9", "cue 9 time 5", 'label cue 9 "Verse"', "clear", Ctrl+S. The saved show must
# hold cue 9 after cue 5 with the four spots at 70 % in orange (the linear filter [1, 0.246, 0])
# with the gobo Dots, a 5 s fade and the label Verse. Then "cue 9" goes there with its times: the
# spots' intensity on stage (the probe, HAZE_GUI_PROBE_FILE) rises linearly from 0 to 0.7 over
# 5 s, about half-way (0.35) at 2.5 s. The GUI's clock stamps each probed frame; when GO
# happened is known to within the frames around the Enter key, and that window (plus the
# probe's 5-digit rounding) is the tolerance, stated in what the check prints.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

demo_copy "$tmp/words.haze.json" </dev/null
export HAZE_GUI_PROBE_FILE="$tmp/probe.json"
probe() {  # probe PYTHON-EXPRESSION: its value on the probe's JSON (p)
  python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$HAZE_GUI_PROBE_FILE" "$1"
}

start_haze "haze - words" "$tmp/words.haze.json" --width 640 --height 360 --quality draft --cue 5
line() { type_text "$1"; hold Return; }
tap l
line "101 thru 104 @ 70"
line "color #ff8800"
line "gobo Dots"
line "record cue 9"
line "cue 9 time 5"
line 'label cue 9 "Verse"'
line "clear"
hold Escape
tap ctrl+s
check "Ctrl+S saved the show (title $(title))" 'wait_until 60 "[[ \"\$(title)\" != *\"*\"* ]]"'

python3 - "$tmp/words.haze.json" <<'PY' && pass=$((pass + 1)) || fail=$((fail + 1))
import json, sys
show = json.load(open(sys.argv[1]))
cues = show["cue_lists"][0]["cues"]
numbers = [c["number"] for c in cues]
nine = next((c for c in cues if c["number"] == "9"), {})
values = nine.get("values", {})
spots = [values.get(str(i), {}) for i in (101, 102, 103, 104)]
ok = (numbers[-2:] == ["5", "9"] and sorted(values, key=int) == ["101", "102", "103", "104"]
      and all(abs(v.get("intensity", -1) - 0.7) < 1e-6 for v in spots)
      and all(v.get("color") and max(abs(a - b) for a, b in zip(v["color"], [1, 0.246, 0])) < 2e-3 for v in spots)
      and all(v.get("gobo") == "Dots" for v in spots)
      and nine.get("fade") == 5 and nine.get("label") == "Verse")
print(("ok" if ok else "FAIL") + f": saved cues {numbers}; cue 9: fade {nine.get('fade')}, label {nine.get('label')!r}, values {values}")
sys.exit(0 if ok else 1)
PY

check "cleared: spot 101 dark at cue 5 ($(probe "p['intensity']['101']"))" '[ "$(probe "p[\"intensity\"][\"101\"] == 0")" = True ]'
# "cue 9": GO happens on the first frame that sees the Enter key, after the frame stamped $before.
tap l
type_text "cue 9"
before=$(probe "p['clock_s']")
xdotool keydown Return
: >"$tmp/fade.txt"
until_s=$(python3 -c "print($before + 6.0)")
while :; do
  settle 1
  probe "'%.4f %.5f' % (p['clock_s'], p['intensity']['101'])" >>"$tmp/fade.txt"
  [ "$(probe "int(p['clock_s'] >= $until_s)")" = 1 ] && break
  [ "$(wc -l <"$tmp/fade.txt")" = 3 ] && xdotool keyup Return
done
xdotool keyup Return
python3 - "$tmp/fade.txt" "$before" <<'PY' && pass=$((pass + 1)) || fail=$((fail + 1))
import sys
rows = [tuple(map(float, l.split())) for l in open(sys.argv[1]) if l.strip()]
before = float(sys.argv[2])
level, fade = 0.7, 5.0
# GO came after the frame stamped `before` and before the first frame that shows any light.
first_lit = next((t for t, i in rows if i > 0), None)
if first_lit is None:
    print(f"FAIL: spot 101 never came up in {len(rows)} frames"); sys.exit(1)
lo_go, hi_go = before, first_lit
def bounds(t):  # what a linear 0 -> 0.7 fade over 5 s allows at clock t, GO in [lo_go, hi_go]
    f = lambda go: level * min(max((t - go) / fade, 0.0), 1.0)
    return f(hi_go) - 1e-4, f(lo_go) + 1e-4
bad = [(t, i) for t, i in rows if not bounds(t)[0] <= i <= bounds(t)[1]]
mid = min(rows, key=lambda r: abs(r[0] - (lo_go + hi_go) / 2 - fade / 2))
share = mid[1] / level
window = hi_go - lo_go
gap = max(b[0] - a[0] for a, b in zip(rows, rows[1:]))
# The frame nearest 2.5 s after the middle of GO's window is at most half a frame gap from it,
# and GO at most half the window from that middle: the share of the way is 0.5 within this.
allowed = (window + gap) / (2 * fade) + 0.01
ok = not bad and rows[-1][1] > level - 1e-4 and abs(share - 0.5) <= allowed
print(("ok" if ok else "FAIL") + f": {len(rows)} frames; GO between clock {lo_go:.3f} and {hi_go:.3f} s; {mid[0] - (lo_go + hi_go) / 2:.2f} s after its middle the spot is at {mid[1]:.3f} ({100 * share:.0f} % of the way, "
      f"allowed 50 +- {100 * allowed:.0f} % from a window of {window:.3f} s and frames {gap:.3f} s apart); frames off the line: {bad or 'none'}; at the end {rows[-1][1]:.3f}")
sys.exit(0 if ok else 1)
PY
finish
