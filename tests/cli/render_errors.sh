#!/usr/bin/env bash
# Bad input to `haze render` gives exactly one clear line on stderr and a non-zero exit:
# a missing show, a show whose venue glTF is broken, an unknown option, a bad number.
set -uo pipefail
haze=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0

expect_error() {  # name, expected text in the line, command...
  local name=$1 want=$2; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  local lines; lines=$(wc -l <"$tmp/err")
  if [ $rc -ne 0 ] && [ "$lines" -eq 1 ] && grep -q -- "$want" "$tmp/err"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1)); echo "FAIL $name: rc=$rc, $lines stderr lines:"; cat "$tmp/err"
  fi
}

expect_error missing-show "no-such.haze.json" "$haze" render "$tmp/no-such.haze.json" -o "$tmp/x.png"
# A copy of the demo whose venue is not glTF.
mkdir -p "$tmp/show/venue"
cp -r "$root/examples/demo/profiles" "$root/examples/demo/gobos" "$tmp/show/"
sed 's#"venue/theatre.gltf"#"venue/broken.gltf"#' "$root/examples/demo/demo.haze.json" >"$tmp/show/demo.haze.json"
echo '{ "asset": { "version": "2.0" }, "buffers": [ { "byteLength": 12' >"$tmp/show/venue/broken.gltf"
expect_error broken-gltf "broken.gltf" "$haze" render "$tmp/show/demo.haze.json" -o "$tmp/x.png"
expect_error unknown-option "--frobnicate" "$haze" render "$root/examples/demo/demo.haze.json" --frobnicate -o "$tmp/x.png"
expect_error bad-width "--width" "$haze" render "$root/examples/demo/demo.haze.json" --width -3 -o "$tmp/x.png"
expect_error unknown-cue "99" "$haze" render "$root/examples/demo/demo.haze.json" --cue 99 -o "$tmp/x.png"
expect_error unknown-camera "Balcony" "$haze" render "$root/examples/demo/demo.haze.json" --camera Balcony --width 32 --height 18 -o "$tmp/x.png"
expect_error bad-extension ".jpg" "$haze" render "$root/examples/demo/demo.haze.json" --width 32 --height 18 -o "$tmp/x.jpg"
expect_error unknown-command "frobnicate" "$haze" frobnicate
[ ! -e "$tmp/x.png" ] || { fail=$((fail + 1)); echo "FAIL: a failed render left an image behind"; }
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
