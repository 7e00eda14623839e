#!/usr/bin/env bash
# Beam optics through the binary: `haze state --at` over one second of a 10 Hz strobe cue gives
# ten openings (docs/show-format.md: the gate runs on the playback clock from GO); a still of a
# strobe of duty 0.25 holds a quarter of the open cue's light (docs/physics.md, "Strobe");
# `haze validate` refuses optics the profile lacks; `haze fixture info --json` lists the optics.
# The show is tests/data/shows/optics.haze.json.
# Usage: optics_state.sh HAZE REPO
set -uo pipefail
haze=$1; root=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

show="$root/tests/data/shows/optics.haze.json"
"$haze" validate "$show" >"$tmp/validate.txt" 2>&1; rc=$?
check "the optics show validates (exit $rc: $(head -3 "$tmp/validate.txt"))" '[ $rc -eq 0 ]'

# One second of cue 2 sampled every 5 ms: count closed -> open edges (the first sample counts).
node -e '
  const { execFileSync } = require("child_process");
  let openings = 0, was = false, opened = 0;
  for (let k = 0; k < 200; ++k) {
    const t = (k * 0.005).toFixed(3);
    const s = JSON.parse(execFileSync(process.argv[1], ["state", process.argv[2], "--cue", "2", "--at", t, "--json"]));
    const open = s["1"].gate > 0;
    if (open && !was) ++openings;
    if (open) ++opened;
    was = open;
    if (JSON.stringify(s["1"].shutter) !== JSON.stringify({ strobe_hz: 10, duty: 0.5 })) { console.log("shutter", s["1"].shutter); process.exit(2); }
  }
  console.log(openings + " " + opened);
' "$haze" "$show" >"$tmp/openings.txt"
check "10 Hz strobe opens ten times in one second (got $(cat "$tmp/openings.txt"): openings, open samples)" \
  '[ "$(cut -d" " -f1 "$tmp/openings.txt")" = 10 ] && [ "$(cut -d" " -f2 "$tmp/openings.txt")" = 100 ]'

"$haze" state "$show" --cue 4 --json >"$tmp/state4.json"
check "cue 4's optics in haze state" 'node -e "
  const s = JSON.parse(require(\"fs\").readFileSync(process.argv[1]))[\"1\"];
  process.exit(s.prism === \"3-facet\" && s.prism_rotation === 30 && s.frost === 0.5 && s.blades[0][1] === 0.3 &&
               s.blade_rotation === 10 && s.shutter === \"open\" ? 0 : 1)" "$tmp/state4.json"'

# Stills: cue 3 (duty 0.25) against cue 1 (open), reference integrator, PFMs summed less the
# dark cue 5 (the venue has emissive surfaces of its own).
"$haze" render "$show" --cue 1 --width 64 --height 36 --quality reference -o "$tmp/open.pfm"
"$haze" render "$show" --cue 3 --width 64 --height 36 --quality reference -o "$tmp/strobe.pfm"
"$haze" render "$show" --cue 5 --width 64 --height 36 --quality reference -o "$tmp/dark.pfm"
ratio=$(python3 - "$tmp/open.pfm" "$tmp/strobe.pfm" "$tmp/dark.pfm" <<'PY'
import struct, sys
def total(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split()); scale = float(parts[2])
    fmt = ("<" if scale < 0 else ">") + "f" * (3 * w * h)
    return sum(struct.unpack(fmt, parts[3][:12 * w * h]))
dark = total(sys.argv[3])
a, b = total(sys.argv[1]) - dark, total(sys.argv[2]) - dark
print("%.6f" % (b / a) if a > 0 else "nan")
PY
)
check "a still of a duty-0.25 strobe holds 0.25 of the open light (got $ratio)" \
  'awk -v r="$ratio" "BEGIN { exit !(r > 0.2499 && r < 0.2501) }"'

# A profile without the optics: every optics value is refused at its place.
sed 's/"1": { "intensity": 1 }/"2": { "frost": 0.5, "prism": "3-facet", "blades": [[0.5, 0.5], [0, 0], [0, 0], [0, 0]] }/' \
  "$show" | sed 's|"../../../examples|"'"$root"'/examples|' >"$tmp/bad.haze.json"
"$haze" validate "$tmp/bad.haze.json" >"$tmp/bad.txt" 2>&1; rc=$?
check "validate refuses optics the par lacks (exit $rc: $(tr '\n' '|' <"$tmp/bad.txt"))" \
  '[ $rc -ne 0 ] && grep -q "values/2/frost" "$tmp/bad.txt" && grep -q "values/2/prism" "$tmp/bad.txt" && grep -q "values/2/blades" "$tmp/bad.txt"'

# fixture info lists the BMFL's prisms, frost and shutter.
source "$root/tests/cli/test_data.bash"
rel="gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"
if want_data "$rel"; then
  "$haze" fixture info "$(data_path "$rel")" --json >"$tmp/bmfl.json"
  check "fixture info lists the BMFL's optics" 'node -e "
    const f = JSON.parse(require(\"fs\").readFileSync(process.argv[1]));
    const ok = f.prisms.length === 2 && f.prisms[0].facets === 6 && f.prisms[0].linear === true && f.frost.max === 5 &&
               f.blades === false && f.shutter.modes.includes(\"strobe\") && f.shutter.modes.includes(\"random\") &&
               f.shutter.max_hz === 10 && Array.isArray(f.warnings);
    process.exit(ok ? 0 : 1)" "$tmp/bmfl.json"'
fi
echo "$pass passed, $fail failed"
data_exit $fail
