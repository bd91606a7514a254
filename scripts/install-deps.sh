#!/usr/bin/env bash
# Installs bandlight's build and test dependencies on Debian 12 (bookworm).
# Run as root. Idempotent: packages already present are left as they are.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libopencolorio-dev opencolorio-tools
  libopenimageio-dev openimageio-tools
  catch2 libeigen3-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libbenchmark-dev gnuplot-nox
  colord-data argyll-ref argyll
  clang libclang-rt-14-dev
  glslang-tools libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
  python3 python3-pyopencolorio
  pybind11-dev python3-dev python3-numpy python3-pytest python3-openimageio
  libhwy-dev python3-dask python3-distributed
  blender
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if [[ $(id -u) -ne 0 ]]; then
  echo "install-deps: need root to install: ${missing[*]}" >&2
  exit 1
fi

export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: installed ${missing[*]}"
