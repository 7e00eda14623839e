#!/usr/bin/env bash
# `haze render --all-cues` writes one PNG per cue of the demo, and a PFM render is a float image
# of the right size with finite, non-negative values and lit pixels.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

show="$root/examples/demo/demo.haze.json"
"$haze" render "$show" --all-cues --width 320 --height 180 --quality draft -o "$tmp/cues/" >/dev/null
cues=$(grep -c '"number"' "$show")
pngs=$(ls "$tmp/cues"/cue-*.png 2>/dev/null | wc -l)
check "one PNG per cue ($cues cues, $pngs PNGs)" '[ "$pngs" -eq "$cues" ] && [ "$cues" -ge 4 ]'
for f in "$tmp/cues"/cue-*.png; do
  check "$f is a PNG" '[ "$(head -c 4 "$f" | tail -c 3)" = "PNG" ]'
done
"$haze" render "$show" --cue 2 --width 64 --height 36 -o "$tmp/c2.pfm"
check "PFM header" '[ "$(head -c 2 "$tmp/c2.pfm")" = "PF" ]'
size=$(stat -c %s "$tmp/c2.pfm")
header=$(head -c 20 "$tmp/c2.pfm" | head -n 3 | wc -c)
check "PFM holds 64x36 RGB floats" '[ $((size - header)) -eq $((64 * 36 * 12)) ]'
# Values: decode the floats with od and look at them.
od -A n -t f4 -v -j "$header" "$tmp/c2.pfm" | tr -s ' ' '\n' | grep -v '^$' >"$tmp/values"
check "values are finite and non-negative" '! grep -qiE "nan|inf|^-" "$tmp/values"'
check "some pixels are lit" 'awk "\$1 > 1.0 { n++ } END { exit !(n > 10) }" "$tmp/values"'
# Two cues that differ visibly differ in their images.
"$haze" render "$show" --cue 3 --width 64 --height 36 -o "$tmp/c3.pfm"
check "cue 2 and cue 3 differ" '! cmp -s "$tmp/c2.pfm" "$tmp/c3.pfm"'
# --no-bodies: the fixtures' housings leave the image, and nothing else does (they are a few
# percent of the pixels: the rig's heads, at the top of the frame and on the deck).
"$haze" render "$show" --cue 2 --width 64 --height 36 --no-bodies -o "$tmp/c2-nobodies.pfm"
changed=$(python3 - "$tmp/c2.pfm" "$tmp/c2-nobodies.pfm" <<'PY'
import struct, sys
def floats(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split())
    scale = float(parts[2])
    return struct.unpack(("<" if scale < 0 else ">") + "%df" % (3 * w * h), parts[3][: 12 * w * h])
a, b = floats(sys.argv[1]), floats(sys.argv[2])
print(sum(1 for i in range(0, len(a), 3) if abs(a[i] - b[i]) > 1e-3 * max(b[i], 1e-3)) * 3 * 100 // len(a))
PY
)
check "--no-bodies changes some pixels, under 10 % of them ($changed %)" '! cmp -s "$tmp/c2.pfm" "$tmp/c2-nobodies.pfm" && [ "$changed" -lt 10 ]'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
