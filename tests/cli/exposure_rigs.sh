#!/usr/bin/env bash
# The picture a designer sees first: the Capture rig and the theatre rig, imported and rendered
# with no exposure option, and every cue of the demo (each metered on its own), are metered like a camera: fewer than 2 %
# of the pixels clip to white and at least a fifth of the frame is above black. The PNGs are read
# by png_shares.py (zlib and the PNG filters), not by haze. A manual EV 0 render of the Capture
# rig (today's fixed key) shows what the meter fixes: to the eye a white sheet, it fails the
# same 2 % limit (about 5 % of its pixels are exactly white; the rest sit in the shoulder).
# Usage: exposure_rigs.sh HAZE REPO
set -u
haze=$1
repo=$2
source "$repo/tests/cli/test_data.bash"
shares="python3 $repo/tests/cli/png_shares.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
passed=0
check() {  # check NAME FILE: its shares are within the limits
  read -r _ clipped lit <<<"$($shares "$2")"
  echo "$1: $clipped % clipped, $lit % above black"
  if awk -v c="$clipped" -v l="$lit" 'BEGIN { exit !(c < 2 && l >= 20) }'; then
    passed=$((passed + 1))
  else
    echo "FAIL: $1: $clipped % clipped (limit 2), $lit % above black (at least 20)"
    fail=$((fail + 1))
  fi
}

for rig in capture_demo_show scene_objects; do
  want_data "gdtf/mvr/$rig.mvr" || continue
  if ! "$haze" import-mvr "$(data_path "gdtf/mvr/$rig.mvr")" -o "$tmp/$rig.haze.json" >/dev/null 2>"$tmp/$rig.err"; then
    echo "FAIL: $rig: import-mvr: $(head -2 "$tmp/$rig.err")"; fail=$((fail + 1)); continue
  fi
  if ! "$haze" render "$tmp/$rig.haze.json" --width 640 --height 360 -o "$tmp/$rig.png" 2>"$tmp/$rig.err"; then
    echo "FAIL: $rig: render: $(head -2 "$tmp/$rig.err")"; fail=$((fail + 1)); continue
  fi
  check "$rig" "$tmp/$rig.png"
done

if [ -f "$tmp/capture_demo_show.haze.json" ]; then
  "$haze" render "$tmp/capture_demo_show.haze.json" --width 160 --height 90 --exposure-mode manual \
    -o "$tmp/manual.png" 2>/dev/null
  read -r _ clipped _ <<<"$($shares "$tmp/manual.png")"
  echo "capture_demo_show at manual EV 0: $clipped % clipped"
  if awk -v c="$clipped" 'BEGIN { exit !(c > 2) }'; then passed=$((passed + 1)); else
    echo "FAIL: manual EV 0 should keep today's absolute key (over 2 % white), got $clipped % clipped"
    fail=$((fail + 1))
  fi
fi

# A camera's own exposure is used by --camera NAME, and the command line overrides it.
if [ -f "$tmp/capture_demo_show.haze.json" ]; then
  python3 - "$tmp/capture_demo_show.haze.json" "$tmp/cams.haze.json" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
dark = dict(show["cameras"][0], name="dark", exposure={"mode": "manual", "ev": -8})
show["cameras"].append(dark)
json.dump(show, open(sys.argv[2], "w"), indent=1)
PY
  lit() { "$haze" render "$tmp/cams.haze.json" --width 160 --height 90 "$@" -o "$tmp/cam.png" 2>/dev/null &&
    $shares "$tmp/cam.png" | cut -d' ' -f3; }
  own=$(lit --camera dark); over=$(lit --camera dark --exposure-mode auto); first=$(lit)
  echo "camera 'dark' (manual EV -8): $own % above black; with --exposure-mode auto: $over %; first camera: $first %"
  if awk -v a="$own" -v b="$over" -v c="$first" 'BEGIN { exit !(a + 5 < b && b == c) }'; then
    passed=$((passed + 1))
  else
    echo "FAIL: the camera's manual exposure is not used, or the command line does not override it"
    fail=$((fail + 1))
  fi
fi

# Each demo cue metered on its own, as a still is (an --all-cues run holds one exposure for the
# list by default, so its darker cues stay darker: render_exposure_fade.sh).
if "$haze" render "$repo/examples/demo/demo.haze.json" --all-cues --exposure-mode per-frame --width 640 --height 360 \
  -o "$tmp/demo/" >/dev/null 2>"$tmp/demo.err"; then
  for png in "$tmp/demo"/cue-*.png; do check "demo $(basename "$png" .png)" "$png"; done
else
  echo "FAIL: demo: render --all-cues: $(head -2 "$tmp/demo.err")"; fail=$((fail + 1))
fi

echo "$passed passed, $fail failed"
data_exit "$fail"
