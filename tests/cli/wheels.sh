#!/usr/bin/env bash
# The second gobo wheel and spinning wheels through the binary: `haze fixture info` of the BMFL
# lists both gobo wheels and both colour wheels with their slots and which wheel each channel
# drives; `haze state --at` over a held cue with gobo_spin shows the angle growing linearly
# (rotation + spin * t, docs/physics.md "Spin"); `haze validate` refuses a second wheel the
# profile lacks; a reference render of the BMFL with gobo2 in holds less light than without.
# Usage: wheels.sh HAZE REPO
set -uo pipefail
haze=$1; root=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

source "$root/tests/cli/test_data.bash"
need_data "gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"
bmfl=$(data_path "gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf")
"$haze" fixture info "$bmfl" --json >"$tmp/bmfl.json" 2>/dev/null
check "fixture info lists the BMFL's two gobo wheels and two colour wheels with their slots" 'node -e "
  const f = JSON.parse(require(\"fs\").readFileSync(process.argv[1]));
  const g = f.gobo_wheels, c = f.color_wheels, ch = f.modes[0].channels;
  const ok = g.length === 2 && g[0].name === \"Gobo1\" && g[1].name === \"Gobo2\" && g[0].slots.length === 7 &&
             g[1].slots.length === 7 && g[1].slots[1] === \"G01 (Dot Breakup)\" && c.length === 2 && c[1].slots.length === 7 &&
             ch[25].attribute === \"gobo\" && ch[25].wheel === 2 && ch[26].attribute === \"gobo_rotation\" && ch[26].wheel === 2 &&
             ch[23].spin_when_selected[0] === -30 && ch[23].spin_when_selected[1] === 30;
  process.exit(ok ? 0 : 1)" "$tmp/bmfl.json"'
"$haze" fixture info "$bmfl" >"$tmp/bmfl.txt" 2>/dev/null
check "the text lists gobo wheel 2 and its slots" 'grep -q "gobo wheel 2 \"Gobo2\": 7 slots: \"Open\" \"G01 (Dot Breakup)\"" "$tmp/bmfl.txt"'

cat >"$tmp/spin.haze.json" <<JSON
{
  "format": "haze-show", "version": 1,
  "venue": { "gltf": "$root/examples/demo/venue/theatre.gltf" },
  "cameras": [ { "name": "Top", "position": [0, 5, 0.01], "target": [0, 0, 0], "fov_y": 40 } ],
  "profiles": {
    "spot": { "format": "haze-fixture", "version": 1, "name": "Two wheels",
              "photometry": { "beam_angle": 12, "field_angle": 18, "peak_candela": 40000 },
              "prisms": [ { "name": "3-facet", "facets": 3, "deflection": 10 } ],
              "gobo_wheels": [ { "name": "Gobo 1", "slots": [ { "name": "Open" }, { "name": "Dots" } ] },
                               { "name": "Gobo 2", "slots": [ { "name": "Open" }, { "name": "Leaves" } ] } ],
              "modes": [ { "name": "m", "channels": [ "Dimmer", "Gobo 1", "Gobo 1 rotation", "Gobo 2", "Gobo 2 spin" ] } ] },
    "bmfl": "$bmfl"
  },
  "fixtures": [ { "id": 1, "profile": "spot", "position": [0, 6, 0] }, { "id": 2, "profile": "bmfl", "position": [0, 6, 0] } ],
  "cue_lists": [ { "name": "Main", "cues": [
    { "number": "1", "values": { "1": { "intensity": 1, "gobo": "Dots", "gobo_rotation": 10, "gobo_spin": 30,
                                        "gobo2": "Leaves", "gobo2_spin": -45, "prism": "3-facet", "prism_spin": 90, "cto": 100 } } },
    { "number": "2", "values": { "1": { "intensity": 0 }, "2": { "intensity": 1 } } },
    { "number": "3", "values": { "2": { "gobo2": "G02 (Radial Dashes 18)" } } }
  ] } ]
}
JSON
"$haze" validate "$tmp/spin.haze.json" >"$tmp/validate.txt" 2>&1; rc=$?
check "the wheels show validates (exit $rc: $(head -3 "$tmp/validate.txt"))" '[ $rc -eq 0 ]'

# The new keys are in schemas/show.schema.json.
source "$root/tests/cli/schema_check.bash"
check_conforms show.schema.json "$tmp/spin.haze.json" "the wheels show"

# Cue 1 held: the angles at t = 0, 0.5, ..., 4 s lie on rotation + spin * t.
for t in 0 0.5 1 1.5 2 2.5 3 3.5 4; do
  "$haze" state "$tmp/spin.haze.json" --cue 1 --at "$t" --json >"$tmp/at-$t.json" || echo "state --at $t failed"
done
node -e '
  const fs = require("fs");
  let bad = [];
  for (const t of [0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4]) {
    const s = JSON.parse(fs.readFileSync(process.argv[1] + "/at-" + t + ".json"))["1"];
    const want = { gobo_angle: 10 + 30 * t, gobo2_angle: -45 * t, prism_angle: 90 * t };
    // An angle is the same modulo 360 (haze keeps the turns of a spin modulo 360 for precision).
    const off = (k) => Math.abs((((s[k] - want[k]) % 360) + 540) % 360 - 180);
    for (const k in want) if (off(k) > 1e-3) bad.push(k + " at " + t + ": " + s[k] + " not " + want[k]);
    if (s.gobo_spin !== 30 || s.gobo2_spin !== -45 || s.prism_spin !== 90 || s.gobo_rotation !== 10 || s.gobo2 !== "Leaves" || s.cto !== 100) bad.push("spins at " + t);
  }
  if (bad.length) { console.log(bad.join("; ")); process.exit(1); }
' "$tmp" >"$tmp/angles.txt"
check "state --at: the angles grow linearly ($(cat "$tmp/angles.txt"))" '[ ! -s "$tmp/angles.txt" ]'

# A slot the second wheel lacks is refused at its place.
sed 's/"gobo2": "Leaves"/"gobo2": "Nope"/' "$tmp/spin.haze.json" >"$tmp/bad.haze.json"
"$haze" validate "$tmp/bad.haze.json" >"$tmp/bad.txt" 2>&1; rc=$?
check "validate refuses a gobo2 slot the wheel lacks (exit $rc: $(tr '\n' '|' <"$tmp/bad.txt"))" \
  '[ $rc -ne 0 ] && grep -q "values/1/gobo2: .*no gobo slot \"Nope\" on its second gobo wheel" "$tmp/bad.txt"'

# The BMFL from above (its real gobo images, the camera under the grid): cue 3 puts G02 of the
# second wheel in the gate (measured: 0.09 of the open pool's light).
"$haze" render "$tmp/spin.haze.json" --cue 2 --width 48 --height 48 --quality reference -o "$tmp/open.pfm" 2>/dev/null
"$haze" render "$tmp/spin.haze.json" --cue 3 --width 48 --height 48 --quality reference -o "$tmp/gobo2.pfm" 2>/dev/null
ratio=$(python3 - "$tmp/open.pfm" "$tmp/gobo2.pfm" <<'PY'
import struct, sys
def total(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split()); scale = float(parts[2])
    fmt = ("<" if scale < 0 else ">") + "f" * (3 * w * h)
    return sum(struct.unpack(fmt, parts[3][:12 * w * h]))
a, b = total(sys.argv[1]), total(sys.argv[2])
print("%.4f" % (b / a) if a > 0 else "nan")
PY
)
check "the BMFL's pool with gobo2 in holds less light than open (got $ratio)" \
  'awk -v r="$ratio" "BEGIN { exit !(r > 0.02 && r < 0.95) }"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
