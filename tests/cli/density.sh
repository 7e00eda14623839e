#!/usr/bin/env bash
# atmosphere.density from the command line (docs/shows.md, "Density"): `haze state --at` gives
# the field at that time, a render at two times differs as the plume drifts, a grid too large
# and a negative output are refused naming their place, a hazer outside the venue is warned
# about (file and place) by render, state and validate, cues set the hazers' levels, and
# `haze bench --density` gives the cost ratio.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

with() {  # with OUT DENSITY-JSON: the test show (the Cube venue) with that density
  python3 - "$root/tests/data/shows/valid.haze.json" "$1" "$2" <<'PY'
import json, os, sys
s = json.load(open(sys.argv[1]))
here = os.path.dirname(os.path.abspath(sys.argv[1]))
s['venue']['gltf'] = os.path.join(here, s['venue']['gltf'])
s['profiles'] = {k: (os.path.join(here, v) if isinstance(v, str) else v) for k, v in s['profiles'].items()}
s['atmosphere']['density'] = json.loads(sys.argv[3])
json.dump(s, open(sys.argv[2], 'w'), indent=1)
PY
}

with "$tmp/d.haze.json" '{"base": 0.5, "grid": 16, "warmup": 5,
  "hazers": [{"position": [-0.8, 0.2, 0], "direction": [1, 0.3, 0], "output": 0.05, "speed": 1},
             {"position": [30, 1, 0]}]}'
"$haze" state "$tmp/d.haze.json" --cue 1 --at 3 --json >"$tmp/s.json" 2>"$tmp/err"; rc=$?
check "state exits 0 ($(cat "$tmp/err"))" '[ $rc -eq 0 ]'
check "state gives the field at warmup + --at" \
  'python3 -c "import json,sys; a=json.load(open(sys.argv[1]))[\"atmosphere\"]; sys.exit(not (a[\"density_time_s\"] == 8 and a[\"grid\"] == [16, 16, 16] and a[\"max_density\"] > 0.5))" "$tmp/s.json"'
check "the hazer outside the venue is named with file and place" \
  'grep -q "d.haze.json: /atmosphere/density/hazers/1/position: the hazer at \[30, 1, 0\] is outside" "$tmp/err"'

with "$tmp/still.haze.json" '{"base": 0.5, "grid": 16, "still": true, "hazers": [{"position": [-0.8, 0.2, 0], "output": 0.05}]}'
"$haze" validate "$tmp/d.haze.json" >"$tmp/out" 2>"$tmp/err"; rc=$?
check "validate warns about the hazer outside the venue, with file and place, and exits 0 (rc $rc: $(cat "$tmp/err"))" \
  '[ $rc -eq 0 ] && [ "$(grep -c "is outside the density grid" "$tmp/err")" = 1 ] && grep -q "d.haze.json: /atmosphere/density/hazers/1/position: the hazer at \[30, 1, 0\] is outside" "$tmp/err"'
"$haze" validate "$tmp/still.haze.json" >"$tmp/out" 2>"$tmp/err" 
check "validate is silent about a hazer inside the venue ($(cat "$tmp/err"))" '[ ! -s "$tmp/err" ]'

"$haze" render "$tmp/d.haze.json" --cue 1 --at 40 --width 80 --height 45 -o "$tmp/a.pfm" 2>/dev/null
"$haze" render "$tmp/d.haze.json" --cue 1 --at 20 --width 80 --height 45 -o "$tmp/b.pfm" 2>/dev/null
check "renders at two times differ (the haze drifts)" '[ -s "$tmp/a.pfm" ] && [ -s "$tmp/b.pfm" ] && ! cmp -s "$tmp/a.pfm" "$tmp/b.pfm"'
"$haze" render "$tmp/still.haze.json" --cue 1 --at 40 --width 80 --height 45 -o "$tmp/c.pfm" 2>/dev/null
"$haze" render "$tmp/still.haze.json" --cue 1 --at 20 --width 80 --height 45 -o "$tmp/e.pfm" 2>/dev/null
check "a still field is the same at every time" '[ -s "$tmp/c.pfm" ] && cmp -s "$tmp/c.pfm" "$tmp/e.pfm"'

with "$tmp/big.haze.json" '{"grid": [512, 512, 512]}'
"$haze" validate "$tmp/big.haze.json" >"$tmp/out" 2>&1; rc=$?
check "a grid too large is refused naming its place" '[ $rc -ne 0 ] && grep -q "/atmosphere/density/grid: a grid of 512x512x512 cells needs about" "$tmp/out"'
with "$tmp/neg.haze.json" '{"hazers": [{"position": [0, 1, 0], "output": -2}]}'
"$haze" render "$tmp/neg.haze.json" --width 80 --height 45 -o "$tmp/n.pfm" >"$tmp/out" 2>&1; rc=$?
check "a negative output is refused naming its place" '[ $rc -ne 0 ] && grep -q "/atmosphere/density/hazers/0/output" "$tmp/out" && [ ! -e "$tmp/n.pfm" ]'

