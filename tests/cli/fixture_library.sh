#!/usr/bin/env bash
# The fixture library on Debian's qlcplus-data: `fixture search` forgiving case, spaces and
# hyphens, its cache, `fixture info` on a .qxf checked against the XML (read here with node, not
# through haze), and `fixture change-type` on ten demo fixtures: every cue still plays with pan
# and tilt as before (within the new range), the saved show validates, undo gives it back byte
# for byte, and an overlapping footprint is refused with the list.
# Usage: bash fixture_library.sh <haze-binary> <repo-root>
set -u
haze="$1"
repo="$2"
qlc=/usr/share/qlcplus/fixtures
[ -d "$qlc" ] || { echo "skipped: qlcplus-data is not installed ($qlc; tools/install-deps.sh installs it)"; exit 77; }
command -v node >/dev/null || { echo "skipped: node is not installed (tools/install-deps.sh installs it)"; exit 77; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export XDG_CACHE_HOME="$tmp/cache"
unset HAZE_FIXTURE_PATH

# js FILE 'expression over j (the JSON)' ...
js() {
  local file="$1"; shift
  for expr in "$@"; do
    node -e "const j = JSON.parse(require('fs').readFileSync('$file', 'utf8')); if (!($expr)) { console.error(JSON.stringify(j).slice(0, 2000)); process.exit(1); }" \
      || fail "$file: expected $expr"
  done
}

# Search: words in any case, spaces and hyphens ignored.
"$haze" fixture search "robin 600" --json > "$tmp/robin.json" 2> "$tmp/err.txt" || fail "search exited $?: $(cat "$tmp/err.txt")"
js "$tmp/robin.json" "j.some(e => e.manufacturer === 'Robe' && e.name === 'Robin 600E Spot (v1.1)' && e.file === '$qlc/Robe/Robe-Robin-600E-Spot.qxf')" \
  "j.every(e => /robin/i.test(e.name))"
"$haze" fixture search "ROBE-robin600e spot" --json > "$tmp/robin2.json" || fail "search with hyphens exited $?"
js "$tmp/robin2.json" "j.length >= 1 && j[0].name === 'Robin 600E Spot (v1.1)'"
"$haze" fixture search alphaspot --json > "$tmp/alpha.json" || fail "search alphaspot exited $?"
js "$tmp/alpha.json" "j.length >= 1 && j.every(e => /alpha ?spot/i.test(e.name))" "j.some(e => e.manufacturer === 'Clay Paky')"
"$haze" fixture search "no such fixture anywhere" --json > "$tmp/none.json" || fail "an empty search exited $?"
js "$tmp/none.json" "j.length === 0"

# The second index comes from the cache: nothing read again, well under 2 s.
start=$(date +%s%N)
"$haze" fixture search "robin" --stats > /dev/null 2> "$tmp/stats.txt" || fail "search --stats exited $?"
ms=$(( ($(date +%s%N) - start) / 1000000 ))
grep -q "(0 read, [0-9]* from the cache)" "$tmp/stats.txt" || fail "the second index was not cached: $(cat "$tmp/stats.txt")"
[ "$ms" -lt 2000 ] || fail "a cached search took $ms ms; expected under 2000"
echo "cached search: $ms ms ($(cat "$tmp/stats.txt"))"

# fixture info on a .qxf: the facts the XML gives, read from the XML by node.
robin="$qlc/Robe/Robe-Robin-600E-Spot.qxf"
"$haze" fixture info "$robin" --mode "Mode 3" --json > "$tmp/info.json" 2> "$tmp/err.txt" || fail "info exited $?: $(cat "$tmp/err.txt")"
cat > "$tmp/xml.js" <<'JS'
// attr(xml, element, name): the attribute as written; modeChannels(xml, mode): <Channel> count.
const fs = require('fs');
const xml = fs.readFileSync(process.argv[2], 'utf8');
const attr = (el, name) => Number(new RegExp('<' + el + '\\b[^>]*\\b' + name + '="([^"]*)"').exec(xml)[1]);
const mode = process.argv[3];
const body = new RegExp('<Mode Name="' + mode + '">([\\s\\S]*?)</Mode>').exec(xml)[1];
console.log(JSON.stringify({ panMax: attr('Focus', 'PanMax'), tiltMax: attr('Focus', 'TiltMax'),
  dmin: attr('Lens', 'DegreesMin'), dmax: attr('Lens', 'DegreesMax'), lumens: attr('Bulb', 'Lumens'),
  channels: (body.match(/<Channel /g) || []).length }));
JS
node "$tmp/xml.js" "$robin" "Mode 3" > "$tmp/xml.json" || fail "reading $robin with node"
x="JSON.parse(require('fs').readFileSync('$tmp/xml.json', 'utf8'))"
js "$tmp/info.json" "j.name === 'Robin 600E Spot (v1.1)' && j.manufacturer === 'Robe'" \
  "j.modes.length === 1 && j.modes[0].name === 'Mode 3' && j.modes[0].footprint === $x.channels" \
  "j.pan.max - j.pan.min === $x.panMax && j.tilt.max - j.tilt.min === $x.tiltMax" \
  "j.zoom.min === $x.dmin && j.zoom.max === $x.dmax" \
  "Math.abs(j.lumens - $x.lumens) < 0.02 * $x.lumens" \
  "!('defaults' in j)" \
  "j.gobo_wheels.length === 2 && j.gobo_wheels[0].slots.includes('Gobo 5')" \
  "j.color_wheels[0].slots.includes('Deep Blue') && j.prisms.length >= 1 && j.frost !== null"
"$haze" fixture info "$robin" --mode "Mode 9" --json > /dev/null 2> "$tmp/err.txt" && fail "an unknown mode was accepted"
grep -q 'no mode "Mode 9"; its modes are: "Mode 1", "Mode 2", "Mode 3"' "$tmp/err.txt" || fail "unknown mode: $(cat "$tmp/err.txt")"
# A definition without lens degrees says which facts are defaults.
leda="$qlc/Clay_Paky/Clay-Paky-A.LEDA-Wash-K20.qxf"
grep -q 'DegreesMax="0"' "$leda" || fail "$leda gives its lens degrees now; pick another file"
"$haze" fixture info "$leda" --json > "$tmp/leda.json" 2>/dev/null || fail "info on $leda exited $?"
js "$tmp/leda.json" "j.defaults.includes('field_angle') && !j.defaults.includes('lumens')"
"$haze" fixture info "$leda" 2>/dev/null | grep -q "defaults (not in the file): field_angle" || fail "the text output does not list the defaults"

# Change type: ten demo fixtures become a QLC+ spot whose 8 slots fit the demo's patch.
cp -r "$repo/examples/demo" "$tmp/demo"
show="$tmp/demo/demo.haze.json"
out="$tmp/demo/changed.haze.json"
"$haze" fixture change-type "$show" --fixtures 101-104,201-204,301-302 --type "Robe Spot 160 XT" --mode "8-channel, 16-Bit" \
  -o "$out" --verify-undo > "$tmp/change.txt" 2>&1 || fail "change-type exited $?: $(cat "$tmp/change.txt")"
grep -q '^changed 10 fixtures to Robe Spot 160 XT' "$tmp/change.txt" || fail "change-type said: $(head -3 "$tmp/change.txt")"
grep -q 'gobo "Leaves" is not on the new type' "$tmp/change.txt" || fail "the report does not list the gobo it could not map"
grep -q '^undo gives the show back byte for byte' "$tmp/change.txt" || fail "undo check: $(tail -2 "$tmp/change.txt")"
"$haze" validate "$out" > "$tmp/validate.txt" 2>&1 || fail "the changed show does not validate: $(cat "$tmp/validate.txt")"
for cue in 1 2 3 4 4.5 5; do
  "$haze" state "$show" --cue "$cue" --at 10 --json > "$tmp/was-$cue.json" 2>"$tmp/err.txt" || fail "state of the demo, cue $cue: $(cat "$tmp/err.txt")"
  "$haze" state "$out" --cue "$cue" --at 10 --json > "$tmp/now-$cue.json" 2>"$tmp/err.txt" || fail "state after the change, cue $cue: $(cat "$tmp/err.txt")"
  node -e "
    const fs = require('fs');
    const was = JSON.parse(fs.readFileSync('$tmp/was-$cue.json', 'utf8')), now = JSON.parse(fs.readFileSync('$tmp/now-$cue.json', 'utf8'));
    const clamp = (v, lo, hi) => Math.min(hi, Math.max(lo, v));
    for (const id of ['101','102','103','104','201','202','203','204','301','302']) {
      // Robe Spot 160 XT: PanMax 530, TiltMax 280 (its Physical block).
      const pan = clamp(was[id].pan, -265, 265), tilt = clamp(was[id].tilt, -140, 140);
      if (Math.abs(now[id].pan - pan) > 1e-3 || Math.abs(now[id].tilt - tilt) > 1e-3 || Math.abs(now[id].intensity - was[id].intensity) > 1e-6) {
        console.error('cue $cue fixture ' + id + ': was ' + JSON.stringify(was[id]).slice(0, 200) + ' now ' + JSON.stringify(now[id]).slice(0, 200));
        process.exit(1);
      }
    }" || fail "cue $cue does not play as before"
done
grep -q 'PanMax="530" TiltMax="280"' "$qlc/Robe/Robe-Spot-160-XT.qxf" || fail "the Spot 160 XT's ranges changed; update the clamp above"

# A footprint that overlaps the next fixture is refused, with the list, and nothing is written.
cp "$show" "$tmp/before.json"
"$haze" fixture change-type "$show" --fixtures 101-104 --type "Robe Robin 600E Spot" --mode "Mode 1" > "$tmp/refused.txt" 2>&1 \
  && fail "an overlapping footprint was accepted"
grep -q 'fixture 102 (universe 1 13-44) overlaps fixture 101 (universe 1 1-32)' "$tmp/refused.txt" || fail "refusal: $(cat "$tmp/refused.txt")"
cmp -s "$show" "$tmp/before.json" || fail "a refused change wrote the show"
# An imported rig whose GDTF files are stubs: the types the library has are matched, the rest
# said; --keep-embedded keeps them all.
source "$repo/tests/cli/test_data.bash"
if mvr=$(data_path gdtf/mvr/capture_demo_show.mvr); then
  "$haze" import-mvr "$mvr" -o "$tmp/cap/cap.haze.json" --no-venue > "$tmp/mvr.txt" 2> "$tmp/err.txt" || fail "import-mvr exited $?: $(cat "$tmp/err.txt")"
  grep -q "(ADB ALC4): a stub, matched to the library's ADB ALC4 ($qlc/ADB/ADB-ALC4.qxf)" "$tmp/mvr.txt" || fail "ALC4 not matched: $(cat "$tmp/mvr.txt")"
  grep -q "(Clay Paky A.leda Wash K20): a stub, matched to the library's Clay Paky A.LEDA Wash K20" "$tmp/mvr.txt" || fail "K20 not matched"
  grep -q 'no library fixture is named "Robe Robin MMX Spot"' "$tmp/mvr.txt" || fail "the unmatched MMX Spot is not said"
  [ "$(grep -c '^fixture type ' "$tmp/mvr.txt")" -eq 5 ] || fail "expected one line per fixture type: $(cat "$tmp/mvr.txt")"
  "$haze" validate "$tmp/cap/cap.haze.json" > /dev/null 2>&1 || fail "the matched rig does not validate"
  grep -q "\"$qlc/ADB/ADB-ALC4.qxf\"" "$tmp/cap/cap.haze.json" || fail "the show does not refer to the library's ALC4"
  "$haze" import-mvr "$mvr" -o "$tmp/keep/cap.haze.json" --no-venue --keep-embedded > "$tmp/keep.txt" 2>/dev/null || fail "--keep-embedded exited $?"
  [ "$(grep -c 'kept as embedded' "$tmp/keep.txt")" -eq 5 ] || fail "--keep-embedded: $(cat "$tmp/keep.txt")"
  grep -q "qlcplus" "$tmp/keep/cap.haze.json" && fail "--keep-embedded still refers to the library"
else
  want_data gdtf/mvr/capture_demo_show.mvr
fi
echo "fixture library: search, info, change-type and MVR matching OK"
data_exit 0
