#!/usr/bin/env bash
# File > Export MVR from the keyboard (Ctrl+E), under Xvfb with real X input events: on a saved
# copy of the demo show the path popup starts at SHOW.mvr, the export writes it (an MVR 1.6 with
# every fixture, well-formed), reports it on stderr, saves the fixtures' new uuids in the show and
# reopens it (the title stays, no unsaved changes). 640x360, draft quality.
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

python3 "$root/tests/show_copy.py" "$root/examples/demo/demo.haze.json" "$tmp/rig.haze.json"
fixtures=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["fixtures"]))' "$tmp/rig.haze.json")
start_haze "haze - rig.haze.json" "$tmp/rig.haze.json" --width 640 --height 360 --quality draft
tap ctrl+e                 # the path popup, its field focused and holding rig.mvr
hold Return
wait_until 120 '[ -s "$tmp/rig.mvr" ]'
check "the MVR is written where the popup proposed" '[ -s "$tmp/rig.mvr" ]'
summary=$(grep "haze: exported" "$tmp/haze.out")
check "the export is reported on stderr ($summary)" '[[ "$summary" == *"MVR 1.6, $fixtures fixtures"* ]]'
python3 -c 'import sys, zipfile; open(sys.argv[2], "wb").write(zipfile.ZipFile(sys.argv[1]).read("GeneralSceneDescription.xml"))' \
  "$tmp/rig.mvr" "$tmp/rig.xml" 2>/dev/null
check "the XML is well-formed" 'xmllint --noout "$tmp/rig.xml"'
n=$(xmllint --xpath 'count(//Fixture)' "$tmp/rig.xml" 2>/dev/null)
check "it holds the $fixtures fixtures (got $n)" '[ "$n" = "$fixtures" ]'
uuids=$(grep -c '"uuid"' "$tmp/rig.haze.json")
check "the new uuids are saved in the show ($uuids of $fixtures)" '[ "$uuids" = "$fixtures" ]'
check "the show is open again, unchanged (title '$(title)')" '[[ "$(title)" == "haze - rig.haze.json" ]]'
tap ctrl+q                 # no unsaved changes: no question
sleep 1
wait_exit
check "Ctrl+Q exits cleanly after the export (status $rc)" '[ "$rc" = 0 ]'
finish
