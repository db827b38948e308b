#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The instructions of the default estimator's call, counted by callgrind (Debian package
# valgrind): `curvature --threads 1` on the N x N grid of benchmark/grid_off.py (the
# tool_end_to_end.sh grid), counting only inside the registry's run (ce_tool::run: the
# estimator's call, writing its outputs included; not the reading of the file nor the
# summary). A count does not depend on the machine's load. Output, for make_report.py:
#   grid NxN: V vertices
#   instructions: I
#   benchmark/instructions.sh [CURVATURE_BINARY [N]]     (defaults: build/tools/curvature, 317)
set -euo pipefail

tool="${1:-build/tools/curvature}"
n="${2:-317}"
if [ ! -x "$tool" ]; then
  echo "instructions.sh: no executable '$tool' (build the target curvature first)" >&2
  exit 1
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$(dirname "$0")/grid_off.py" "$n" "$work/grid.off"
valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" --toggle-collect='ce_tool::run(*' \
  "$tool" --threads 1 "$work/grid.off" >"$work/summary.txt" 2>"$work/valgrind.txt" || {
  echo "instructions.sh: callgrind failed:" >&2
  cat "$work/valgrind.txt" >&2
  exit 1
}
count=$(awk '/^(summary|totals):/ { print $2; exit }' "$work/callgrind.out")
if [ -z "$count" ] || [ "$count" -eq 0 ]; then
  echo "instructions.sh: callgrind counted nothing in ce_tool::run" >&2
  exit 1
fi
echo "grid ${n}x${n}: $((n * n)) vertices"
echo "instructions: $count"
