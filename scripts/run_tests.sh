#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Configure (Release, tests + examples ON), build everything, run CTest, then the Python
# package's tests: pip installs it (the README's command) into a fresh virtual environment
# $BUILD_DIR/python-venv of /usr/bin/python3 and runs python/tests with pytest.
# Arguments: further CMake options, e.g. -DCE_WARNINGS_AS_ERRORS=ON.
# env: BUILD_DIR (default ./build), JOBS (default nproc),
#      CGAL_DIR (a CGAL other than the system's, e.g. ../shared/cgal-6.1.1/lib/cmake/CGAL;
#      the downstream tests use it too), CE_BUILD_BENCHMARKS (default ON),
#      CE_PYTHON_TESTS (default ON without CGAL_DIR, OFF with it: the package builds against
#      the system's CGAL only).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"

cgal=()
if [ -n "${CGAL_DIR:-}" ]; then
  cgal=(-DCGAL_DIR="$CGAL_DIR")
fi

python="${CE_PYTHON_TESTS:-$([ -n "${CGAL_DIR:-}" ] && echo OFF || echo ON)}"
# The Python package links this build's tool parts (CE_TOOL_PARTS_BUILD in setup.py) rather
# than compiling them a second time.
pic=()
if [ "$python" = ON ]; then
  pic=(-DCE_TOOL_PARTS_PIC=ON)
fi

bash scripts/install_dependencies.sh
source scripts/cmake_generator.sh
# shellcheck disable=SC2046 # the generator's options are words
cmake $(cmake_generator "$BUILD_DIR") -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${cgal[@]}" "${pic[@]}" \
  -DCE_BUILD_TESTS=ON -DCE_BUILD_EXAMPLES=ON -DCE_BUILD_BENCHMARKS="${CE_BUILD_BENCHMARKS:-ON}" "$@"
cmake --build "$BUILD_DIR" -j "$JOBS"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"

if [ "$python" != ON ]; then
  echo "run_tests: the Python package's tests are skipped (CE_PYTHON_TESTS is not ON)"
  exit 0
fi
venv="$BUILD_DIR/python-venv"
rm -rf "$venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
export CE_PYTHON_BUILD_DIR="$BUILD_DIR/python" # also for test_install.py
export CE_TOOL_PARTS_BUILD="$(cd "$BUILD_DIR" && pwd)"
CE_PYTHON_JOBS="$JOBS" "$venv/bin/pip" install --no-build-isolation --no-index --no-deps .
# pytest's exit status 5 (no tests collected) is a failure too, as any other than 0.
CE_CURVATURE_TOOL="$BUILD_DIR/tools/curvature" CE_BUNNY="$BUILD_DIR/data/meshes/bunny00.off" \
  "$venv/bin/python" -m pytest -p no:cacheprovider -q python/tests || {
  status=$?
  [ "$status" -eq 5 ] && echo "run_tests: pytest collected no tests" >&2
  echo "run_tests: pytest failed (exit status $status)" >&2
  exit 1
}
