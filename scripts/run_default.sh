#!/usr/bin/env bash
# Build and run the default example: curvature summary of a mesh
# (default: the Stanford bunny extracted from CGAL's data archive at configure time).
# Usage: scripts/run_default.sh [mesh-file]      (env BUILD_DIR overrides ./build)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"

bash scripts/install_dependencies.sh
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" --target curvature_summary -j "$JOBS"
"$BUILD_DIR/examples/curvature_summary" "$@"
