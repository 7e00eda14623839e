#!/usr/bin/env bash
# One validation everywhere: a show whose cue names fixture 999 (which the show does not have) is
# refused by every command that reads a show, each exiting 1 with the line `haze validate` gives;
# and one exit-code convention: usage errors exit 2 in every command, and haze --help says so.
# usage: bash validate_everywhere.sh HAZE_BINARY REPO_ROOT
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; failed=0
check() {  # name, condition
  if eval "$2"; then pass=$((pass + 1)); else failed=$((failed + 1)); echo "FAIL $1"; fi
}

mkdir -p "$tmp/show"
cp -r "$root/examples/demo/profiles" "$root/examples/demo/gobos" "$root/examples/demo/venue" "$tmp/show/"
python3 - "$root/examples/demo/demo.haze.json" "$tmp/show/bad.haze.json" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
show["cue_lists"][0]["cues"][0]["values"]["999"] = {"intensity": 1.0}
json.dump(show, open(sys.argv[2], "w"), indent=2)
PY
bad="$tmp/show/bad.haze.json"

"$haze" validate "$bad" >"$tmp/v.out" 2>"$tmp/v.err"; rc=$?
check "validate refuses the show (rc $rc)" '[ $rc -eq 1 ]'
line=$(grep "999" "$tmp/v.err" | head -1)
check "validate names fixture 999 with its pointer: $line" '[[ "$line" == *"bad.haze.json:/cue_lists/0/cues/0/values/999"* ]]'

refused() {  # name, command...: exit 1, validate's line on stderr, nothing written
  local name=$1; shift
  "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  check "$name exits 1 (got $rc)" '[ $rc -eq 1 ]'
  check "$name prints validate's line" 'grep -qF -- "$line" "$tmp/err"'
}
refused render "$haze" render "$bad" --width 32 --height 18 -o "$tmp/x.png"
refused "render --all-cues" "$haze" render "$bad" --all-cues --width 32 --height 18 -o "$tmp/all/"
refused "render --video" "$haze" render "$bad" --video "$tmp/v.mp4" --width 32 --height 18
refused state "$haze" state "$bad" --cue 1 --json
refused sheet "$haze" sheet "$bad" -o "$tmp/s.pdf"
refused live "$haze" live "$bad" --sacn --sacn-port 0 --duration 0.1
refused "bench --show" "$haze" bench --show "$bad" --frames 1
check "nothing was written" '[ ! -e "$tmp/x.png" ] && [ ! -e "$tmp/v.mp4" ] && [ ! -e "$tmp/s.pdf" ]'

# Usage errors: exit 2 from every command, one line naming the option.
demo="$root/examples/demo/demo.haze.json"
usage() {  # name, want, command...
  local name=$1 want=$2; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  check "$name: usage error exits 2 (got $rc)" '[ $rc -eq 2 ] && grep -qF -- "$want" "$tmp/err"'
}
for cmd in render state validate sheet live import-mvr open; do
  usage "$cmd --frobnicate" "--frobnicate" "$haze" $cmd "$demo" --frobnicate
done
usage "bench --frobnicate" "--frobnicate" "$haze" bench --frobnicate
usage "compare --frobnicate" "--frobnicate" "$haze" compare a.pfm b.pfm --frobnicate
usage "fixture info --frobnicate" "--frobnicate" "$haze" fixture info "$demo" --frobnicate
usage "render --width -3" "--width" "$haze" render "$demo" --width -3 -o "$tmp/x.png"
usage "render --cue with --all-cues" "exclude" "$haze" render "$demo" --cue 1 --all-cues -o "$tmp/d/"
usage "state without --cue" "--cue" "$haze" state "$demo"
usage "unknown command" "frobnicate" "$haze" frobnicate
usage "version with an argument" "takes no arguments" "$haze" --version extra

# haze --help lists the convention and the main options.
"$haze" --help >"$tmp/help"; rc=$?
check "haze --help exits 0" '[ $rc -eq 0 ]'
for want in "--video" "--timecode" "--play" "--save-as" "--state-json" "--record-cue" "--osc" "--on-loss" \
    "import-mvr" "sheet" "bench" "compare" "fixture info" "Exit status" "2 a usage error"; do
  check "haze --help mentions $want" 'grep -qF -- "$want" "$tmp/help"'
done
echo "$pass passed, $failed failed"
[ $failed -eq 0 ]
