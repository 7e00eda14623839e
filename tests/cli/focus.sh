#!/usr/bin/env bash
# Focus (docs/physics.md, "Focus") through the binary: `haze fixture info` of the BMFL lists its
# focus and the 16-bit Focus1 channel; a native profile's `focus` block is listed (and a blur out
# of range clamped with a warning); a show with focus validates and conforms to the schemas;
# `haze state --at` samples a focus fade linearly; `haze validate` refuses a focus outside 0..1
# and focus on a profile without one, naming the JSON place; a reference render of a bladed pool
# changes when the lens is defocused and keeps its light.
# Usage: focus.sh HAZE REPO
set -uo pipefail
haze=$1; root=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

source "$root/tests/cli/test_data.bash"
need_data "gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"
bmfl=$(data_path "gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf")
"$haze" fixture info "$bmfl" --json >"$tmp/bmfl.json" 2>/dev/null
check "fixture info lists the BMFL's focus and its Focus1 channel with the fine byte" 'node -e "
  const f = JSON.parse(require(\"fs\").readFileSync(process.argv[1]));
  const ch = f.modes[0].channels.filter((c) => c.attribute === \"focus\");
  const ok = f.focus && f.focus.sharp === 0.5 && f.focus.blur === 0.3 && ch.length === 2 &&
             ch[0].byte === \"coarse\" && ch[1].byte === \"fine\";
  process.exit(ok ? 0 : 1)" "$tmp/bmfl.json"'
"$haze" fixture info "$bmfl" >"$tmp/bmfl.txt" 2>/dev/null
check "fixture info's text says the BMFL has focus" 'grep -q "focus: sharp at 0.5, blur 0.3" "$tmp/bmfl.txt"'

mkdir -p "$tmp/p"
cat >"$tmp/p/lens.json" <<JSON
{ "format": "haze-fixture", "version": 1, "name": "Profile spot",
  "photometry": { "beam_angle": 20, "field_angle": 26, "peak_candela": 40000 },
  "focus": { "sharp": 0.4, "blur": 0.5 }, "blades": true,
  "modes": [ { "name": "m", "channels": [ "Dimmer", "Focus", "Focus fine" ] } ] }
JSON
cat >"$tmp/p/plain.json" <<JSON
{ "format": "haze-fixture", "version": 1, "name": "Wash",
  "photometry": { "beam_angle": 20, "field_angle": 26, "peak_candela": 40000 },
  "modes": [ { "name": "m", "channels": [ "Dimmer" ] } ] }
JSON
sed 's/"blur": 0.5/"blur": 3/' "$tmp/p/lens.json" >"$tmp/p/wild.json"
"$haze" fixture info "$tmp/p/lens.json" --json >"$tmp/lens-info.json" 2>/dev/null
check "fixture info lists the native focus block and channel" 'node -e "
  const f = JSON.parse(require(\"fs\").readFileSync(process.argv[1]));
  const ch = f.modes[0].channels;
  process.exit(f.focus.sharp === 0.4 && f.focus.blur === 0.5 && ch[1].attribute === \"focus\" && ch[2].byte === \"fine\" ? 0 : 1)" \
  "$tmp/lens-info.json"'
"$haze" fixture info "$tmp/p/plain.json" --json >"$tmp/plain-info.json" 2>/dev/null
check "a profile without a focus block has focus null" 'node -e "
  process.exit(JSON.parse(require(\"fs\").readFileSync(process.argv[1])).focus === null ? 0 : 1)" "$tmp/plain-info.json"'
"$haze" fixture info "$tmp/p/wild.json" --json >"$tmp/wild-info.json" 2>"$tmp/wild.err"
check "a blur out of range is clamped to 1 with a warning ($(tr '\n' '|' <"$tmp/wild.err"))" 'node -e "
  const f = JSON.parse(require(\"fs\").readFileSync(process.argv[1]));
  process.exit(f.focus.blur === 1 && f.warnings.some((w) => w.includes(\"/focus/blur is 3; clamped to 1\")) ? 0 : 1)" \
  "$tmp/wild-info.json"'

cat >"$tmp/focus.haze.json" <<JSON
{
  "format": "haze-show", "version": 1,
  "venue": { "gltf": "$root/examples/demo/venue/theatre.gltf" },
  "cameras": [ { "name": "Top", "position": [0, 5, 0.01], "target": [0, 0, 0], "fov_y": 60 } ],
  "profiles": { "lens": "$tmp/p/lens.json", "wash": "$tmp/p/plain.json", "bmfl": "$bmfl" },
  "fixtures": [ { "id": 1, "profile": "lens", "position": [0, 6, 0] }, { "id": 2, "profile": "wash", "position": [2, 6, 0] },
                { "id": 3, "profile": "bmfl", "position": [-2, 6, 0] } ],
  "cue_lists": [ { "name": "Main", "cues": [
    { "number": "1", "values": { "1": { "intensity": 1, "focus": 0.2, "blades": [[0.5, 0.5], [0, 0], [0, 0], [0, 0]] },
                                 "3": { "intensity": 1, "focus": 0.9 } } },
    { "number": "2", "fade": 4, "values": { "1": { "focus": 0.8 } } },
    { "number": "3", "values": { "1": { "focus": 0.4 } } },
    { "number": "4", "values": { "1": { "focus": 1 } } }
  ] } ]
}
JSON
"$haze" validate "$tmp/focus.haze.json" >"$tmp/validate.txt" 2>&1; rc=$?
check "the focus show validates (exit $rc: $(head -3 "$tmp/validate.txt"))" '[ $rc -eq 0 ]'
source "$root/tests/cli/schema_check.bash"
check_conforms show.schema.json "$tmp/focus.haze.json" "the show"
check_conforms fixture.schema.json "$tmp/p/lens.json" "the profile"

# Cue 2 fades fixture 1's focus from 0.2 to 0.8 over 4 s: 0.2 + 0.15 t. The wash has no focus
# and lists none; the BMFL holds its 0.9.
for t in 0 1 2.5 4; do
  "$haze" state "$tmp/focus.haze.json" --cue 2 --at "$t" --json >"$tmp/at-$t.json" || echo "state --at $t failed"
done
node -e '
  const fs = require("fs");
  let bad = [];
  for (const t of [0, 1, 2.5, 4]) {
    const s = JSON.parse(fs.readFileSync(process.argv[1] + "/at-" + t + ".json"));
    if (Math.abs(s["1"].focus - (0.2 + 0.15 * t)) > 1e-3) bad.push("focus at " + t + ": " + s["1"].focus);
    if ("focus" in s["2"]) bad.push("the wash lists a focus");
    if (s["3"].focus !== 0.9) bad.push("BMFL focus " + s["3"].focus);
  }
  if (bad.length) { console.log(bad.join("; ")); process.exit(1); }
' "$tmp" >"$tmp/fade.txt"
check "state --at: a focus fade is linear in time ($(cat "$tmp/fade.txt"))" '[ ! -s "$tmp/fade.txt" ]'

sed 's/"focus": 0.8/"focus": 1.5/' "$tmp/focus.haze.json" >"$tmp/bad.haze.json"
"$haze" validate "$tmp/bad.haze.json" >"$tmp/bad.txt" 2>&1; rc=$?
check "validate refuses focus 1.5 at its JSON place (exit $rc: $(tr '\n' '|' <"$tmp/bad.txt"))" \
  '[ $rc -ne 0 ] && grep -q "/cue_lists/0/cues/1/values/1/focus" "$tmp/bad.txt"'
sed 's/"1": { "focus": 0.4 }/"2": { "focus": 0.4 }/' "$tmp/focus.haze.json" >"$tmp/nofocus.haze.json"
"$haze" validate "$tmp/nofocus.haze.json" >"$tmp/nofocus.txt" 2>&1; rc=$?
check "validate refuses focus on a profile without one (exit $rc: $(tr '\n' '|' <"$tmp/nofocus.txt"))" \
  '[ $rc -ne 0 ] && grep -q "values/2/focus: .*has no focus" "$tmp/nofocus.txt"'

# Fixture 1 alone with blade 1 in to the centre: cue 3 is sharp (focus 0.4), cue 4 at focus 1 is
# blurred by 0.3 gate radii. The blurred pool keeps the sharp one's light (the kernel is
# normalised; the lamp is not flat under the blur, so not exactly) and differs from it.
sed -e 's/"3": { "intensity": 1, "focus": 0.9 }/"3": { "intensity": 0 }/' "$tmp/focus.haze.json" >"$tmp/one.haze.json"
for c in 3 4; do
  "$haze" render "$tmp/one.haze.json" --cue $c --width 48 --height 48 --quality reference -o "$tmp/cue$c.pfm" 2>/dev/null
done
read -r ratio moved < <(python3 - "$tmp/cue3.pfm" "$tmp/cue4.pfm" <<'PY'
import struct, sys
def load(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split()); scale = float(parts[2])
    fmt = ("<" if scale < 0 else ">") + "f" * (3 * w * h)
    return struct.unpack(fmt, parts[3][:12 * w * h])
a, b = load(sys.argv[1]), load(sys.argv[2])
print("%.4f %.4f" % (sum(b) / sum(a) if sum(a) > 0 else float("nan"),
                     sum(abs(x - y) for x, y in zip(a, b)) / max(sum(a), 1e-30)))
PY
)
check "the defocused pool keeps the sharp pool's light within 5 % (got $ratio)" \
  'awk -v r="$ratio" "BEGIN { exit !(r > 0.95 && r < 1.05) }"'
check "defocusing changes the pool (relative change $moved)" \
  'awk -v r="$moved" "BEGIN { exit !(r > 0.02) }"'
echo "ratio $ratio, moved $moved"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
