#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A short, deterministic run of the libFuzzer target of the tool's input path
# (tools/fuzz_tool_input.cpp): clang build with ASan + UBSan, then CTest's
# fuzz_tool_input_short, which runs -seed=1 -runs=$FUZZ_RUNS from the seeds in
# tools/fuzz_seeds/ (one per input format). Same seed, same runs, same inputs:
# a failure here reproduces. Measured on the 2-core machine: about 120 s to build,
# 20 s for 50000 runs. Longer runs, to look for new findings:
#   build-fuzz/tools/fuzz_tool_input -max_total_time=300 -max_len=4096 CORPUS_DIR tools/fuzz_seeds
# Arguments: further CMake options, e.g. -DCE_WARNINGS_AS_ERRORS=ON.
# env: FUZZ_BUILD_DIR (default ./build-fuzz), FUZZ_RUNS (default 50000), JOBS (default nproc).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${FUZZ_BUILD_DIR:-build-fuzz}"
RUNS="${FUZZ_RUNS:-50000}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"

bash scripts/install_dependencies.sh
start=$(date +%s)
# CE_BUILD_TESTS=ON only so that CTest knows the test; only the fuzz target is built.
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCE_BUILD_TESTS=ON -DCE_BUILD_EXAMPLES=OFF -DCE_BUILD_BENCHMARKS=OFF -DCE_BUILD_TOOLS=ON \
  -DCE_BUILD_FUZZERS=ON -DCE_FUZZ_RUNS="$RUNS" "$@"
cmake --build "$BUILD_DIR" -j "$JOBS" --target fuzz_tool_input
built=$(date +%s)
ctest --test-dir "$BUILD_DIR" --output-on-failure -R '^fuzz_tool_input_short$'
echo "run_fuzz.sh: build $((built - start)) s, $RUNS runs $(($(date +%s) - built)) s"