# The schema knows every key (ajv, as tests/cli/show_schema.sh runs it), and refuses a grid too large.
ajv=$root/tests/node/node_modules/.bin/ajv
if [ -x "$ajv" ]; then
  with "$tmp/full.haze.json" '{"base": 0.3, "grid": [32, 16, 24], "bounds": [[-5, 0, -5], [5, 6, 5]],
    "air_flow": [0.1, 0, -0.2], "mixing": 0.08, "dissipation": 0.01, "warmup": 30, "still": true,
    "fog": {"density": 4, "height": 0.4, "falloff": 0.25},
    "boxes": [{"min": [-1, 0, -1], "max": [1, 2, 1], "density": 2.5}],
    "hazers": [{"position": [4, 0.3, -4], "direction": [-1, 0.2, 0.5], "output": 1.5, "spread": 40, "speed": 3}]}'
  schema() { "$ajv" validate --spec=draft2020 -c ajv-formats --strict=true -s "$root/schemas/show.schema.json" -d "$1" >/dev/null 2>&1; }
  check "the schema takes every density key" 'schema "$tmp/full.haze.json"'
  check "the schema refuses a grid too large" '! schema "$tmp/big.haze.json"'
  check "haze validate takes the same show" '"$haze" validate "$tmp/full.haze.json" >/dev/null 2>&1'
else
  fail=$((fail + 1)); echo "FAIL: ajv is missing from tests/node/node_modules; run 'npm ci' in tests/node"
fi

# Hazers in cues (docs/shows.md, "Hazers in cues"): cue 1 holds the hazer off, cue 2 (delay 1 s,
# fade 4 s) brings it up to full output and half fan.
with "$tmp/cued.haze.json" '{"base": 0.5, "grid": 16, "warmup": 5,
  "hazers": [{"position": [-0.8, 0.2, 0], "direction": [1, 0.3, 0], "output": 0.05, "speed": 1}]}'
python3 - "$tmp/cued.haze.json" "$tmp/off.haze.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s['version'] = 2
cues = s['cue_lists'][0]['cues']
cues[0]['hazers'] = {'1': {'output': 0, 'fan': 0}}
cues[1]['hazers'] = {'1': {'output': 1, 'fan': 0.5}}
cues[1]['delay'] = 1
cues[1]['fade'] = 4
json.dump(s, open(sys.argv[1], 'w'), indent=1)
for c in cues: c.pop('hazers', None)
s['atmosphere']['density']['hazers'][0]['output'] = 0
json.dump(s, open(sys.argv[2], 'w'), indent=1)
PY
"$haze" state "$tmp/cued.haze.json" --cue 2 --at 3 --json >"$tmp/h.json" 2>"$tmp/err"; rc=$?
check "state gives the hazer's levels halfway through the fade: 0.5 and 0.25 (rc $rc: $(cat "$tmp/err"))" \
  'python3 -c "import json,sys; h=json.load(open(sys.argv[1]))[\"atmosphere\"][\"hazers\"]; sys.exit(not (abs(h[0][\"output\"] - 0.5) < 1e-6 and abs(h[0][\"fan\"] - 0.25) < 1e-6))" "$tmp/h.json"'
"$haze" state "$tmp/cued.haze.json" --cue 1 --json >"$tmp/h1.json" 2>/dev/null
"$haze" state "$tmp/cued.haze.json" --cue 2 --json >"$tmp/h2.json" 2>/dev/null
check "a hazer held off by its cue adds no haze; the next cue's does" \
  'python3 -c "import json,sys; a=json.load(open(sys.argv[1]))[\"atmosphere\"]; b=json.load(open(sys.argv[2]))[\"atmosphere\"]; sys.exit(not (a[\"max_density\"] == 0.5 and a[\"hazers\"][0][\"output\"] == 0 and b[\"max_density\"] > 0.5))" "$tmp/h1.json" "$tmp/h2.json"'
"$haze" render "$tmp/cued.haze.json" --cue 1 --width 80 --height 45 -o "$tmp/k1.pfm" 2>/dev/null
"$haze" render "$tmp/off.haze.json" --cue 1 --width 80 --height 45 -o "$tmp/k0.pfm" 2>/dev/null
check "a render of the cue holding the hazer off is the render of a hazer with no output" \
  '[ -s "$tmp/k1.pfm" ] && cmp -s "$tmp/k1.pfm" "$tmp/k0.pfm"'
"$haze" render "$tmp/cued.haze.json" --cue 2 --width 80 --height 45 -o "$tmp/k2.pfm" 2>/dev/null
check "the cue running it renders differently" '[ -s "$tmp/k2.pfm" ] && ! cmp -s "$tmp/k2.pfm" "$tmp/k0.pfm"'
if [ -x "$ajv" ]; then
  check "the schema takes hazer levels in cues" 'schema "$tmp/cued.haze.json"'
fi

"$haze" bench --fixtures 2 --density 16 --width 160 --height 90 --frames 1 --json >"$tmp/bench.json" 2>"$tmp/err"
check "bench --density gives the ratio ($(cat "$tmp/err"))" \
  'python3 -c "import json,sys; d=json.load(open(sys.argv[1]))[\"density\"]; sys.exit(not (d[\"grid\"] == 16 and d[\"ratio_frame\"] > 0 and d[\"median_frame_ms\"] > 0))" "$tmp/bench.json"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
