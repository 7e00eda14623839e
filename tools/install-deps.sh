#!/usr/bin/env bash
# Installs the Debian packages haze needs that are missing (nothing else is downloaded).
# Root runs apt-get directly; anyone else goes through sudo.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libglm-dev nlohmann-json3-dev libstb-dev libtinygltf-dev libpugixml-dev libzip-dev
  libglfw3-dev libimgui-dev libegl-dev libopengl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libassimp-dev liblo-dev liblo-tools ola iproute2 libasound2-dev alsa-utils
  libopenexr-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libcairo2-dev
  librsvg2-dev  # SVG gobos (fixtures/gobo_image.cpp)
  libavahi-client-dev avahi-daemon  # MVR-xchange announced over mDNS (shows/xchange/mdns.cpp)
  xvfb xdotool x11-utils imagemagick ffmpeg poppler-utils libxml2-utils
  qlcplus-data
  chromium  # tests/cli/sheet_html.sh loads the HTML review sheet in it (headless, file:// only)
)
# `make fuzz` (tools/fuzz.sh) asks for libFuzzer too: clang and its runtime.
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang-14 libclang-rt-14-dev)
fi
# `make farm-test` (tests/farm/slurm_farm.sh) runs a one-node Slurm cluster on this machine:
# the controller, the node daemon, the client commands and munge for their authentication.
# Only that target asks for them, so `make test` never installs a cluster manager.
if [ "${1:-}" = "--farm" ]; then
  packages+=(slurmctld slurmd slurm-client munge)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js runs the tests' npm tools; any node and npm on the PATH will do (some machines have
# them from outside Debian, where Debian's npm package would conflict).
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  missing+=(nodejs npm)
fi
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
