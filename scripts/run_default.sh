#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The main job: build the command-line tool `curvature` and print the curvature
# summary of a mesh (default: the Stanford bunny extracted from CGAL's data
# archive at configure time, build/data/meshes/bunny00.off).
# Usage: scripts/run_default.sh [curvature options] [mesh-file]   (env BUILD_DIR overrides ./build)
#   e.g. scripts/run_default.sh -m gauss-map -o bunny.ply some.off
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"

bash scripts/install_dependencies.sh
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" --target curvature -j "$JOBS"
if [ "$#" -eq 0 ]; then
  set -- "$BUILD_DIR/data/meshes/bunny00.off"
fi
"$BUILD_DIR/tools/curvature" "$@"
