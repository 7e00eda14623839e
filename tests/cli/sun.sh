#!/usr/bin/env bash
# atmosphere.sun from the command line (docs/shows.md, "The sun"): a show with a sun validates,
# saves byte-stable (saved twice, the same bytes) with every key kept, renders differently from
# the show without it, the schema takes it; bad values (negative lux, an elevation beyond 90, a
# string for a number, a word for enabled, an unknown key) are refused on one line naming the
# file and the JSON place; `haze bench --sun` gives the cost ratio.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi; }

with() {  # with OUT SUN-JSON: the test show (the Cube venue) in haze, with that sun
  python3 - "$root/tests/data/shows/valid.haze.json" "$1" "$2" <<'PY'
import json, os, sys
s = json.load(open(sys.argv[1]))
here = os.path.dirname(os.path.abspath(sys.argv[1]))
s['venue']['gltf'] = os.path.join(here, s['venue']['gltf'])
s['profiles'] = {k: (os.path.join(here, v) if isinstance(v, str) else v) for k, v in s['profiles'].items()}
s['atmosphere']['scattering'] = 0.05
if sys.argv[3] != 'none':
    s['atmosphere']['sun'] = json.loads(sys.argv[3])
json.dump(s, open(sys.argv[2], 'w'), indent=1)
PY
}

with "$tmp/sun.haze.json" '{"enabled": true, "azimuth": 250, "elevation": 35.5, "illuminance_lux": 42000, "color": [1, 0.9, 0.8]}'
with "$tmp/none.haze.json" none
"$haze" validate "$tmp/sun.haze.json" >"$tmp/out" 2>&1; rc=$?
check "validate takes the sun (rc $rc: $(cat "$tmp/out"))" '[ $rc -eq 0 ]'
"$haze" validate "$tmp/sun.haze.json" --save-as "$tmp/a.haze.json" >/dev/null 2>&1
"$haze" validate "$tmp/a.haze.json" --save-as "$tmp/b.haze.json" >/dev/null 2>&1
check "saved twice, the same bytes" '[ -s "$tmp/a.haze.json" ] && cmp -s "$tmp/a.haze.json" "$tmp/b.haze.json"'
check "the saved show keeps every key of the sun" \
  'python3 -c "import json,sys; s=json.load(open(sys.argv[1]))[\"atmosphere\"][\"sun\"]; sys.exit(not (s == {\"enabled\": True, \"azimuth\": 250, \"elevation\": 35.5, \"illuminance_lux\": 42000, \"color\": [1, 0.9, 0.8]}))" "$tmp/a.haze.json"'

"$haze" render "$tmp/sun.haze.json" --cue 1 --width 80 --height 45 -o "$tmp/s.pfm" 2>"$tmp/err"; rc=$?
check "a render with the sun exits 0 ($(cat "$tmp/err"))" '[ $rc -eq 0 ]'
"$haze" render "$tmp/none.haze.json" --cue 1 --width 80 --height 45 -o "$tmp/n.pfm" 2>/dev/null
check "the sun changes the image" '[ -s "$tmp/s.pfm" ] && [ -s "$tmp/n.pfm" ] && ! cmp -s "$tmp/s.pfm" "$tmp/n.pfm"'
with "$tmp/off.haze.json" '{"enabled": false, "azimuth": 250, "elevation": 35.5, "illuminance_lux": 42000}'
"$haze" render "$tmp/off.haze.json" --cue 1 --width 80 --height 45 -o "$tmp/o.pfm" 2>/dev/null
check "a sun switched off is no sun" '[ -s "$tmp/o.pfm" ] && cmp -s "$tmp/o.pfm" "$tmp/n.pfm"'

# Through a density field the sun renders (the field applies to it: a different image), silently.
python3 - "$tmp/sun.haze.json" "$tmp/dense.haze.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s['atmosphere']['density'] = {'base': 0.5, 'grid': 8, 'still': True}
json.dump(s, open(sys.argv[2], 'w'), indent=1)
PY
"$haze" render "$tmp/dense.haze.json" --cue 1 --width 80 --height 45 -o "$tmp/d.pfm" 2>"$tmp/err"; rc=$?
check "a sun through a density field renders without a warning (rc $rc: $(cat "$tmp/err"))" \
  '[ $rc -eq 0 ] && [ ! -s "$tmp/err" ] && [ -s "$tmp/d.pfm" ] && ! cmp -s "$tmp/d.pfm" "$tmp/s.pfm"'

refused() {  # refused NAME SUN-JSON PLACE
  with "$tmp/bad.haze.json" "$2"
  "$haze" validate "$tmp/bad.haze.json" >"$tmp/out" 2>&1; local rc=$? place=$3
  check "$1 is refused naming file and place (rc $rc: $(cat "$tmp/out"))" \
    '[ $rc -ne 0 ] && [ "$(grep -c /atmosphere/sun "$tmp/out")" -eq 1 ] && grep -qF "bad.haze.json:$place" "$tmp/out"'
}
refused "negative lux" '{"illuminance_lux": -5}' "/atmosphere/sun/illuminance_lux: expected an illuminance in lux from 0 to 1e+06, got -5"
refused "an elevation of 120" '{"elevation": 120}' "/atmosphere/sun/elevation: expected an elevation in degrees above the horizon from -90 to 90, got 120"
refused "a word for the azimuth" '{"azimuth": "west"}' "/atmosphere/sun/azimuth: expected an azimuth"
refused "a word for enabled" '{"enabled": "yes"}' "/atmosphere/sun/enabled: expected true or false"
refused "an unknown key" '{"lux": 5}' "/atmosphere/sun"
refused "a negative colour" '{"color": [1, -1, 0]}' "/atmosphere/sun/color"

ajv=$root/tests/node/node_modules/.bin/ajv
if [ -x "$ajv" ]; then
  schema() { "$ajv" validate --spec=draft2020 -c ajv-formats --strict=true -s "$root/schemas/show.schema.json" -d "$1" >/dev/null 2>&1; }
  check "the schema takes the sun" 'schema "$tmp/sun.haze.json"'
  with "$tmp/bad.haze.json" '{"elevation": 120}'
  check "the schema refuses an elevation of 120" '! schema "$tmp/bad.haze.json"'
else
  fail=$((fail + 1)); echo "FAIL: ajv is missing from tests/node/node_modules; run 'npm ci' in tests/node"
fi

"$haze" bench --fixtures 2 --sun --width 160 --height 90 --frames 1 --json >"$tmp/bench.json" 2>"$tmp/err"
check "bench --sun gives the ratio ($(cat "$tmp/err"))" \
  'python3 -c "import json,sys; d=json.load(open(sys.argv[1]))[\"sun\"]; sys.exit(not (d[\"ratio_frame\"] > 0 and d[\"median_frame_ms\"] > 0))" "$tmp/bench.json"'
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
