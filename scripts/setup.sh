#!/usr/bin/env bash
# The first README command: install, build, and run the main job on the
# built-in demo (a crowd up three steps and through a doorway, one walker holding its arms in and
# one side-stepping through narrow gaps): the planner
# writes out/demo-plan.json and prints a table; Blender animates the project's
# rig on it and writes out/demo.png (a render), out/demo.glb (the animated
# character) and out/demo.blend.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/footfall demo -o out/demo-plan.json
blender -b --factory-startup -noaudio --python-exit-code 1 --python scripts/demo.py -- out 2>&1 |
  grep -E "^(demo:|Error)"
