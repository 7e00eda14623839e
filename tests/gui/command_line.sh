#!/usr/bin/env bash
# The console command line driven by real X key events (docs/gui.md, "Console commands"): on a
# copy of tests/data/shows/console.haze.json, L focuses the field; "group sp" + Tab completes
# to the group "Spots SR" (without the Tab the line is an error and cue 7 would be empty);
# "@ 60" Enter, "record cue 7" Enter; "1 @ 20" Enter, "record cue 8" Enter; a typo line
# changes nothing; Esc leaves the field, Ctrl+Z undoes "record cue 8" as one step, Ctrl+S saves.
# The saved show must hold cue 7 with fixtures 7-12 at 60 % (cue 5 has 7 at 50 %) and no cue 8. 640x360, draft quality.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

mkdir -p "$tmp/show"
cp "$root/tests/data/shows/console.haze.json" "$tmp/show/"
cp -r "$root/tests/data/shows/profiles" "$tmp/show/"
start_haze "haze - console" "$tmp/show/console.haze.json" --width 640 --height 360 --quality draft

line() { type_text "$1"; hold Return; }
tap l
type_text "group sp"
hold Tab
line "@ 60"
line "record cue 7"
line "1 @ 20"
line "record cue 8"
line "1 thru @ 50"      # an error: expected a number after 'thru'
shot typed
hold Escape
tap ctrl+z
tap ctrl+s
sleep 1
check "Ctrl+S saved the show (title $(title))" '[[ "$(title)" != *"*"* ]]'

python3 - "$tmp/show/console.haze.json" <<'PY' && pass=$((pass + 1)) || fail=$((fail + 1))
import json, sys
show = json.load(open(sys.argv[1]))
cues = {c["number"]: c for c in show["cue_lists"][0]["cues"]}
ok = True
def check(what, cond):
    global ok
    print(("ok: " if cond else "FAIL: ") + what)
    ok = ok and cond
check("cues are 1, 5, 7, 10 (cue 8 undone): %s" % sorted(cues), sorted(cues, key=float) == ["1", "5", "7", "10"])
seven = cues.get("7", {}).get("values", {})
check("cue 7 holds fixtures 7-12 at 60 %%: %s" % seven,
      sorted(seven, key=int) == [str(i) for i in range(7, 13)] and all(abs(v.get("intensity", -1) - 0.6) < 1e-6 for v in seven.values()))
sys.exit(0 if ok else 1)
PY
finish
