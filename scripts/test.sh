#!/usr/bin/env bash
# The second README command: every test. Installs and builds what it needs;
# runs all three tiers (GoogleTest, pytest, Blender background tests), then
# the native and Python tiers again built with AddressSanitizer and
# UndefinedBehaviorSanitizer, and the native tier built with ThreadSanitizer
# (the crowd plans on a pool of threads, pipelining its ticks); last, a short
# run of each fuzzing target (tests/fuzz) under the sanitizers.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"

# The sanitized module goes to a folder of its own, so it never replaces the
# one that Blender loads from blender_addon/footfall.
BUILD_DIR=build-sanitize scripts/build.sh -DFOOTFALL_SANITIZE=ON
ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" -L 'native|python'

# Without address-space randomisation: ThreadSanitizer cannot map its shadow
# memory beside the randomised layouts of some kernels.
BUILD_DIR=build-tsan scripts/build.sh -DFOOTFALL_TSAN=ON -DFOOTFALL_BUILD_PYTHON=OFF \
  -DFOOTFALL_BUILD_BENCHMARKS=OFF
setarch "$(uname -m)" -R ctest --test-dir build-tsan --output-on-failure -j "$(nproc)" -L native

# Coverage-guided fuzzing of every reader and of the navigation mesh's
# updates, 20 s a target, replaying the seed and regression corpus first.
scripts/fuzz.sh 20
