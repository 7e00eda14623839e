#!/usr/bin/env bash
# File > Import MVR from the keyboard (Ctrl+I), under Xvfb with real X input events: the Capture
# demo rig is imported beside its .mvr, opened (the title names the new show), its warnings come
# folded (fewer lines than warnings, listed in a window and on stderr), and the stage shows
# the rig lit. 640x360, draft quality.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/cli/test_data.bash"
need_data gdtf/mvr/capture_demo_show.mvr
. "$root/tests/gui/gui_session.bash"

cp "$(data_path gdtf/mvr/capture_demo_show.mvr)" "$tmp/rig.mvr"
start_haze "haze - demo" "$root/examples/demo/demo.haze.json" --width 640 --height 360 --quality draft
shot before
tap ctrl+i                 # the path popup, its field focused
hold ctrl+a
type_text "$tmp/rig.mvr"
hold Return
wait_until 300 '[[ "$(title)" == "haze - rig.haze.json" ]]'
check "the imported show is open (title '$(title)')" '[[ "$(title)" == "haze - rig.haze.json" ]]'
check "the show was written beside the MVR" '[ -s "$tmp/rig.haze.json" ] && [ -d "$tmp/rig_gdtf" ]'
check "haze validate accepts it" '"$haze" validate "$tmp/rig.haze.json" >/dev/null 2>&1'
summary=$(grep "imported rig.mvr" "$tmp/haze.out")
check "the import is reported ($summary)" '[[ "$summary" == *"warnings"* ]]'
kinds=$(grep -c "haze: warning: " "$tmp/haze.out")
total=$(echo "$summary" | sed -n 's/.*, \([0-9]*\) warnings.*/\1/p')
check "warnings folded: $kinds lines for $total warnings" '[ "$kinds" -ge 1 ] && [ "$total" -gt "$kinds" ]'
check "each folded line names its place in the XML" '! grep "haze: warning: " "$tmp/haze.out" | grep -qv "GeneralSceneDescription.xml\|\.gdtf"'
sleep 3
shot imported
change=$(difference before imported)
check "the window shows another stage (difference $change)" 'awk -v d="$change" "BEGIN { exit !(d > 0.03) }"'
tap ctrl+q
sleep 1
wait_exit
check "Ctrl+Q exits cleanly after the import (status $rc)" '[ "$rc" = 0 ]'
finish
