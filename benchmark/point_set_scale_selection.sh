#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The cost of the scale selection on point sets: the `curvature` tool's estimation
# time (the summary's "time:", the library call alone), single thread, with
# --radius auto (2x to 32x mean distances to the nearest neighbor) against one fixed
# ball at the largest radius it considers (--radius 32x), in the same run, best of
# three each. Inputs: N random points of the ellipsoid (1, 0.8, 0.6) with Gaussian
# noise of 5% of their mean spacing (generated here, seed 1), and the point sets
# given after N (for instance CGAL's data/points_3/kitten.xyz).
#   benchmark/point_set_scale_selection.sh [CURVATURE_BINARY [N [FILE...]]]
# Defaults: build/tools/curvature, N = 20000. Run it under the machine's build lock.
set -euo pipefail

tool="${1:-build/tools/curvature}"
n="${2:-20000}"
shift $(($# < 2 ? $# : 2))
if [ ! -x "$tool" ]; then
  echo "point_set_scale_selection.sh: no executable '$tool' (build the target curvature first)" >&2
  exit 1
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 - "$n" "$work/ellipsoid.xyz" <<'EOF'
import sys
import numpy as np

n, path = int(sys.argv[1]), sys.argv[2]
rng = np.random.default_rng(1)
u = rng.normal(size=(n, 3))
p = u / np.linalg.norm(u, axis=1)[:, None] * np.array([1.0, 0.8, 0.6])
spacing = np.sqrt(4 * np.pi * (0.48 ** (2 / 3)) / n) / 2  # about the mean distance to the nearest neighbor
p += rng.normal(scale=0.05 * spacing, size=p.shape)
np.savetxt(path, p, fmt="%.17g")
EOF

# The least estimation time in ms of three runs of the tool with the arguments given.
best_time() {
  local best=""
  for _ in 1 2 3; do
    local t
    t="$("$tool" --threads 1 "$@" | sed -n 's/^time: \([0-9.e+-]*\) ms.*/\1/p')"
    best="$(/usr/bin/python3 -c "import sys; print(min(float(x) for x in sys.argv[1:]))" $best "$t")"
  done
  echo "$best"
}

echo "tool: $tool"
echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
printf '%-24s %8s %14s %14s %8s\n' input points "auto ms" "32x ms" ratio
for input in "$work/ellipsoid.xyz" "$@"; do
  points="$(grep -cv '^[[:space:]]*\(#\|$\)' "$input" || true)"
  auto="$(best_time --radius auto "$input")"
  fixed="$(best_time --radius 32x "$input")"
  ratio="$(/usr/bin/python3 -c "print(f'{$auto / $fixed:.2f}')")"
  printf '%-24s %8s %14s %14s %8s\n' "$(basename "$input")" "$points" "$auto" "$fixed" "$ratio"
done
