#!/usr/bin/env bash
# What cells cost (docs/cells.md, docs/rendering.md "Cells"): `haze bench --show` on three rigs
# that light the same place with the same photometry:
#   one    a 1-cell wash (tests/data/gdtf/hex1_wash.xml)
#   cells  a 19-cell wash (tests/data/gdtf/hex19_wash.xml), every cell lit, one beam per cell
#          (--cells separate: every cell lit alike, `auto` would draw it as one beam)
#   split  19 separate 1-cell washes at the 19 cells' lens positions
#   merged the 19-cell wash with --cells merged (its alike cells as one beam)
# and prints each median frame time and the ratios, measured in one run.
# usage: tools/bench_cells.sh HAZE [bench options, e.g. --width 640 --height 360 --frames 5]
set -eu
HAZE=$1
shift
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
python3 "$ROOT/tests/data/gdtf/make_gdtf.py" "$ROOT/tests/data/gdtf/hex1_wash.xml" "$OUT/hex1.gdtf"
python3 "$ROOT/tests/data/gdtf/make_gdtf.py" "$ROOT/tests/data/gdtf/hex19_wash.xml" "$OUT/hex19.gdtf"
VENUE="$ROOT/tests/data/shared/venues/Cube/Cube.gltf"  # CC0, travels with the repository
python3 - "$OUT" "$VENUE" "$HAZE" <<'PY'
import json, subprocess, sys
out, venue, haze = sys.argv[1:4]
info = json.loads(subprocess.run([haze, "fixture", "info", out + "/hex19.gdtf", "--json"], check=True,
                                 capture_output=True, text=True).stdout)
def show(profiles, fixtures):
    cue = {str(f["id"]): {"intensity": 1} for f in fixtures}
    return {"format": "haze-show", "version": 1, "venue": {"gltf": venue},
            "atmosphere": {"scattering": 0.05, "absorption": 0.0, "phase": "hazy", "g": 0.0, "ambient": 0.05},
            "cameras": [{"name": "FOH", "position": [0, 3, 12], "target": [0, 1, 0], "fov_y": 50}],
            "profiles": profiles, "fixtures": fixtures,
            "cue_lists": [{"name": "Main", "cues": [{"number": "1", "values": cue}]}]}
at = [0, 5, 0]
one = show({"w": "hex1.gdtf"}, [{"id": 1, "name": "one", "profile": "w", "position": at}])
cells = show({"w": "hex19.gdtf"}, [{"id": 1, "name": "cells", "profile": "w", "position": at}])
# The 1-cell wash's lens sits at the first cell's offset; each separate wash is moved so that its
# lens lands where its cell's is.
first = info["cells"][0]["lens_offset"]
split = show({"w": "hex1.gdtf"}, [{"id": k + 1, "name": "split %d" % (k + 1), "profile": "w",
                                   "position": [at[i] + c["lens_offset"][i] - first[i] for i in range(3)]}
                                  for k, c in enumerate(info["cells"])])
for name, s in (("one", one), ("cells", cells), ("split", split)):
    json.dump(s, open("%s/%s.haze.json" % (out, name), "w"), indent=1)
PY
declare -A ms
for rig in one cells split merged; do
  if [ "$rig" = merged ]; then
    json=$("$HAZE" bench --show "$OUT/cells.haze.json" --cells merged --json "$@")
  else
    json=$("$HAZE" bench --show "$OUT/$rig.haze.json" --cells separate --json "$@")
  fi
  ms[$rig]=$(python3 -c 'import json,sys; j=json.loads(sys.argv[1]); print(j["median_frame_ms"], j["beams"], j["pass_ms"]["shadow_maps"], j["pass_ms"]["planes"], j["device"])' "$json")
  echo "$rig: median_frame_ms beams shadow_maps_ms planes_ms device = ${ms[$rig]}"
done
python3 - "${ms[one]}" "${ms[cells]}" "${ms[split]}" "${ms[merged]}" <<'PY'
import sys
one, cells, split, merged = (float(a.split()[0]) for a in sys.argv[1:5])
print("19-cell wash / 1-cell wash: %.2f; 19 separate washes / 1-cell wash: %.2f; 19-cell wash / 19 separate: %.2f; "
      "merged 19-cell wash / 1-cell wash: %.2f" % (cells / one, split / one, cells / split, merged / one))
PY
