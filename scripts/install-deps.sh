#!/usr/bin/env bash
# Installs the Debian 12 packages fraktal builds and tests with; installs only what is missing.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libglfw3-dev libglm-dev libopenexr-dev openexr libopencolorio-dev opencolorio-tools
  libimgui-dev libepoxy-dev libegl-dev libegl1-mesa-dev libgles-dev libgl1-mesa-dri mesa-utils
  nlohmann-json3-dev libcli11-dev libstb-dev libgtest-dev glslang-tools
  libopenvdb-dev libopenvdb-tools libboost-iostreams-dev libassimp-dev
  xvfb xauth imagemagick
  xdotool jq
  ffmpeg slurm-wlm munge
  clang libclang-rt-14-dev
  mandelbulber2
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
