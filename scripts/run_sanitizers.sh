#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# AddressSanitizer + UndefinedBehaviorSanitizer build of the tool and of the tests
# that exercise bad input or the tool's own mesh building (test_tool runs the sanitized tool on every bad and
# degenerate input), then CTest on them. Any sanitizer report fails the run.
# Built with clang: GCC 12 took 2 to 2.5 times as long to compile these units with the
# same sanitizers (test_paraboloid_fitting: 280 s of CPU at -O1 -g, clang 127 s at -O2 -g).
# With line tables only (-g1, what the reports' stack traces need): test_paraboloid_fitting 139 s
# against 181 s at -O2 -g, two compiles side by side. -O2 rather than -O1: on one fresh clone, one
# after the other, the tests took 115 s at -O2 -g1 and 128 s at -O1 -g1.
# With clang, every unit also carries libFuzzer's coverage, and the same build runs the short
# deterministic fuzzing of scripts/run_fuzz.sh (fuzz_tool_input_short) on the parts it built
# (CE_FUZZ_BUILT_PARTS): one instrumented build of the tool's parts instead of two. FUZZ_RUNS as there.
# Arguments: further CMake options, e.g. -DCE_WARNINGS_AS_ERRORS=ON.
# env: SAN_BUILD_DIR (default ./build-sanitize), JOBS (default nproc), CXX (default clang++).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${SAN_BUILD_DIR:-build-sanitize}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
TARGETS=(curvature test_tool test_tool_mesh test_paraboloid_fitting)
TESTS='^(test_tool|test_tool_mesh|test_paraboloid_fitting)\.|^tool_'
CXX="${CXX:-clang++}"

bash scripts/install_dependencies.sh
SANITIZERS=address,undefined
FUZZ=()
if "$CXX" --version | grep -q clang; then
  SANITIZERS+=,fuzzer-no-link
  FUZZ=(-DCE_BUILD_FUZZERS=ON -DCE_FUZZ_BUILT_PARTS=ON -DCE_FUZZ_RUNS="${FUZZ_RUNS:-50000}")
  TARGETS+=(fuzz_tool_input)
  TESTS+='|^fuzz_tool_input_short$'
fi
FLAGS="-fsanitize=$SANITIZERS -fno-sanitize-recover=all -fno-omit-frame-pointer"
source scripts/cmake_generator.sh
# shellcheck disable=SC2046 # the generator's options are words
cmake $(cmake_generator "$BUILD_DIR") -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" -DCMAKE_CXX_COMPILER="$CXX" \
  -DCE_BUILD_TESTS=ON -DCE_BUILD_TOOLS=ON -DCE_BUILD_EXAMPLES=OFF -DCE_BUILD_BENCHMARKS=OFF \
  -DCMAKE_CXX_FLAGS="$FLAGS" "${FUZZ[@]}" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" "$@"
cmake --build "$BUILD_DIR" -j "$JOBS" --target "${TARGETS[@]}"

# Leaks are reported too (LeakSanitizer is part of ASan on Linux).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" -R "$TESTS"
