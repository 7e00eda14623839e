#!/usr/bin/env bash
# `haze export-mvr` through the binary. The demo show (native profiles) exports its profiles as
# GDTFs written by haze (warned with what they leave out) and imports again; its fixtures' uuids
# are saved in the show (which still validates), and a second export writes the same XML; the XML is well-formed (xmllint) and
# carries MVR 1.6 with every fixture. With the shared data: the theatre MVR imported, exported
# and imported again keeps its 72 fixtures, its uuids and its GDTF files. Errors: one line, exit 1
# (an existing file, a show that is not there); bad arguments exit 2.
# Usage: export_mvr.sh HAZE REPO
set -u
haze=$1
repo=$2
source "$repo/tests/cli/test_data.bash"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$repo/tests/cli/checks.bash"
scene_xml() {  # scene_xml RIG.mvr OUT.xml: the archive's GeneralSceneDescription.xml
  python3 -c 'import sys, zipfile; open(sys.argv[2], "wb").write(zipfile.ZipFile(sys.argv[1]).read("GeneralSceneDescription.xml"))' "$1" "$2"
}

python3 "$repo/tests/show_copy.py" "$repo/examples/demo/demo.haze.json" "$tmp/demo.haze.json"
fixtures=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["fixtures"]))' "$tmp/demo.haze.json")
"$haze" export-mvr "$tmp/demo.haze.json" -o "$tmp/demo.mvr" >"$tmp/out" 2>"$tmp/err"
rc=$?
check "export-mvr exits 0 (got $rc): $(head -3 "$tmp/err")" $rc
grep -q "MVR 1.6, $fixtures fixtures" "$tmp/out"; rc=$?; check "the summary names MVR 1.6 and $fixtures fixtures: $(cat "$tmp/out")" $rc
grep -q "fixtures given an MVR uuid (saved in the show)" "$tmp/err"; rc=$?; check "the new uuids are reported" $rc
grep -q "^warning: .*is written as the GDTF" "$tmp/err"; rc=$?; check "native profiles are written as GDTF and warned: $(head -2 "$tmp/err")" $rc
uuids=$(grep -c '"uuid"' "$tmp/demo.haze.json")
test "$uuids" -eq "$fixtures"; rc=$?; check "every fixture's uuid is saved in the show ($uuids of $fixtures)" $rc
test -f "$tmp/demo.haze.json.bak"; rc=$?; check "the show's previous version is kept as .bak" $rc
"$haze" validate "$tmp/demo.haze.json" >/dev/null 2>"$tmp/verr"
rc=$?
check "the show with uuids validates: $(head -3 "$tmp/verr")" $rc
scene_xml "$tmp/demo.mvr" "$tmp/demo.xml"
xmllint --noout "$tmp/demo.xml" 2>"$tmp/xerr"; rc=$?; check "the XML is well-formed: $(head -3 "$tmp/xerr")" $rc
xmllint --xpath 'string(/GeneralSceneDescription/@verMajor)' "$tmp/demo.xml" | grep -qx 1; rc=$?; check "verMajor 1" $rc
xmllint --xpath 'string(/GeneralSceneDescription/@verMinor)' "$tmp/demo.xml" | grep -qx 6; rc=$?; check "verMinor 6" $rc
n=$(xmllint --xpath 'count(//Fixture)' "$tmp/demo.xml")
test "$n" -eq "$fixtures"; rc=$?; check "the XML holds $fixtures fixtures (got $n)" $rc
"$haze" export-mvr "$tmp/demo.haze.json" -o "$tmp/demo2.mvr" >/dev/null 2>"$tmp/err2"
! grep -q "given an MVR uuid" "$tmp/err2"; rc=$?; check "a second export makes no uuids" $rc
scene_xml "$tmp/demo2.mvr" "$tmp/demo2.xml"
cmp -s "$tmp/demo.xml" "$tmp/demo2.xml"; rc=$?; check "a second export writes the same XML" $rc
"$haze" import-mvr "$tmp/demo.mvr" -o "$tmp/demo-back.haze.json" >"$tmp/dout" 2>/dev/null
grep -q "^$tmp/demo-back.haze.json: $fixtures fixtures" "$tmp/dout"; rc=$?; check "the demo's MVR imports with its $fixtures fixtures: $(cat "$tmp/dout")" $rc

