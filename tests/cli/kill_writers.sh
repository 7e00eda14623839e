#!/usr/bin/env bash
# The kill test: every command that writes a file the user keeps is killed with SIGKILL at
# random moments, ROUNDS times each, over an existing file. After every kill the file must be
# exactly the old or the new version (byte for byte), and a show must still validate.
#   - `haze import-mvr --force` over an imported show, alternating two MVRs (the show, its venue
#     and its GDTF folder are each replaced atomically, the show last);
#   - `haze render -o` over an existing PFM and PNG, alternating two cues;
#   - `haze live --state-json` over an existing state file.
# The GUI's save (with its backup) is killed the same way in tests/gui/kill_save.sh.
# ctest runs a handful of rounds; `make soak` runs 200 of each.
# usage: kill_writers.sh HAZE REPO [ROUNDS] [SEED]
set -uo pipefail
haze=$1
root=$2
rounds=${3:-3}
RANDOM=${4:-1}
source "$root/tests/cli/test_data.bash"
mvr=$(dirname "$(data_path gdtf/mvr/scene_objects.mvr)")  # both MVRs travel with the repository
demo=$root/examples/demo/demo.haze.json
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
kills=0
die() { echo "FAIL: $*"; fail=$((fail + 1)); }

# run_and_kill MAX_MS CMD...: starts CMD, kills it with SIGKILL after a random 0..MAX_MS ms
# (or lets it finish first); counts the kills that landed while it ran.
run_and_kill() {
  local max=$1; shift
  "$@" >/dev/null 2>&1 &
  local pid=$!
  local ms=$((RANDOM % max))
  sleep "$(printf '0.%03d' "$ms")" 2>/dev/null || sleep 0
  if kill -9 $pid 2>/dev/null; then kills=$((kills + 1)); fi
  wait $pid 2>/dev/null
}
sum() { sha256sum "$1" | cut -d' ' -f1; }
# Milliseconds one run of a command takes here, so kills spread over its whole run.
time_ms() {
  local t0; t0=$(date +%s%N)
  "$@" >/dev/null 2>&1
  echo $(( ($(date +%s%N) - t0) / 1000000 + 20 ))
}

# ---- import-mvr --force ----
show=$tmp/rig.haze.json
"$haze" import-mvr "$mvr/basic_fixture.mvr" -o "$show" --force >/dev/null 2>&1 || die "import basic_fixture"
sumA=$(sum "$show")
ms=$(time_ms "$haze" import-mvr "$mvr/scene_objects.mvr" -o "$show" --force)
sumB=$(sum "$show")
[ "$sumA" != "$sumB" ] || die "the two imports wrote the same show, the test would compare nothing"
for i in $(seq "$rounds"); do
  src=$mvr/scene_objects.mvr; [ $((i % 2)) -eq 0 ] && src=$mvr/basic_fixture.mvr
  run_and_kill "$ms" "$haze" import-mvr "$src" -o "$show" --force
  s=$(sum "$show")
  [ "$s" = "$sumA" ] || [ "$s" = "$sumB" ] || { die "import-mvr round $i left a show that is neither version"; break; }
  "$haze" validate "$show" >/dev/null 2>"$tmp/verr" || { die "import-mvr round $i: the show no longer validates: $(head -2 "$tmp/verr")"; break; }
done

# ---- render -o (PFM and PNG) ----
for ext in pfm png; do
  img=$tmp/still.$ext
  "$haze" render "$demo" --cue 1 --width 160 --height 90 --quality draft -o "$img" >/dev/null 2>&1 || die "render cue 1"
  old=$(sum "$img")
  ms=$(time_ms "$haze" render "$demo" --cue 2 --width 160 --height 90 --quality draft -o "$img")
  new=$(sum "$img")
  [ "$old" != "$new" ] || die "cues 1 and 2 render the same $ext, the test would compare nothing"
  for i in $(seq "$rounds"); do
    cue=1; [ $((i % 2)) -eq 0 ] && cue=2
    run_and_kill "$ms" "$haze" render "$demo" --cue $cue --width 160 --height 90 --quality draft -o "$img"
    s=$(sum "$img")
    [ "$s" = "$old" ] || [ "$s" = "$new" ] || { die "render $ext round $i left an image that is neither version"; break; }
  done
done

# ---- live --state-json ----
state=$tmp/state.json
"$haze" live "$demo" --duration 0.2 --no-preview --artnet-port 0 --sacn-port 0 --state-json "$state" >/dev/null 2>&1 \
  || die "live --state-json"
old=$(sum "$state")
for i in $(seq "$rounds"); do
  run_and_kill 600 "$haze" live "$demo" --duration 0.3 --no-preview --artnet-port 0 --sacn-port 0 --state-json "$state"
  [ "$(sum "$state")" = "$old" ] || { die "live round $i changed or broke the state file"; break; }
done

# No temporary file may be left under a name a user would take for the real one.
left=$(find "$tmp" -name '*.tmp*' -newer "$show" | wc -l)
echo "kill test: $rounds rounds of each writer, $kills kills landed mid-run, $left temporary files left behind (named .NAME.tmp-PID-N; the next write clears them)"
[ "$kills" -gt 0 ] || die "no kill landed while a command ran: the test tested nothing"
[ $fail -eq 0 ] && echo "1 passed, 0 failed"
[ $fail -eq 0 ]
