#!/usr/bin/env bash
# `haze fixture info FILE --json` on a native profile, an IES, an LDT and a GDTF file: the facts are
# JSON with the documented keys and the values the files imply; a bad file is one stderr line
# and exit 1. Also validates the native profile against schemas/fixture.schema.json.
# Usage: bash fixture_info.sh <haze-binary> <repo-root>
set -u
haze="$1"
repo="$2"
source "$repo/tests/cli/test_data.bash"
node_dir="$repo/tests/node"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cat > "$tmp/par.json" <<'JSON'
{
  "format": "haze-fixture",
  "version": 1,
  "manufacturer": "Haze Tests",
  "name": "Par 20/35",
  "photometry": { "beam_angle": 20, "field_angle": 35, "peak_candela": 12000 },
  "zoom": { "min": 10, "max": 50 },
  "color": { "mixing": "rgb" },
  "modes": [ { "name": "6ch", "channels": [ "Dimmer", "Red", "Green", "Blue", "Zoom", "Strobe" ] } ]
}
JSON

# The profile is valid against the schema (and a broken one is not).
if [ -x "$node_dir/node_modules/.bin/ajv" ]; then
  (cd "$node_dir" && node_modules/.bin/ajv validate --spec=draft2020 -c ajv-formats --strict=true -s "$repo/schemas/fixture.schema.json" -d "$tmp/par.json" >/dev/null 2>&1) \
    || fail "par.json does not validate against fixture.schema.json"
  sed 's/"rgb"/"hsv"/' "$tmp/par.json" > "$tmp/bad-schema.json"
  (cd "$node_dir" && node_modules/.bin/ajv validate --spec=draft2020 -c ajv-formats --strict=true -s "$repo/schemas/fixture.schema.json" -d "$tmp/bad-schema.json" >/dev/null 2>&1) \
    && fail "the schema accepts colour mixing \"hsv\""
fi

# check FILE 'js expression over f (the facts)' ...
check() {
  local file="$1"; shift
  "$haze" fixture info "$file" --json > "$tmp/out.json" 2> "$tmp/err.txt" || fail "fixture info $file exited $?: $(cat "$tmp/err.txt")"
  for expr in "$@"; do
    node -e "const f = JSON.parse(require('fs').readFileSync('$tmp/out.json', 'utf8')); if (!($expr)) { console.error(JSON.stringify(f)); process.exit(1); }" \
      || fail "$file: expected $expr"
  done
}

keys='["name","manufacturer","peak_candela","lumens","beam_angle","beam_angle_c0","beam_angle_c90","field_angle","field_angle_c0","field_angle_c90","symmetry","grid"].every(k => k in f)'

check "$tmp/par.json" "$keys" \
  "f.name === 'Par 20/35'" "f.manufacturer === 'Haze Tests'" \
  "Math.abs(f.peak_candela - 12000) < 0.5" \
  "Math.abs(f.beam_angle - 20) < 0.05" "Math.abs(f.field_angle - 35) < 0.05" \
  "Math.abs(f.beam_angle_c0 - f.beam_angle_c90) < 1e-3" \
  "f.symmetry === 'axial'" "f.zoom.min === 10 && f.zoom.max === 50" \
  "f.modes[0].name === '6ch' && f.modes[0].footprint === 6" \
  "f.modes[0].channels.length === 6 && f.modes[0].channels[0].offset === 1 && f.modes[0].channels[0].attribute === 'intensity'" \
  "f.modes[0].channels[4].attribute === 'zoom' && f.modes[0].channels[4].range[0] === 10 && f.modes[0].channels[4].range[1] === 50" \
  "f.modes[0].channels[5].name === 'Strobe' && f.modes[0].channels[5].attribute === 'none'" \
  "f.lumens > 500 && f.lumens < 5000" \
  "f.lens_radius === 0.05 && f.lens_radius_source === 'default'" \
  "f.body.source === 'default' && f.body.base === null && f.body.head.size[0] === 0.16 && f.body.head.center[1] === 0.16"

# SOURCES.md: Ansorg stage spot, axial, 37 gammas, peak ~42,000 cd, FWHM ~10 degrees.
check "$(data_path photometry/ies/hydraapi/ies_34.ies)" "$keys" \
  "f.manufacturer === 'Ansorg GmbH'" "f.symmetry === 'axial'" "f.grid.gamma === 37 && f.grid.c === 1" \
  "f.peak_candela > 40000 && f.peak_candela < 44000" "f.beam_angle > 8 && f.beam_angle < 12" \
  "f.field_angle > f.beam_angle"

# SOURCES.md: Regent NEO U LED12800, no symmetry, 24 C x 37 gamma; 12,800 lm luminaire.
check "$(data_path photometry/ldt/eulumdat-py/sample3.ldt)" "$keys" \
  "f.manufacturer === 'Regent'" "f.symmetry === 'none'" "f.grid.gamma === 37 && f.grid.c === 24" \
  "Math.abs(f.lumens - 12800) < 128" \
  "Math.abs(f.lens_radius - 0.2437) < 1e-3 && f.lens_radius_source === 'ldt'"  # 594 x 314 mm, the same area

# GDTF goes through the same loadProfile (fixtures/gdtf.h): facts come out with the same keys.
par=$(data_path "gdtf/BlenderDMX@LED_PAR_64_RGBW@v0.3.gdtf")
check "$par" "$keys" "f.name === 'LED PAR 64 RGBW'" "f.manufacturer === 'BlenderDMX'" "f.peak_candela > 0 && f.lumens > 0" \
  "f.lens_radius === 0.1 && f.lens_radius_source === 'gdtf'"
