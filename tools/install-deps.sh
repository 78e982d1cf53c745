#!/usr/bin/env bash
# Installs the Debian 12 packages shadenet builds and tests with, only those missing.
# Run as root (or through sudo). Safe to run again: it does nothing when all are there.
set -euo pipefail
packages=(
  g++ cmake make pkg-config ccache git
  libluajit-5.1-dev luajit          # the scripting language
  libglfw3-dev                      # --window
  libedit-dev                       # the live console's line editing and history (BSD licence, readline API)
  libglm-dev                        # camera maths
  libtinygltf-dev nlohmann-json3-dev libstb-dev   # glTF meshes
  libopenimageio-dev                # PNG / EXR images
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgbm1   # GL 4.5 core through EGL (llvmpipe without a GPU)
  xvfb xauth                        # windowed tests without a display
  libgtest-dev                      # unit tests
  clang libclang-rt-14-dev          # fuzz targets (tools/fuzz.sh: libFuzzer, ASan, UBSan)
  gnuplot-nox                       # plots
  fonts-dejavu-core                 # figure labels (OpenImageIO render_text; its default DroidSans is not packaged)
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
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
