#!/usr/bin/env bash
# Coverage-guided fuzzing (libFuzzer, with AddressSanitizer and
# UndefinedBehaviorSanitizer): builds the targets of tests/fuzz into
# BUILD_DIR (default build-fuzz) with clang and runs each for SECONDS
# (default 20), starting from its seed corpus in tests/fuzz/corpus/<target>/.
# Usage: scripts/fuzz.sh [SECONDS [TARGET ...]]; without targets, every one:
# the readers and the navigation mesh's updates.
# An input that fails is written to BUILD_DIR/fuzz/findings/<target>/; once
# the fault is fixed, add it to the target's corpus, where every run replays it.
# FUZZ_SEED (default 1) fixes the mutations, so that the test command gives the
# same verdict on every machine that gets as far in its time; FUZZ_SEED=0 draws
# a new seed each run, for exploring (docs/notes/hostile-input.md).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
build_dir=${BUILD_DIR:-build-fuzz}
seed=${FUZZ_SEED:-1}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
  -DFOOTFALL_FUZZ=ON -DFOOTFALL_BUILD_TESTS=OFF -DFOOTFALL_BUILD_PYTHON=OFF \
  -DFOOTFALL_BUILD_BENCHMARKS=OFF >/dev/null
shift $(($# > 0 ? 1 : 0))
targets=("$@")
((${#targets[@]})) || targets=(fuzz_scenario_json fuzz_steersuite_xml fuzz_plan_json fuzz_rig_gltf fuzz_rig_profile
                          fuzz_navmesh_updates)
cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]}"

status=0
for target in "${targets[@]}"; do
  found="$build_dir/fuzz/findings/$target"
  scratch=$(mktemp -d)  # new inputs go here, not into the repository's corpus
  mkdir -p "$found"
  # -timeout: an input that takes 30 s is a finding too (a cost that explodes).
  if "$build_dir/fuzz/$target" -max_total_time="$seconds" -seed="$seed" -timeout=30 -rss_limit_mb=4096 \
      -max_len=8192 -print_final_stats=1 -artifact_prefix="$found/" \
      "$scratch" "tests/fuzz/corpus/$target" >"$found/log.txt" 2>&1; then
    echo "fuzz: $target: $(grep -m1 -o 'cov: [0-9]*' <(tac "$found/log.txt")) edges," \
         "$(grep -o 'average_exec_per_sec: *[0-9]*' "$found/log.txt" | grep -o '[0-9]*$') runs/s"
  else
    echo "fuzz: $target FAILED; the input and the log are in $found" >&2
    tail -30 "$found/log.txt" >&2
    status=1
  fi
  rm -rf "$scratch"
done
exit $status
