#!/usr/bin/env bash
# Exposure held through a fade (docs/rendering.md, "Exposure"): the demo with a last cue that takes
# every fixture out in 5 s, rendered as a video (H.264, decoded again with ffmpeg). Metered once
# for the list (the default), the mean frame level falls monotonically over the fade and the last
# second's mean is below half the first second's. With --exposure-mode per-frame the meter chases
# the fade: half-way through the picture is still brighter than the held exposure's.
# usage: bash render_exposure_fade.sh HAZE_BINARY REPO_ROOT
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
command -v ffmpeg >/dev/null || { echo "SKIP: ffmpeg is not installed (tools/install-deps.sh installs it)"; exit 77; }
fail() { echo "FAIL: $*"; exit 1; }

cp -r "$root/examples/demo/." "$tmp/"
python3 - "$tmp/demo.haze.json" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
cues = show["cue_lists"][0]["cues"]
cues.append({"number": "6", "label": "Out", "fade": 5.0, "delay": 0.0, "follow": None,
             "values": {str(f["id"]): {"intensity": 0.0} for f in show["fixtures"]}})
json.dump(show, open(sys.argv[1], "w"), indent=1)
PY

# Mean grey level (0..255) of each decoded frame, one a line.
levels() {
  "$haze" render "$tmp/demo.haze.json" --video "$tmp/$1.mp4" --from 6 --to 6 --hold 1 --fps 10 \
    --width 160 --height 90 --quality draft --progress "${@:2}" >/dev/null 2>"$tmp/$1.err" || fail "render $1: $(cat "$tmp/$1.err")"
  ffmpeg -v error -i "$tmp/$1.mp4" -f rawvideo -pix_fmt gray - >"$tmp/$1.gray" || fail "ffmpeg could not decode $1"
  python3 - "$tmp/$1.gray" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
n = 160 * 90
for k in range(len(data) // n):
    frame = data[k * n:(k + 1) * n]
    print(sum(frame) / n)
PY
}
levels held >"$tmp/held.txt"
levels chased --exposure-mode per-frame >"$tmp/chased.txt"
grep -q "exposure metered once, on cue 5" "$tmp/held.err" || fail "the video did not say where it metered: $(cat "$tmp/held.err")"

python3 - "$tmp/held.txt" "$tmp/chased.txt" <<'PY' || exit 1
import sys
held = [float(x) for x in open(sys.argv[1])]
chased = [float(x) for x in open(sys.argv[2])]
fps, fade = 10, 5.0
frames = int(fps * fade)  # the fade runs over frames 0..49 (GO at 0)
assert len(held) >= frames and len(chased) >= frames, (len(held), len(chased))
bad = []
# Monotonic: no frame brighter than the one before by more than the codec's noise.
for k in range(1, frames):
    if held[k] > held[k - 1] + 0.5:
        bad.append("frame %d rose from %.2f to %.2f" % (k, held[k - 1], held[k]))
first, last = sum(held[:fps]) / fps, sum(held[frames - fps:frames]) / fps
print("held: first second %.2f, last second %.2f, half-way %.2f; per-frame half-way %.2f" %
      (first, last, held[frames // 2], chased[frames // 2]))
if not last < 0.5 * first:
    bad.append("the last second (%.2f) is not below half the first (%.2f)" % (last, first))
# per-frame: the old behaviour, the meter brightening the picture as the fixtures go out.
if not chased[frames // 2] > held[frames // 2] + 2.0:
    bad.append("per-frame is not brighter half-way (%.2f) than the held exposure (%.2f)" % (chased[frames // 2], held[frames // 2]))
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY
echo "PASS render_exposure_fade"
