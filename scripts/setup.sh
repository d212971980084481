#!/usr/bin/env bash
# The first README command: install, build, and run the main job on the
# built-in demo (a character through a doorway and around a box), which writes
# out/demo-plan.json and prints a table.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/footfall demo -o out/demo-plan.json
