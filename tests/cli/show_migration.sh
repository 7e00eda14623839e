#!/usr/bin/env bash
# A version-1 show migrates to version 2 without loss (docs/show-format.md, "Versions"): `haze
# validate` on the demo as it was in version 1 (tests/data/shows/demo-v1.haze.json) says it
# migrated, `--save-as` writes it as version 2, and `haze state --json` of every cue, at its full
# state and at moments in its delay and fade, is the same byte for byte from the old file and
# from the new one. The bundled demo is the same show rewritten by hand-chosen groups and
# palettes (tools/make_demo_venue.py) plus one effect: without its effect it plays exactly as the
# version-1 file, and the effect moves only the pan and tilt of its group, by at most its size.
# Usage: show_migration.sh HAZE REPO
set -u
haze=$1
repo=$2
demo=$repo/tests/data/shows/demo-v1.haze.json
bundled=$repo/examples/demo/demo.haze.json
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
check "the old demo is version 1 (the test is about a version-1 file)" grep -q '"version": 1,' "$demo"
check "the bundled demo is version 2" grep -q '"version": 2,' "$bundled"
check "the saved copy is version 2" grep -q '"version": 2,' "$tmp/demo.haze.json"
out2=$("$haze" validate "$tmp/demo.haze.json" 2>&1)
rc2=$?
check "the copy validates without a migration note (got $rc2: $out2)" bash -c '[ "$0" -eq 0 ] && ! grep -q migrated <<<"$1"' "$rc2" "$out2"
check "haze validate refuses to overwrite an existing file" bash -c '! "$0" validate "$1" --save-as "$2" >/dev/null 2>&1' \
  "$haze" "$demo" "$tmp/demo.haze.json"

cues=$(node -e 'const s = require(process.argv[1]); for (const c of s.cue_lists[0].cues) console.log(c.number)' "$demo")
[ -n "$cues" ] || { echo "FAIL: no cues read from $demo"; fail=$((fail + 1)); }
# same_states OTHER WHAT MOMENTS...: `haze state --json` of every cue of the version-1 demo, at
# each moment ("" = full state) and in both movement modes, is byte for byte OTHER's.
same_states() {
  local other=$1 what=$2 cue at movement a b
  shift 2
  for cue in $cues; do
    for at in "$@"; do
      for movement in instant real; do
        a=$("$haze" state "$demo" --cue "$cue" $at --movement $movement --json 2>&1)
        b=$("$haze" state "$other" --cue "$cue" $at --movement $movement --json 2>&1)
        if [ -n "$a" ] && [ "$a" = "$b" ] && grep -q '"intensity"' <<<"$a"; then
          passed=$((passed + 1))
        else
          echo "FAIL: haze state --cue $cue $at --movement $movement differs between the version-1 demo and $what"
          diff <(echo "$a") <(echo "$b") | head -5
          fail=$((fail + 1))
        fi
      done
    done
  done
}
same_states "$tmp/demo.haze.json" "its version-2 copy" "" "--at 0.5" "--at 1.5" "--at 3" "--at 6.5"

# The bundled demo without its effects, with its paths made absolute so the copy can live in $tmp.
node -e '
const fs = require("fs"), path = require("path");
const [src, dst] = process.argv.slice(1), dir = path.dirname(src), s = JSON.parse(fs.readFileSync(src, "utf8"));
let effects = 0;
for (const l of s.cue_lists) for (const c of l.cues) if (c.effects) { effects += c.effects.length; delete c.effects; }
if (effects !== 1 || !s.groups.length || !s.palettes.length) { console.error("expected groups, palettes and one effect"); process.exit(1); }
s.venue.gltf = path.resolve(dir, s.venue.gltf);
for (const k in s.profiles) s.profiles[k] = path.resolve(dir, s.profiles[k]);
fs.writeFileSync(dst, JSON.stringify(s, null, 1));' "$bundled" "$tmp/still.haze.json"
check "the bundled demo has groups, palettes and one effect" [ -s "$tmp/still.haze.json" ]
same_states "$tmp/still.haze.json" "the bundled demo's groups and palettes" "" "--at 0.5" "--at 3" "--at 100"
# The effect: a circle of 4 degrees on the Beams, spread round the group, in cue 4.5.
for at in 10 12.5 100; do
  "$haze" state "$tmp/still.haze.json" --cue 4.5 --at $at --json >"$tmp/still.json" 2>&1
  "$haze" state "$bundled" --cue 4.5 --at $at --json >"$tmp/moving.json" 2>&1
  check "cue 4.5 at $at s: the effect moves only the Beams' pan and tilt, on a circle of 4 degrees" node -e '
const [a, b] = process.argv.slice(1).map(f => JSON.parse(require("fs").readFileSync(f, "utf8")));
const beams = ["301", "302", "303", "304"];
let ok = Object.keys(a).length === 12, moved = 0;
for (const id of Object.keys(a)) for (const k of Object.keys(a[id])) {
  const same = JSON.stringify(a[id][k]) === JSON.stringify(b[id][k]);
  if (beams.includes(id) && (k === "pan" || k === "tilt")) continue;
  if (!same) { console.error(id, k, a[id][k], b[id][k]); ok = false; }
}
for (const id of beams) {
  const r = Math.hypot(b[id].pan - a[id].pan, b[id].tilt - a[id].tilt);
  if (Math.abs(r - 4) > 0.06) { console.error(id, "moved", r.toFixed(3), "degrees, not 4"); ok = false; }
  moved++;
}
process.exit(ok && moved === 4 ? 0 : 1);' "$tmp/still.json" "$tmp/moving.json"
done

echo "show_migration: $passed passed, $fail failed"
[ $fail -eq 0 ]
