#!/usr/bin/env bash
# Installs what Footfall needs to build and test, from Debian's packages.
# Idempotent: does nothing when everything is already there. Run as root.
set -euo pipefail

packages=(
  cmake g++ make
  pybind11-dev nlohmann-json3-dev libpugixml-dev libcgal-dev python3-dev
  libgtest-dev libbenchmark-dev
  clang libclang-rt-14-dev
  python3-pytest python3-numpy
  blender
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
# Node.js runs the Khronos glTF validator; a machine may have its own.
command -v npm >/dev/null || missing+=(nodejs npm)
if ((${#missing[@]})); then
  echo "Installing: ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The glTF validator, pinned by tests/gltf/package-lock.json.
cd "$(dirname "$0")/.."
if [ ! -d tests/gltf/node_modules/gltf-validator ]; then
  npm ci --prefix tests/gltf --no-audit --no-fund --loglevel=error >/dev/null
fi
