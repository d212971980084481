#!/usr/bin/env bash
# Configures and builds Footfall into BUILD_DIR (default build/); extra
# arguments go to cmake, e.g. -DFOOTFALL_SANITIZE=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