beskyd_rel="gdtf/BlenderDMX@BeskydBeam@version10.gdtf"
if want_data "$beskyd_rel"; then
  beskyd=$(data_path "$beskyd_rel")
  check "$beskyd" "$keys" \
    "f.name === 'BeskydBeam'" "f.manufacturer === 'BlenderDMX'" "f.peak_candela > 0 && f.lumens > 0" \
    "f.lens_radius === 0.08 && f.lens_radius_source === 'gdtf'" \
    "f.body.source === 'gdtf' && JSON.stringify(f.body.head.size) === '[0.224,0.244,0.186]' && f.body.base.size[1] === 0.13"

  # A body in the text form too.
  "$haze" fixture info "$beskyd" > "$tmp/out.txt" 2>&1 || fail "fixture info (text) failed"
  grep -q "^  body (gdtf): base 0.3 x 0.13 x 0.3 m yoke arm .* head 0.224 x 0.244 x 0.186 m$" "$tmp/out.txt" ||
    fail "the text form does not show the body: $(grep body "$tmp/out.txt")"
  check "$beskyd" "f.body.models.length === 0"
fi

# Body models (docs/fixtures.md, "Bodies"): the BMFL's three .3ds files and the PAR's .glb are
# listed with their triangles and sizes (each fitted to its GDTF Model's dimensions).
check "$par" \
  "f.body.models.length === 1 && f.body.models[0].file === 'models/gltf/Body.glb' && f.body.models[0].part === 'head'"
bmfl_rel="gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"
if want_data "$bmfl_rel"; then
  bmfl=$(data_path "$bmfl_rel")
  check "$bmfl" \
    "f.body.models.length === 3" \
    "f.body.models.map(m => m.part + ':' + m.file).join(',') === 'base:models/3ds/base.3ds,yoke:models/3ds/yoke.3ds,head:models/3ds/head.3ds'" \
    "f.body.models.every(m => m.triangles > 10)" \
    "JSON.stringify(f.body.models[2].size) === '[0.34,0.613,0.23]'"
  "$haze" fixture info "$bmfl" > "$tmp/out.txt" 2>&1 || fail "fixture info (text) failed on the BMFL"
  grep -q "^    head model models/3ds/head.3ds: [0-9]* triangles, 0.34 x 0.613 x 0.23 m$" "$tmp/out.txt" ||
    fail "the text form does not list the body models: $(grep model "$tmp/out.txt")"

  # Bad input: a BMFL whose head.3ds is missing and whose yoke.3ds is broken imports, with a
  # warning naming each file; those parts are boxes (the Model's size), the base keeps its mesh.
  python3 - "$bmfl" "$tmp/bmfl_broken.gdtf" <<'PY'
import sys, zipfile
src = zipfile.ZipFile(sys.argv[1])
with zipfile.ZipFile(sys.argv[2], 'w', zipfile.ZIP_DEFLATED) as out:
    for name in src.namelist():
        if name == 'models/3ds/head.3ds':
            continue
        out.writestr(name, b'not a 3ds file' if name == 'models/3ds/yoke.3ds' else src.read(name))
PY
  check "$tmp/bmfl_broken.gdtf" \
    "f.body.models.length === 1 && f.body.models[0].file === 'models/3ds/base.3ds'" \
    "f.warnings.some(w => w.includes(\"model file 'head'\") && w.includes('models/3ds/head.3ds'))" \
    "f.warnings.some(w => w.includes('models/3ds/yoke.3ds'))" \
    "JSON.stringify(f.body.head.size) === '[0.34,0.613,0.23]' && f.body.yoke_left !== null && f.body.yoke_right !== null"
fi

# A native lens_radius wins over the default.
sed 's/"zoom"/"lens_radius": 0.07, "zoom"/' "$tmp/par.json" > "$tmp/par_lens.json"
check "$tmp/par_lens.json" "f.lens_radius === 0.07 && f.lens_radius_source === 'profile'"

# Bad input: one line on stderr naming the file and the line, exit status 1, nothing on stdout.
printf 'IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 1 2 2 0 0 0\n1 1 0\n0 45 90\n0\n10 5 0\n' > "$tmp/typeb.ies"
"$haze" fixture info "$tmp/typeb.ies" --json > "$tmp/out.txt" 2> "$tmp/err.txt"
status=$?
[ "$status" -eq 1 ] || fail "a type B IES file exited $status, expected 1"
[ "$(wc -l < "$tmp/err.txt")" -eq 1 ] || fail "expected one stderr line, got: $(cat "$tmp/err.txt")"
grep -q "typeb.ies:line 3: photometric type B" "$tmp/err.txt" || fail "unexpected error: $(cat "$tmp/err.txt")"
[ ! -s "$tmp/out.txt" ] || fail "stdout is not empty on error"

"$haze" fixture info "$tmp/missing.ldt" --json > /dev/null 2> "$tmp/err.txt" && fail "a missing file exited 0"
[ "$(wc -l < "$tmp/err.txt")" -eq 1 ] || fail "expected one stderr line for a missing file"
"$haze" fixture info > /dev/null 2> "$tmp/err.txt" && fail "no file exited 0"
grep -q "usage" "$tmp/err.txt" || fail "no usage line without a file"
echo "fixture_info: ok"
data_exit 0
