#!/usr/bin/env bash
# Runs COPIES copies of each GUI test at the same time (each on an Xvfb of its own), one test
# after another, and fails if any copy fails: the proof that the GUI tests do not flake under
# load or when run side by side. Each copy's output is kept in build/gui-parallel/ on failure.
# usage: tools/gui_parallel.sh HAZE [COPIES] [NAME...]   (NAME: only those tests, e.g. record_dmx)
set -uo pipefail
haze=$1
copies=${2:-20}
only=("${@:3}")
root=$(cd "$(dirname "$0")/.." && pwd)
logs=$root/build/gui-parallel
rm -rf "$logs"; mkdir -p "$logs"
failed=0
for script in "$root"/tests/gui/*.sh; do
  name=$(basename "$script" .sh)
  if [ ${#only[@]} -gt 0 ] && [[ ! " ${only[*]} " == *" $name "* ]]; then continue; fi
  t0=$(date +%s)
  pids=()
  for i in $(seq "$copies"); do
    bash "$script" "$haze" "$root" >"$logs/$name-$i.log" 2>&1 &
    pids+=($!)
  done
  bad=0
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || { bad=$((bad + 1)); echo "  $name copy $((i + 1)) failed: $(grep -m1 FAIL "$logs/$name-$((i + 1)).log")"; }
  done
  echo "$name: $((copies - bad)) of $copies copies passed side by side in $(( $(date +%s) - t0 )) s"
  failed=$((failed + bad))
done
[ $failed -eq 0 ] && rm -rf "$logs"
[ $failed -eq 0 ]
