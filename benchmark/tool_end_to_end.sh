#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The `curvature` tool end to end (read + estimate + summary or CSV write), single
# thread, on a generated ASCII OFF of a smooth height field: an N x N grid
# (N = 1000: 1M vertices, 2M triangles, 82 MB), coordinates with 9
# significant digits. Two files: the clean grid, which needs no repair, and a copy
# with one face flipped, which goes through the soup repair. Each is run without
# and with `-o FILE.csv` under /usr/bin/time -v (Debian package `time`), three
# times; the table gives the least wall time and the peak resident memory per vertex.
#   benchmark/tool_end_to_end.sh [CURVATURE_BINARY [N]]
# Defaults: build/tools/curvature, N = 1000. The files go to a temporary
# directory, removed at the end.
set -euo pipefail

tool="${1:-build/tools/curvature}"
n="${2:-1000}"
if [ ! -x "$tool" ]; then
  echo "tool_end_to_end.sh: no executable '$tool' (build the target curvature first)" >&2
  exit 1
fi
if [ ! -x /usr/bin/time ]; then
  echo "tool_end_to_end.sh: /usr/bin/time is missing (apt-get install time)" >&2
  exit 1
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

generate() { /usr/bin/python3 "$(dirname "$0")/grid_off.py" "$n" "$1" "$2"; }

generate "$work/clean.off" clean
generate "$work/flipped.off" flip
vertices=$((n * n))
echo "grid ${n}x${n}: $vertices vertices, $((2 * (n - 1) * (n - 1))) triangles, $(stat -c %s "$work/clean.off") bytes"
echo "tool: $tool"
echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
printf '%-12s %-8s %10s %16s\n' file output "wall s" "peak bytes/vertex"

# Best of three runs (as bench_estimators takes the best of 3 repetitions): the
# least wall time, and the largest peak resident memory, per vertex, from time -v.
measure() {
  local input="$1" label="$2" output="$3"
  shift 3
  : >"$work/times.txt"
  for run in 1 2 3; do
    /usr/bin/time -v -o "$work/time.txt" "$tool" --threads 1 "$@" "$input" >"$work/stdout.txt" 2>"$work/stderr.txt" || {
      echo "tool_end_to_end.sh: the tool failed on $input:" >&2
      cat "$work/stderr.txt" >&2
      exit 1
    }
    cat "$work/time.txt" >>"$work/times.txt"
  done
  awk -v file="$label" -v output="$output" -v vertices="$vertices" '
    /Elapsed \(wall clock\) time/ {
      n = split($NF, t, ":"); wall = 0
      for (i = 1; i <= n; ++i) wall = wall * 60 + t[i]
      if (best == "" || wall < best) best = wall
    }
    /Maximum resident set size/ { if ($NF * 1024 > rss) rss = $NF * 1024 }
    END { printf "%-12s %-8s %10.2f %16.0f\n", file, output, best, rss / vertices }' "$work/times.txt"
}

for name in clean flipped; do
  measure "$work/$name.off" "$name" summary
  measure "$work/$name.off" "$name" csv -o "$work/$name.csv"
  rm -f "$work/$name.csv"
done
