#!/usr/bin/env bash
# An imported rig's first picture shows the stage: each bundled MVR imported, cue 1 of "MVR
# focus" rendered with the import's "MVR overview" camera at 320x180, and
#  - every fixture and where its beam lands (its focus point, else where its -Z axis meets the
#    MVR floor), read from the MVR by mvr_frame_points.py's own walk and projected through the
#    stored camera, is inside the frame;
#  - at least a quarter of the PNG's pixels are above black (png_shares.py's own PNG reader).
# Usage: mvr_overview.sh HAZE REPO
set -u
haze=$1
repo=$2
source "$repo/tests/cli/test_data.bash"
need_data gdtf/mvr/basic_fixture.mvr gdtf/mvr/capture_demo_show.mvr gdtf/mvr/scene_objects.mvr
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$repo/tests/cli/checks.bash"

for name in basic_fixture capture_demo_show scene_objects; do
  mvr=$(data_path "gdtf/mvr/$name.mvr")
  "$haze" import-mvr "$mvr" -o "$tmp/$name.haze.json" >/dev/null 2>"$tmp/$name.err"
  check "$name: import-mvr exits 0: $(head -2 "$tmp/$name.err")" $?
  "$haze" render "$tmp/$name.haze.json" --camera "MVR overview" --list "MVR focus" --cue 1 \
    --width 320 --height 180 -o "$tmp/$name.png" >/dev/null 2>"$tmp/$name.rerr"
  check "$name: render exits 0: $(head -2 "$tmp/$name.rerr")" $?
  python3 "$repo/tests/cli/mvr_frame_points.py" "$mvr" "$tmp/$name.haze.json" "MVR overview" 320 180 >"$tmp/$name.pts"
  read -r inside total <"$tmp/$name.pts"
  check "$name: every fixture and beam landing inside the frame (got $inside of $total: $(sed -n 2,4p "$tmp/$name.pts" | tr '\n' ';'))" \
    "$([ -n "$total" ] && [ "$total" -gt 0 ] && [ "$inside" = "$total" ]; echo $?)"
  [ -f "$tmp/$name.png" ] || continue
  lit=$(python3 "$repo/tests/cli/png_shares.py" "$tmp/$name.png" | awk '{ print $3 }')
  check "$name: at least 25% of the pixels above black (got $lit%)" "$(awk -v l="$lit" 'BEGIN { exit !(l >= 25) }'; echo $?)"
  echo "$name: $inside of $total rig points in the frame, $lit% of the pixels above black"
done

echo "$passed passed, $fail failed"
data_exit "$fail"
