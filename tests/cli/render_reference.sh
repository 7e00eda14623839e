#!/usr/bin/env bash
# `haze render --quality reference` runs the CPU reference integrator: its PFM of a demo cue
# agrees with the GPU's `high` image of the same cue (mean relative error over the lit values,
# as physics.md measures accuracy), is not the same file (a different integrator made it), and
# its PNG is a PNG.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

show="$root/examples/demo/demo.haze.json"
"$haze" render "$show" --cue 2 --width 96 --height 54 --quality reference -o "$tmp/ref.pfm"
check "reference PFM written" '[ -s "$tmp/ref.pfm" ]'
"$haze" render "$show" --cue 2 --width 96 --height 54 --quality high -o "$tmp/gpu.pfm"
check "the reference is another integrator's image" '! cmp -s "$tmp/ref.pfm" "$tmp/gpu.pfm"'
err=$(python3 - "$tmp/ref.pfm" "$tmp/gpu.pfm" <<'PY'
import struct, sys
def read(path):
    data = open(path, 'rb').read()
    parts = data.split(b'\n', 3)
    w, h = map(int, parts[1].split())
    little = float(parts[2]) < 0
    return struct.unpack(('<' if little else '>') + '%df' % (w * h * 3), parts[3][:w * h * 12])
ref, gpu = read(sys.argv[1]), read(sys.argv[2])
top = max(ref)
lit = [(r, g) for r, g in zip(ref, gpu) if r > 0.01 * top]
print('%.4f' % (sum(abs(g - r) / r for r, g in lit) / len(lit)) if top > 1.0 and len(lit) > 500 else 'unlit')
PY
)
check "GPU high within 8 % of the reference on cue 2 (mean relative error $err)" \
  '[ "$err" != unlit ] && awk -v e="$err" "BEGIN { exit !(e < 0.08) }"'
"$haze" render "$show" --cue 2 --width 96 --height 54 --quality reference -o "$tmp/ref.png"
check "reference PNG written" '[ "$(head -c 4 "$tmp/ref.png" | tail -c 3)" = "PNG" ]'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
