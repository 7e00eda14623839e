#!/usr/bin/env bash
# --cells auto (the default, docs/cells.md "Cost"): a fixture's cells are drawn as one beam where
# they act as one (every cell lit alike, packed within tan(F / 2) x 1 m of their centre), else one
# beam per cell. The beams `haze bench` draws are checked against that rule worked out here from
# `haze fixture info` and `haze state` (the cells' lens offsets, the zoom, each cell's level and
# colour): on the 19-cell test wash lit alike and with one cell red, and, with the optional test
# data, on the imported Capture rig (its A.leda Wash K20s come from the QLC+ library with 37
# cells). There the picture must stay what the cells drawn one by one give (PNGs within a level
# of 255 on average; measured 0.2 at 1280x720). `--quality reference` draws every cell.
# Usage: cells_auto.sh HAZE REPO
set -u
haze=$1
repo=$(cd "$2" && pwd)
source "$repo/tests/cli/test_data.bash"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$repo/tests/cli/checks.bash"

beams() {  # beams SHOW [bench options]: the beams a bench frame of the show's first cue draws
  "$haze" bench --show "$@" --width 64 --height 36 --frames 1 --json 2>/dev/null |
    python3 -c 'import json, sys; t = sys.stdin.read(); print(json.loads(t[t.index("{"):])["beams"])' 2>/dev/null || echo none
}
# expected SHOW: the beams of cue 1 by the rule, from the profiles' cells and the stage state.
expected() {
  "$haze" state "$1" --cue 1 --json >"$tmp/state.json" || return
  python3 - "$1" "$haze" "$tmp/state.json" <<'PY'
import json, math, os, subprocess, sys
show_path, haze, state = sys.argv[1], sys.argv[2], json.load(open(sys.argv[3]))
show = json.load(open(show_path))
infos = {}
auto = separate = 0
for f in show["fixtures"]:
    s = state.get(str(f["id"]), {})
    if s.get("intensity", 0) <= 0:
        continue
    pid = f["profile"]
    if pid not in infos:
        path = os.path.join(os.path.dirname(show_path), show["profiles"][pid])
        infos[pid] = json.loads(subprocess.run([haze, "fixture", "info", path, "--json"], capture_output=True,
                                               text=True, check=True).stdout)
    cells = infos[pid]["cells"]
    if not cells:
        auto += 1; separate += 1
        continue
    levels = s.get("cells") or [{"intensity": 1.0, "color": [1, 1, 1]}] * len(cells)
    lit = [(c, v) for c, v in zip(cells, levels) if v["intensity"] > 0]
    separate += len(lit)
    field = s.get("zoom", infos[pid]["field_angle"])
    centre = [sum(c["lens_offset"][i] for c, _ in lit) / max(len(lit), 1) for i in range(3)]
    spread = max((math.dist(c["lens_offset"], centre) for c, _ in lit), default=0.0)
    alike = len(lit) == len(cells) and all(abs(v["intensity"] - lit[0][1]["intensity"]) <= 1e-3 and
                                           all(abs(a - b) <= 1e-3 for a, b in zip(v["color"], lit[0][1]["color"]))
                                           for _, v in lit)
    auto += 1 if len(lit) > 1 and alike and spread <= math.tan(math.radians(field / 2)) else len(lit)
print(auto, separate)
PY
}

# The 19-cell test wash in the Cube venue (both travel with the repository).
python3 "$repo/tests/data/gdtf/make_gdtf.py" "$repo/tests/data/gdtf/hex19_wash.xml" "$tmp/hex19.gdtf"
cube="$repo/tests/data/shared/venues/Cube/Cube.gltf"
python3 "$repo/tests/cells_show.py" "$tmp/alike.haze.json" hex19.gdtf "$cube"
python3 "$repo/tests/cells_show.py" "$tmp/apart.haze.json" hex19.gdtf "$cube" '{"intensity": 1, "cells": {"4": {"color": [1, 0, 0]}}}'
read -r want_auto want_separate <<<"$(expected "$tmp/alike.haze.json")"
check "the rule says one beam for the wash lit alike, 19 cell by cell (got '$want_auto $want_separate')" \
  "$([ "$want_auto" = 1 ] && [ "$want_separate" = 19 ]; echo $?)"
got=$(beams "$tmp/alike.haze.json")
check "auto draws the wash lit alike as one beam (got $got)" "$([ "$got" = 1 ]; echo $?)"
got=$(beams "$tmp/alike.haze.json" --cells separate)
check "--cells separate draws its 19 cells (got $got)" "$([ "$got" = 19 ]; echo $?)"
got=$(beams "$tmp/apart.haze.json")
check "auto draws 19 beams when one cell is red (got $got)" "$([ "$got" = 19 ]; echo $?)"
got=$(beams "$tmp/apart.haze.json" --cells merged)
check "--cells merged draws the 18 white and the red cell as one beam (got $got)" "$([ "$got" = 1 ]; echo $?)"
# --quality reference draws what is there: every cell, as --cells separate does (byte for byte),
# not the merged beam.
for c in auto separate merged; do
  "$haze" render "$tmp/alike.haze.json" --quality reference --width 48 --height 27 \
    $([ $c = auto ] || echo --cells $c) -o "$tmp/ref_$c.pfm" >/dev/null 2>&1
done
check "--quality reference draws every cell: the same image as --cells separate" \
  "$(cmp -s "$tmp/ref_auto.pfm" "$tmp/ref_separate.pfm"; echo $?)"
check "and not the merged beam's" "$([ -s "$tmp/ref_merged.pfm" ] && ! cmp -s "$tmp/ref_auto.pfm" "$tmp/ref_merged.pfm"; echo $?)"

if want_data gdtf/mvr/capture_demo_show.mvr; then
  mkdir -p "$tmp/cap"
  "$haze" import-mvr "$(data_path gdtf/mvr/capture_demo_show.mvr)" -o "$tmp/cap/cap.haze.json" >/dev/null 2>&1
  read -r want_auto want_separate <<<"$(expected "$tmp/cap/cap.haze.json")"
  got_auto=$(beams "$tmp/cap/cap.haze.json")
  got_separate=$(beams "$tmp/cap/cap.haze.json" --cells separate)
  echo "Capture rig, cue 1: auto $got_auto beams (rule: $want_auto), separate $got_separate (rule: $want_separate)"
  check "the Capture rig's beams follow the rule: auto $got_auto of $want_auto, separate $got_separate of $want_separate" \
    "$([ -n "$want_auto" ] && [ "$got_auto" = "$want_auto" ] && [ "$got_separate" = "$want_separate" ]; echo $?)"
  for c in auto separate; do
    "$haze" render "$tmp/cap/cap.haze.json" --cells $c --width 640 --height 360 -o "$tmp/$c.png" >/dev/null 2>&1
  done
  diff=$(compare -metric MAE "$tmp/auto.png" "$tmp/separate.png" null: 2>&1 | sed 's/.*(\(.*\))/\1/')
  echo "Capture rig at 640x360: mean difference auto against separate $diff of full scale"
  check "the Capture rig's picture stays within a level of 255 on average (got $diff)" \
    "$(awk -v d="$diff" 'BEGIN { exit !(d != "" && d + 0 < 1 / 255) }'; echo $?)"
fi

echo "$passed passed, $fail failed"
data_exit "$fail"
