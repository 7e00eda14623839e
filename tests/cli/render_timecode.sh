#!/usr/bin/env bash
# `haze render --timecode`: tests/data/live/cues.haze.json times cues 1, 2, 3 at 00:00:01:00,
# 02:00 and 03:00 (fades 0). A still at 00:00:02:10 is the same picture, bit for bit, as
# `--cue 2`; one before the first timed cue is the stage at its defaults (a copy of the show
# whose cue 1 sets nothing, rendered with --cue 1). A video from 00:00:00:20 fires cues 1 and 2
# on their own frames (the log names the frame) and its frame just after cue 1 is the still of
# cue 1. Bad input: one line and exit 1.
# usage: bash render_timecode.sh HAZE_BINARY REPO_ROOT
set -uo pipefail
haze=$1
root=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "FAIL: $*"
  exit 1
}
show="$root/tests/data/live/cues.haze.json"
opts=(--width 96 --height 54 --quality draft --movement instant)

"$haze" render "$show" --timecode 00:00:02:10 "${opts[@]}" -o "$tmp/tc.pfm" 2>"$tmp/err" || fail "render --timecode: $(cat "$tmp/err")"
grep -q "^haze render: timecode 00:00:02:10: cue 2$" "$tmp/err" || fail "no 'cue 2' line: $(cat "$tmp/err")"
"$haze" render "$show" --cue 2 "${opts[@]}" -o "$tmp/cue2.pfm" || fail "render --cue 2 failed"
cmp -s "$tmp/tc.pfm" "$tmp/cue2.pfm" || fail "--timecode 00:00:02:10 differs from --cue 2"
"$haze" render "$show" --cue 3 "${opts[@]}" -o "$tmp/cue3.pfm" || fail "render --cue 3 failed"
cmp -s "$tmp/tc.pfm" "$tmp/cue3.pfm" && fail "cues 2 and 3 render alike: the comparison cannot tell cues apart"
# On a cue's own frame it has fired; one frame before, the cue before it is on stage.
"$haze" render "$show" --timecode 00:00:03:00 "${opts[@]}" -o "$tmp/tc3.pfm" 2>/dev/null &&
  cmp -s "$tmp/tc3.pfm" "$tmp/cue3.pfm" || fail "--timecode 00:00:03:00 is not cue 3"
"$haze" render "$show" --timecode 00:00:02:24 "${opts[@]}" -o "$tmp/tc2.pfm" 2>/dev/null &&
  cmp -s "$tmp/tc2.pfm" "$tmp/cue2.pfm" || fail "--timecode 00:00:02:24 is not cue 2"

# Before the first timed cue: the defaults, as cue 1 of a show whose cue 1 sets nothing (and
# that has no timecodes, for the bad input below).
python3 - "$show" "$tmp/blank.haze.json" <<'PY' || fail "cannot write the blank show"
import json, os, sys
src, dst = sys.argv[1], sys.argv[2]
show = json.load(open(src))
base = os.path.dirname(src)
show["venue"]["gltf"] = os.path.normpath(os.path.join(base, show["venue"]["gltf"]))
for k, v in show["profiles"].items():
    if isinstance(v, str):
        show["profiles"][k] = os.path.normpath(os.path.join(base, v))
show["cue_lists"][0]["cues"][0]["values"] = {}
for cue in show["cue_lists"][0]["cues"]:
    cue.pop("timecode", None)
json.dump(show, open(dst, "w"))
PY
"$haze" render "$show" --timecode 00:00:00:12 "${opts[@]}" -o "$tmp/before.pfm" 2>"$tmp/err" || fail "render before the first cue: $(cat "$tmp/err")"
grep -q "^haze render: timecode 00:00:00:12: before the first timed cue$" "$tmp/err" || fail "no 'before' line: $(cat "$tmp/err")"
"$haze" render "$tmp/blank.haze.json" --cue 1 "${opts[@]}" -o "$tmp/blank.pfm" || fail "render of the blank show failed"
cmp -s "$tmp/before.pfm" "$tmp/blank.pfm" || fail "--timecode 00:00:00:12 differs from the stage at its defaults"
"$haze" render "$show" --cue 1 "${opts[@]}" -o "$tmp/cue1.pfm" || fail "render --cue 1 failed"
cmp -s "$tmp/before.pfm" "$tmp/cue1.pfm" && fail "the defaults render like cue 1"

# Video from 00:00:00:20 at 25 fps: cue 1 fires on frame 5 (00:00:01:00), cue 2 on frame 30.
"$haze" render "$show" --video "$tmp/v-%05d.png" --timecode 00:00:00:20 --duration 1.24 "${opts[@]}" \
  >/dev/null 2>"$tmp/err" || fail "render --video --timecode: $(cat "$tmp/err")"
grep '^haze render: timecode' "$tmp/err" >"$tmp/fired"
printf 'haze render: timecode 00:00:01:00: fired cue 1\nhaze render: timecode 00:00:02:00: fired cue 2\n' >"$tmp/want"
diff "$tmp/want" "$tmp/fired" || fail "the video's cues did not fire on their frames"
[ "$(ls "$tmp"/v-*.png | wc -l)" -eq 31 ] || fail "expected 31 frames for 1.24 s at 25 fps"
"$haze" render "$show" --cue 1 "${opts[@]}" -o "$tmp/cue1.png" || fail "render --cue 1 (PNG) failed"
cmp -s "$tmp/v-00005.png" "$tmp/cue1.png" || fail "the frame cue 1 fired on is not the still of cue 1"
cmp -s "$tmp/v-00004.png" "$tmp/cue1.png" && fail "the frame before cue 1 fired already shows it"

# Bad input.
bad() {  # exit status (2: a usage error, 1: bad input), the line's text, show, options
  local status=$1 want=$2 file=$3
  shift 3
  "$haze" render "$file" "$@" -o "$tmp/bad.png" >/dev/null 2>"$tmp/err"
  local rc=$?
  [ "$rc" -eq "$status" ] || fail "render $* exited $rc, expected $status"
  grep -q "$want" "$tmp/err" || fail "render $*: no '$want' in: $(cat "$tmp/err")"
  [ "$(wc -l <"$tmp/err")" -le 2 ] || fail "render $*: more than a line or two of error"
}
bad 2 "frames below 25" "$show" --timecode 00:00:01:25
bad 2 "frames below 30" "$show" --timecode 24:00:00:00 --timecode-rate 30
bad 2 "no --cue" "$show" --timecode 00:00:01:00 --cue 2
bad 1 "has no cue with a timecode" "$tmp/blank.haze.json" --timecode 00:00:01:00
[ -e "$tmp/bad.png" ] && fail "a refused render wrote a file"
echo "PASS render_timecode"
