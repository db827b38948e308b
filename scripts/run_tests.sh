#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Configure (Release, tests + examples ON), build everything, run CTest.
# Arguments: further CMake options, e.g. -DCE_WARNINGS_AS_ERRORS=ON.
# env: BUILD_DIR (default ./build), JOBS (default nproc),
#      CGAL_DIR (a CGAL other than the system's, e.g. ../shared/cgal-6.1.1/lib/cmake/CGAL;
#      the downstream tests use it too), CE_BUILD_BENCHMARKS (default ON).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"

cgal=()
if [ -n "${CGAL_DIR:-}" ]; then
  cgal=(-DCGAL_DIR="$CGAL_DIR")
fi

bash scripts/install_dependencies.sh
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${cgal[@]}" \
  -DCE_BUILD_TESTS=ON -DCE_BUILD_EXAMPLES=ON -DCE_BUILD_BENCHMARKS="${CE_BUILD_BENCHMARKS:-ON}" "$@"
cmake --build "$BUILD_DIR" -j "$JOBS"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