"$haze" export-mvr "$tmp/demo.haze.json" -o "$tmp/demo.mvr" >/dev/null 2>"$tmp/err3"
code=$?
test $code -eq 1; rc=$?; check "an existing file is refused with exit 1 (got $code)" $rc
test "$(wc -l <"$tmp/err3")" -eq 1 && grep -q "demo.mvr" "$tmp/err3"; rc=$?; check "one line naming the file: $(cat "$tmp/err3")" $rc
"$haze" export-mvr "$tmp/demo.haze.json" -o "$tmp/demo.mvr" --force >/dev/null 2>&1; rc=$?; check "--force overwrites" $rc
"$haze" export-mvr "$tmp/none.haze.json" -o "$tmp/none.mvr" >/dev/null 2>"$tmp/err4"
code=$?
test $code -eq 1 -a "$(wc -l <"$tmp/err4")" -eq 1; rc=$?; check "a missing show: exit 1 (got $code), one line: $(cat "$tmp/err4")" $rc
test ! -e "$tmp/none.mvr"; rc=$?; check "nothing written for a missing show" $rc
"$haze" export-mvr "$tmp/demo.haze.json" >/dev/null 2>&1
code=$?
test $code -eq 2; rc=$?; check "missing -o exits 2 (got $code)" $rc

if theatre=$(data_path gdtf/mvr/scene_objects.mvr); then
  "$haze" import-mvr "$theatre" -o "$tmp/theatre.haze.json" >/dev/null 2>&1
  "$haze" export-mvr "$tmp/theatre.haze.json" -o "$tmp/theatre.mvr" >"$tmp/tout" 2>"$tmp/terr"
  rc=$?
  check "theatre export exits 0 (got $rc): $(head -3 "$tmp/terr")" $rc
  scene_xml "$tmp/theatre.mvr" "$tmp/theatre.xml"
  xmllint --noout "$tmp/theatre.xml"; rc=$?; check "theatre XML well-formed" $rc
  # Written over the imported MVR: its version, its 72 focus points and 28 scene objects stay.
  grep -q "MVR 1.5, 72 fixtures, 1 GDTF files, 0 focus points.*0 fixtures moved, 0 removed" "$tmp/tout"
  rc=$?
  check "theatre over its source: nothing moved or new: $(cat "$tmp/tout")" $rc
  scene_xml "$theatre" "$tmp/theatre-src.xml"
  for kind in FocusPoint SceneObject Layer; do
    a=$(xmllint --xpath "count(//$kind)" "$tmp/theatre-src.xml")
    b=$(xmllint --xpath "count(//$kind)" "$tmp/theatre.xml" 2>/dev/null || echo x)
    test "$a" = "$b"; rc=$?; check "the theatre keeps its $a ${kind}s (got $b)" $rc
  done
  ! grep -q "given an MVR uuid" "$tmp/terr"; rc=$?; check "the imported uuids are kept" $rc
  "$haze" import-mvr "$tmp/theatre.mvr" -o "$tmp/back.haze.json" >"$tmp/bout" 2>/dev/null
  grep -q "72 fixtures" "$tmp/bout"; rc=$?; check "the export imports again with 72 fixtures: $(cat "$tmp/bout")" $rc
  a=$(grep -o '"uuid": "[^"]*"' "$tmp/theatre.haze.json" | sort | md5sum)
  b=$(grep -o '"uuid": "[^"]*"' "$tmp/back.haze.json" | sort | md5sum)
  test "$a" = "$b"; rc=$?; check "the same uuids come back" $rc
else
  want_data gdtf/mvr/scene_objects.mvr
fi

echo "$passed passed, $fail failed"
data_exit "$fail"
