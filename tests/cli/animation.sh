#!/usr/bin/env bash
# The animation wheel through the binary: `haze fixture info` of the BMFL lists its animation
# wheel and the channels that drive it; a native profile with `animation_wheels` and "Animation"
# channels validates and conforms to the schemas; `haze state --at` over a held cue shows the
# disc's angle growing as rotation + spin * t; `haze validate` refuses a slot the wheel lacks; a
# reference render of the BMFL with its disc in holds part of the open pool's light, and the
# pool moves when the disc turns.
# Usage: animation.sh HAZE REPO
set -uo pipefail
haze=$1; root=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

source "$root/tests/cli/test_data.bash"
need_data "gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"
bmfl=$(data_path "gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf")
"$haze" fixture info "$bmfl" --json >"$tmp/bmfl.json" 2>/dev/null
check "fixture info lists the BMFL's animation wheel and its channels" 'node -e "
  const f = JSON.parse(require(\"fs\").readFileSync(process.argv[1]));
  const a = f.animation_wheels, ch = f.modes[0].channels.map((c) => c.attribute);
  const ok = a.length === 1 && a[0].name === \"Animation\" && a[0].slots.join() === \"Open,Animation\" &&
             ch.includes(\"animation\") && ch.includes(\"animation_spin\");
  process.exit(ok ? 0 : 1)" "$tmp/bmfl.json"'

mkdir -p "$tmp/p"
python3 - "$tmp/p/disc.png" <<'PY'
import struct, sys, zlib
# 32 x 32 grey PNG: the top half black (opaque), the bottom half white.
w = h = 32
rows = b"".join(b"\x00" + bytes([0 if y < 16 else 255] * w) for y in range(h))
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)) +
                              chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
PY
cat >"$tmp/p/anim.json" <<JSON
{ "format": "haze-fixture", "version": 1, "name": "Animated spot",
  "photometry": { "beam_angle": 20, "field_angle": 26, "peak_candela": 40000 },
  "animation_wheels": [ { "name": "Effects", "slots": [ { "name": "Open" }, { "name": "Half", "image": "disc.png" }, { "name": "Flames" } ] } ],
  "modes": [ { "name": "m", "channels": [ "Dimmer", "Animation", "Animation rotation", "Animation spin" ] } ] }
JSON
cat >"$tmp/anim.haze.json" <<JSON
{
  "format": "haze-show", "version": 1,
  "venue": { "gltf": "$root/examples/demo/venue/theatre.gltf" },
  "cameras": [ { "name": "Top", "position": [0, 5, 0.01], "target": [0, 0, 0], "fov_y": 60 } ],
  "profiles": { "anim": "$tmp/p/anim.json", "bmfl": "$bmfl" },
  "fixtures": [ { "id": 1, "profile": "anim", "position": [0, 6, 0] }, { "id": 2, "profile": "bmfl", "position": [0, 6, 0] } ],
  "cue_lists": [ { "name": "Main", "cues": [
    { "number": "1", "values": { "1": { "intensity": 1, "animation": "Flames", "animation_rotation": 10, "animation_spin": 15 } } },
    { "number": "2", "values": { "1": { "intensity": 0 }, "2": { "intensity": 1 } } },
    { "number": "3", "values": { "2": { "animation": "Animation" } } },
    { "number": "4", "values": { "2": { "animation_rotation": 30 } } }
  ] } ]
}
JSON
"$haze" validate "$tmp/anim.haze.json" >"$tmp/validate.txt" 2>&1; rc=$?
check "the animation show validates (exit $rc: $(head -3 "$tmp/validate.txt"))" '[ $rc -eq 0 ]'
source "$root/tests/cli/schema_check.bash"
check_conforms show.schema.json "$tmp/anim.haze.json" "the show"
check_conforms fixture.schema.json "$tmp/p/anim.json" "the profile"

"$haze" fixture info "$tmp/p/anim.json" --json >"$tmp/anim-info.json" 2>/dev/null
check "fixture info lists the native profile's animation wheel" 'node -e "
  const f = JSON.parse(require(\"fs\").readFileSync(process.argv[1]));
  const ch = f.modes[0].channels;
  process.exit(f.animation_wheels[0].slots.join() === \"Open,Half,Flames\" && ch[1].attribute === \"animation\" &&
               ch[3].attribute === \"animation_spin\" && ch[3].range[0] === -180 ? 0 : 1)" "$tmp/anim-info.json"'

for t in 0 1 2.5 4; do
  "$haze" state "$tmp/anim.haze.json" --cue 1 --at "$t" --json >"$tmp/at-$t.json" || echo "state --at $t failed"
done
node -e '
  const fs = require("fs");
  let bad = [];
  for (const t of [0, 1, 2.5, 4]) {
    const s = JSON.parse(fs.readFileSync(process.argv[1] + "/at-" + t + ".json"))["1"];
    if (s.animation !== "Flames" || s.animation_rotation !== 10 || s.animation_spin !== 15) bad.push("values at " + t);
    if (Math.abs(s.animation_angle - (10 + 15 * t)) > 1e-3) bad.push("angle at " + t + ": " + s.animation_angle);
  }
  if (bad.length) { console.log(bad.join("; ")); process.exit(1); }
' "$tmp" >"$tmp/angles.txt"
check "state --at: the disc's angle is rotation + spin * t ($(cat "$tmp/angles.txt"))" '[ ! -s "$tmp/angles.txt" ]'

sed 's/"animation": "Flames"/"animation": "Nope"/' "$tmp/anim.haze.json" >"$tmp/bad.haze.json"
"$haze" validate "$tmp/bad.haze.json" >"$tmp/bad.txt" 2>&1; rc=$?
check "validate refuses an animation slot the wheel lacks (exit $rc: $(tr '\n' '|' <"$tmp/bad.txt"))" \
  '[ $rc -ne 0 ] && grep -q "values/1/animation: .*no animation slot \"Nope\"" "$tmp/bad.txt"'

# The BMFL's own disc (wheels/11020171.png, spiral spokes about half open) in its pool. Measured
# at 48 x 48: the disc passes 0.62 of the open pool; turned by 30 degrees the pool changes by
# 8 % of its light (a disc that did not turn would change it by exactly 0: the reference is
# deterministic).
for c in 2 3 4; do
  "$haze" render "$tmp/anim.haze.json" --cue $c --width 48 --height 48 --quality reference -o "$tmp/cue$c.pfm" 2>/dev/null
done
read -r ratio moved < <(python3 - "$tmp/cue2.pfm" "$tmp/cue3.pfm" "$tmp/cue4.pfm" <<'PY'
import struct, sys
def load(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split()); scale = float(parts[2])
    fmt = ("<" if scale < 0 else ">") + "f" * (3 * w * h)
    return struct.unpack(fmt, parts[3][:12 * w * h])
a, b, c = load(sys.argv[1]), load(sys.argv[2]), load(sys.argv[3])
print("%.4f %.4f" % (sum(b) / sum(a) if sum(a) > 0 else float("nan"),
                     sum(abs(x - y) for x, y in zip(b, c)) / max(sum(b), 1e-30)))
PY
)
check "the BMFL's pool with the disc in holds part of the open pool's light (got $ratio)" \
  'awk -v r="$ratio" "BEGIN { exit !(r > 0.2 && r < 0.9) }"'
check "turning the disc by 30 degrees changes the pool (relative change $moved)" \
  'awk -v r="$moved" "BEGIN { exit !(r > 0.03) }"'
echo "ratio $ratio, moved $moved"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
