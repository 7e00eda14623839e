#!/usr/bin/env bash
# The GUI's save killed with SIGKILL at random moments: haze opens a show, Ctrl+S saves it over
# itself (keeping the version it replaces as NAME.bak), and haze is killed 0..400 ms after the
# key, ROUNDS times, each time from the same old file. After every kill the show is exactly
# the old or the new version and validates, and a backup, where one was written, is exactly
# the old version. (The old file is the demo written compactly, so haze's save of it differs
# byte for byte; the new version is what one save that was left to finish wrote.)
# usage: kill_save.sh HAZE REPO [ROUNDS]
set -uo pipefail
haze=$1; root=$2; rounds=${3:-4}
. "$root/tests/gui/gui_session.bash"
show=$tmp/kill.haze.json
python3 "$root/tests/show_copy.py" "$root/examples/demo/demo.haze.json" "$tmp/old.json" --compact
sum() { sha256sum "$1" | cut -d' ' -f1; }
old=$(sum "$tmp/old.json")
args=(--width 320 --height 180 --quality draft)

# One save left to finish gives the new version.
cp "$tmp/old.json" "$show"
start_haze "haze - kill" "$show" "${args[@]}"
tap ctrl+s
sleep 1
tap ctrl+q
wait_exit
new=$(sum "$show")
check "a finished save wrote a new version (rc $rc)" '[ "$new" != "$old" ] && [ "$(sum "$show.bak")" = "$old" ]'
check "the saved show validates" '"$haze" validate "$show" >/dev/null'

RANDOM=7
landed=0
for i in $(seq "$rounds"); do
  cp "$tmp/old.json" "$show"; rm -f "$show.bak"
  start_haze "haze - kill" "$show" "${args[@]}"
  xdotool key ctrl+s
  sleep "$(printf '0.%03d' $((RANDOM % 400)))"
  kill -9 $pid 2>/dev/null && landed=$((landed + 1))
  wait $pid 2>/dev/null
  s=$(sum "$show")
  if [ "$s" != "$old" ] && [ "$s" != "$new" ]; then check "round $i: the show is the old or the new version" false; break; fi
  if [ -e "$show.bak" ] && [ "$(sum "$show.bak")" != "$old" ]; then check "round $i: the backup is the old version" false; break; fi
  "$haze" validate "$show" >/dev/null 2>&1 || { check "round $i: the show validates" false; break; }
  [ "$s" = "$new" ] && saved=$((${saved:-0} + 1))
done
echo "$rounds kills, $landed while haze ran, ${saved:-0} after the save had replaced the file"
check "every round left the old or the new show, valid, and a good backup" '[ $fail -eq 0 ]'
check "the kills landed while haze ran" '[ $landed -gt 0 ]'
finish
