#!/usr/bin/env bash
# A version-1 show migrates to version 2 without loss (docs/show-format.md, "Versions"): `haze
# validate` on the bundled demo (version 1) says it migrated, `--save-as` writes it as version 2,
# and `haze state --json` of every cue, at its full state and at moments in its delay and fade,
# is the same byte for byte from the old file and from the new one. Usage: show_migration.sh HAZE REPO
set -u
haze=$1
repo=$2
demo=$repo/examples/demo/demo.haze.json
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
passed=0
check() {  # check NAME COMMAND...
  local name=$1
  shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL: $name"; fail=$((fail + 1)); fi
}

out=$("$haze" validate "$demo" --save-as "$tmp/demo.haze.json" 2>&1)
rc=$?
check "haze validate --save-as exits 0 (got $rc: $out)" [ $rc -eq 0 ]
check "haze validate says the version-1 demo was migrated: $out" grep -q "format version 1, migrated to version 2" <<<"$out"
check "the demo is still version 1 (the test is about a version-1 file)" grep -q '"version": 1,' "$demo"
check "the saved copy is version 2" grep -q '"version": 2,' "$tmp/demo.haze.json"
out2=$("$haze" validate "$tmp/demo.haze.json" 2>&1)
rc2=$?
check "the copy validates without a migration note (got $rc2: $out2)" bash -c '[ "$0" -eq 0 ] && ! grep -q migrated <<<"$1"' "$rc2" "$out2"
check "haze validate refuses to overwrite an existing file" bash -c '! "$0" validate "$1" --save-as "$2" >/dev/null 2>&1' \
  "$haze" "$demo" "$tmp/demo.haze.json"

cues=$(node -e 'const s = require(process.argv[1]); for (const c of s.cue_lists[0].cues) console.log(c.number)' "$demo")
[ -n "$cues" ] || { echo "FAIL: no cues read from $demo"; fail=$((fail + 1)); }
for cue in $cues; do
  for at in "" "--at 0.5" "--at 1.5" "--at 3" "--at 6.5"; do
    for movement in instant real; do
      a=$("$haze" state "$demo" --cue "$cue" $at --movement $movement --json 2>&1)
      b=$("$haze" state "$tmp/demo.haze.json" --cue "$cue" $at --movement $movement --json 2>&1)
      if [ -n "$a" ] && [ "$a" = "$b" ] && grep -q '"intensity"' <<<"$a"; then
        passed=$((passed + 1))
      else
        echo "FAIL: haze state --cue $cue $at --movement $movement differs between the version-1 demo and its version-2 copy"
        diff <(echo "$a") <(echo "$b") | head -5
        fail=$((fail + 1))
      fi
    done
  done
done

echo "show_migration: $passed passed, $fail failed"
[ $fail -eq 0 ]
