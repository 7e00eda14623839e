#!/usr/bin/env bash
# The picture of docs/rendering.md, "Exposure": the mean frame level over the demo's 5 s fade to
# black, with the exposure held for the run (the default) and metered per frame
# (--exposure-mode per-frame). The same show, video and measure as tests/cli/render_exposure_fade.sh
# (a last cue taking all twelve fixtures out in 5 s, 160x90 draft H.264 at 10 fps, decoded to grey
# by ffmpeg); the plot is drawn with ImageMagick. Prints the two series, one line per frame.
# usage: tools/plot_exposure_fade.sh HAZE_BINARY OUT.png   (from the repository root)
set -euo pipefail
haze=$1; out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for tool in ffmpeg convert python3; do
  command -v $tool >/dev/null || { echo "plot_exposure_fade: $tool is not installed (tools/install-deps.sh installs it)" >&2; exit 1; }
done

cp -r "$root/examples/demo/." "$tmp/"
python3 - "$tmp/demo.haze.json" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
show["cue_lists"][0]["cues"].append({"number": "6", "label": "Out", "fade": 5.0, "delay": 0.0, "follow": None,
                                     "values": {str(f["id"]): {"intensity": 0.0} for f in show["fixtures"]}})
json.dump(show, open(sys.argv[1], "w"), indent=1)
PY

# levels NAME [OPTIONS]: mean grey (0..255) of each frame of the video, one a line.
levels() {
  "$haze" render "$tmp/demo.haze.json" --video "$tmp/$1.mp4" --from 6 --to 6 --hold 1 --fps 10 \
    --width 160 --height 90 --quality draft "${@:2}" >/dev/null 2>"$tmp/$1.err" ||
    { echo "plot_exposure_fade: render $1: $(cat "$tmp/$1.err")" >&2; exit 1; }
  ffmpeg -v error -i "$tmp/$1.mp4" -f rawvideo -pix_fmt gray - >"$tmp/$1.gray"
  python3 - "$tmp/$1.gray" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
n = 160 * 90
for k in range(len(data) // n):
    print("%.2f" % (sum(data[k * n:(k + 1) * n]) / n))
PY
}
levels held >"$tmp/held.txt"
levels chased --exposure-mode per-frame >"$tmp/chased.txt"
paste "$tmp/held.txt" "$tmp/chased.txt" | awk 'BEGIN { print "# frame t_s held per_frame" } { printf "%d %.1f %s %s\n", NR - 1, (NR - 1) / 10, $1, $2 }'

# The plot as ImageMagick draw primitives: 0..6 s across, grey 0..100 up.
python3 - "$tmp/held.txt" "$tmp/chased.txt" "$tmp/plot.mvg" <<'PY'
import sys
held = [float(x) for x in open(sys.argv[1])]
chased = [float(x) for x in open(sys.argv[2])]
W, H, left, right, top, bottom = 560, 300, 56, 16, 36, 44
x = lambda t: left + (W - left - right) * t / 6.0
y = lambda g: H - bottom - (H - top - bottom) * g / 100.0
mvg = ["font DejaVu-Sans", "font-size 12", "stroke-antialias 1"]
for g in range(0, 101, 20):  # grid and axis labels
    mvg += ["stroke #dddddd", "stroke-width 1", f"line {left},{y(g):.1f} {W - right},{y(g):.1f}",
            "stroke none", "fill #444444", f"text {left - 28},{y(g) + 4:.1f} '{g}'"]
for t in range(0, 7):
    mvg += ["stroke none", "fill #444444", f"text {x(t) - 4:.1f},{H - bottom + 16} '{t}'"]
mvg += ["stroke #999999", "stroke-width 1", f"line {x(5):.1f},{top} {x(5):.1f},{H - bottom}",
        "stroke none", "fill #666666", f"text {x(5) - 64:.1f},{y(92):.1f} 'fade ends'",
        "fill #222222", f"text {left + (W - left - right) / 2 - 60},{H - 10} 'seconds after GO'",
        f"text 8,{top - 14} 'mean grey (0..255) of each frame: the demo fading to black in 5 s'"]
def series(levels, colour, label, ly):  # the curve, and its key below the curves at the left
    pts = " ".join(f"{x(k / 10):.1f},{y(v):.1f}" for k, v in enumerate(levels))
    lx = x(0.2)
    return ["fill none", f"stroke {colour}", "stroke-width 2", f"polyline {pts}",
            f"line {lx:.1f},{ly:.1f} {lx + 24:.1f},{ly:.1f}", "stroke none", f"fill {colour}", f"text {lx + 30:.1f},{ly + 4:.1f} '{label}'"]
mvg += series(held, "#1f5fbf", "held for the run (default)", y(30))
mvg += series(chased, "#d2691e", "--exposure-mode per-frame", y(20))
open(sys.argv[3], "w").write("\n".join(mvg) + "\n")
PY
# Passed inline: ImageMagick's usual security policy refuses -draw @FILE.
convert -size 560x300 xc:white -draw "$(cat "$tmp/plot.mvg")" -strip "$out"
echo "wrote $out" >&2
