#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Install the Debian 12 packages needed to build, test and document the
# CGAL curvature estimation package. Idempotent: exits at once when every
# package is already installed.
#   --report  also the packages that regenerate benchmark/REPORT.md
set -euo pipefail

PACKAGES=(
  # Toolchain and build system (C++17 compiler, CMake >= 3.16, make; Ninja, which the build
  # scripts use where a build directory is new: scripts/cmake_generator.sh).
  build-essential cmake g++ make ninja-build
  # CGAL 5.5 headers + CMake config; libcgal-demo ships
  # /usr/share/doc/libcgal-dev/data.tar.gz (bunny, elephant, armadillo meshes).
  libcgal-dev libcgal-demo
  # CGAL's dependencies: Eigen3 (linear algebra, CGAL::Eigen3_support),
  # Boost (header-only parts), TBB (optional parallelism, CGAL::TBB_support),
  # GMP/MPFR (exact number types used by CGAL kernels).
  libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
  # Unit tests (GoogleTest/GoogleMock) and speed benchmarks (Google Benchmark).
  libgtest-dev libgmock-dev libbenchmark-dev
  # User manual (CGAL-style Doxygen documentation in doc/).
  doxygen
  # The fuzz target of the tool's input path (libFuzzer ships with Debian's clang).
  clang
  # The Python package (python/, setup.py: pybind11, built by setuptools in a virtual
  # environment of /usr/bin/python3; pkg-config finds Eigen and TBB) and its tests (pytest);
  # matplotlib (Agg backend) draws its example's picture, and the plots and headless renders
  # of benchmark/REPORT.md.
  python3 python3-dev python3-numpy python3-pybind11 pybind11-dev python3-pytest python3-venv python3-setuptools
  python3-wheel pkg-config python3-matplotlib
  # Tiles on Dask (python/curvature_estimation/tiles.py): the distributed scheduler, whose
  # LocalCluster of worker processes on localhost runs the tests of the tiled runs.
  python3-dask python3-distributed
  # The streamed tiles' check of a point set's neighborhoods (python/curvature_estimation/streamed.py).
  python3-scipy
)
if [ "${1:-}" = "--report" ]; then
  # /usr/bin/time: wall time and peak memory of benchmark/tool_end_to_end.sh and
  # benchmark/python_overhead.py.
  PACKAGES+=(time)
  # Callgrind: the default's instructions per vertex (benchmark/instructions.sh).
  PACKAGES+=(valgrind)
  # nanoflann's kd-tree, the point sets' search peer in benchmark/POINT_SETS.md (report only).
  PACKAGES+=(libnanoflann-dev)
fi

is_installed() {
  dpkg -s "$1" 2>/dev/null | grep -q '^Status: install ok installed$'
}

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! is_installed "$pkg"; then
    missing+=("$pkg")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install_dependencies: all ${#PACKAGES[@]} packages already installed."
  exit 0
fi

echo "install_dependencies: missing packages: ${missing[*]}"

SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  else
    echo "install_dependencies: not root and sudo not found; install manually:" >&2
    echo "  apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
  fi
fi

"${SUDO[@]}" apt-get update
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
