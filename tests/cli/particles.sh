#!/usr/bin/env bash
# atmosphere.particles from the command line (docs/shows.md, "Particles"): a PNG follows the
# show and --particles / --no-particles switch it; a PFM has none unless asked for by name, and
# then the command says what its pixels hold; the same --at gives the same file, another --at
# another; a bad value names its place; bench --compare-particles gives the ratio and the count.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

with() {  # with OUT PARTICLES-JSON: the test show (the Cube venue) with those particles
  python3 - "$root/tests/data/shows/valid.haze.json" "$1" "$2" <<'PY'
import json, os, sys
s = json.load(open(sys.argv[1]))
here = os.path.dirname(os.path.abspath(sys.argv[1]))
s['venue']['gltf'] = os.path.join(here, s['venue']['gltf'])
s['profiles'] = {k: (os.path.join(here, v) if isinstance(v, str) else v) for k, v in s['profiles'].items()}
s['atmosphere']['particles'] = json.loads(sys.argv[3])
json.dump(s, open(sys.argv[2], 'w'), indent=1)
PY
}
render() { "$haze" render "$1" --cue 1 --width 160 --height 90 "${@:2}"; }

with "$tmp/on.haze.json" '{"enabled": true, "density": 400, "brightness": 20000}'
render "$tmp/on.haze.json" -o "$tmp/on.png" 2>"$tmp/err"; rc=$?
check "render with particles exits 0 ($(cat "$tmp/err"))" '[ $rc -eq 0 ] && [ -s "$tmp/on.png" ]'
render "$tmp/on.haze.json" --no-particles -o "$tmp/off.png" 2>/dev/null
check "--no-particles changes the PNG of a show that has them on" '[ -s "$tmp/off.png" ] && ! cmp -s "$tmp/on.png" "$tmp/off.png"'
render "$tmp/on.haze.json" -o "$tmp/plain.pfm" 2>"$tmp/err"
render "$tmp/on.haze.json" --no-particles -o "$tmp/none.pfm" 2>/dev/null
check "a PFM has no particles unless asked, and says nothing about them" \
  '[ -s "$tmp/plain.pfm" ] && cmp -s "$tmp/plain.pfm" "$tmp/none.pfm" && ! grep -q particles "$tmp/err"'
render "$tmp/on.haze.json" --particles --at 2 -o "$tmp/p2.pfm" 2>"$tmp/err"
check "a PFM with --particles differs and the note says what its pixels hold ($(cat "$tmp/err"))" \
  '[ -s "$tmp/p2.pfm" ] && ! cmp -s "$tmp/p2.pfm" "$tmp/none.pfm" && grep -q "p2.pfm: --particles adds visible dust on top of the radiance" "$tmp/err"'
render "$tmp/on.haze.json" --particles --at 2 -o "$tmp/p2b.pfm" 2>/dev/null
check "the same --at gives the same file" 'cmp -s "$tmp/p2.pfm" "$tmp/p2b.pfm"'
render "$tmp/on.haze.json" --particles --at 9 -o "$tmp/p9.pfm" 2>/dev/null
check "another --at moves them" '[ -s "$tmp/p9.pfm" ] && ! cmp -s "$tmp/p2.pfm" "$tmp/p9.pfm"'
render "$tmp/on.haze.json" --particles --no-particles -o "$tmp/x.png" >/dev/null 2>"$tmp/err"; rc=$?
check "--particles with --no-particles is refused" '[ $rc -ne 0 ] && grep -q "exclude each other" "$tmp/err"'

with "$tmp/bad.haze.json" '{"enabled": true, "density": -3}'
"$haze" validate "$tmp/bad.haze.json" >/dev/null 2>"$tmp/err"; rc=$?
check "a negative density is refused naming its place ($(cat "$tmp/err"))" \
  '[ $rc -ne 0 ] && grep -q "bad.haze.json:/atmosphere/particles/density: expected particles per m^3 from 0 to 5000, got -3" "$tmp/err"'

ajv=$root/tests/node/node_modules/.bin/ajv
if [ -x "$ajv" ]; then
  schema() { "$ajv" validate --spec=draft2020 -c ajv-formats --strict=true -s "$root/schemas/show.schema.json" -d "$1" >/dev/null 2>&1; }
  with "$tmp/full.haze.json" '{"enabled": true, "density": 20, "size_um": 60, "size_sigma": 0.3, "brightness": 500, "seed": 7}'
  check "the schema takes every particles key" 'schema "$tmp/full.haze.json"'
  check "the schema refuses a negative density" '! schema "$tmp/bad.haze.json"'
fi

"$haze" bench --fixtures 2 --compare-particles --width 160 --height 90 --frames 1 --json >"$tmp/bench.json" 2>"$tmp/err"
check "bench --compare-particles gives the ratio and the count ($(cat "$tmp/err"))" \
  'python3 -c "import json,sys; d=json.load(open(sys.argv[1]))[\"particles\"]; sys.exit(not (d[\"drawn\"] > 0 and d[\"ratio_frame\"] > 0 and d[\"limit\"] == 200000))" "$tmp/bench.json"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
