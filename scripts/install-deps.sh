#!/usr/bin/env bash
# Installs what Footfall needs to build and test, from Debian's packages.
# Idempotent: does nothing when everything is already there. Run as root.
set -euo pipefail

packages=(
  cmake g++ make
  pybind11-dev nlohmann-json3-dev libpugixml-dev libcgal-dev libtinygltf-dev python3-dev
  libgtest-dev libbenchmark-dev
  clang libclang-rt-14-dev
  python3-pytest python3-numpy python3-venv
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

# Blender 4.5 LTS and 5.0 as Python modules (PyPI's bpy wheels, built for
# Python 3.11 like Debian's), one virtual environment each, for the Blender
# test tier on those versions. A marker says the install finished.
for version in 4.5 5.0; do
  venv=".venv/bpy-$version"
  if [ ! -f "$venv/installed" ]; then
    echo "Installing Blender $version as a Python module (bpy) into $venv"
    rm -rf "$venv"
    /usr/bin/python3 -m venv "$venv"
    "$venv/bin/pip" install -q --disable-pip-version-check "bpy==$version.*"
    touch "$venv/installed"
  fi
done
