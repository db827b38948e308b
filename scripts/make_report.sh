#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Regenerates the benchmark report in one command: installs the dependencies,
# builds the benchmarks (Release), runs the speed benchmarks (Google Benchmark,
# JSON) and the accuracy runner (CSV), then writes the report with plots.
#
#   scripts/make_report.sh            full run (26 to 38 minutes on 2 cores):
#                                     writes benchmark/REPORT.md and benchmark/figures/*.png
#   scripts/make_report.sh --quick    smoke run (a few minutes, small meshes): writes
#                                     BUILD/report_quick/REPORT.md, so that the committed
#                                     report is never replaced by smoke numbers
#   scripts/make_report.sh --section=scale   the scale-selection section alone (about 2
#                                     minutes after the build): rewrites that section of
#                                     benchmark/REPORT.md and its figures, nothing else
#
# The CGAL: CGAL_DIR=<dir of CGALConfig.cmake> scripts/make_report.sh uses that one; without
# CGAL_DIR, ../shared/cgal-6.1.1/lib/cmake/CGAL (beside the repository) when it exists - the
# committed report is generated against CGAL 6.1.1, whose own estimators (ICC, the discrete
# operators) it then includes - else the system's CGAL (Debian's 5.5).
# Environment: CGAL_DIR, CE_BUILD_DIR (default: build-report, the report's own build
# directory, configured with the CGAL chosen above at every run; not the tests' build/),
# CE_JOBS (parallel compile jobs, default 2).
# Raw outputs (speed.json, accuracy.csv, noise_radius.csv, scale_selection.csv, estimators.json, the bunny's CSVs,
# first_calls.jsonl, end_to_end.txt, instructions.txt) stay in BUILD/report[_quick]/.
set -euo pipefail

# A relative CGAL_DIR is relative to where the script was started.
cgal_dir="${CGAL_DIR:+$(cd "$CGAL_DIR" && pwd)}"
cd "$(dirname "$0")/.."
quick=()
section=
for arg in "$@"; do
  case "$arg" in
    --quick) quick=(--quick) ;;
    --section=scale) section=scale ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) echo "make_report: unknown argument '$arg' (expected --quick or --section=scale)" >&2; exit 2 ;;
  esac
done

shared_cgal=../shared/cgal-6.1.1/lib/cmake/CGAL
if [ -z "$cgal_dir" ] && [ -d "$shared_cgal" ]; then
  cgal_dir="$(cd "$shared_cgal" && pwd)"
fi
if [ -n "$cgal_dir" ]; then
  cgal=(-DCGAL_DIR="$cgal_dir")
else
  cgal=(-UCGAL_DIR) # the system's CGAL, also where an earlier run cached another one
fi

build="${CE_BUILD_DIR:-build-report}"
jobs="${CE_JOBS:-2}"
if [ ${#quick[@]} -gt 0 ]; then
  raw="$build/report_quick"
  report_dir="$build/report_quick"
else
  raw="$build/report"
  report_dir="benchmark"
fi
start=$(date +%s)
step() { echo "== make_report [$(( $(date +%s) - start )) s]: $*" >&2; }

step "dependencies"
bash scripts/install_dependencies.sh --report

step "configure and build ($build, Release, -j$jobs, CGAL: ${cgal_dir:-the system one})"
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCE_BUILD_BENCHMARKS=ON -DCE_BUILD_TESTS=OFF \
  -DCE_BUILD_EXAMPLES=OFF -DCE_BUILD_TOOLS=ON "${cgal[@]}" > "$build/make_report_configure.log" 2>&1 ||
  { cat "$build/make_report_configure.log" >&2; exit 1; }
mkdir -p "$raw"
if [ -n "$section" ]; then
  cmake --build "$build" --target accuracy_runner -j "$jobs"
  step "accuracy runner, part $section"
  "$build/benchmark/accuracy_runner" --only "$section" --out "$raw"
  step "report, section $section"
  /usr/bin/python3 benchmark/make_report.py --section "$section" --accuracy-dir "$raw" --out-dir benchmark
  step "done: benchmark/REPORT.md, section $section"
  exit 0
fi
cmake --build "$build" --target accuracy_runner bench_estimators first_calls curvature -j "$jobs"

# Speed first: it is the part that suffers most from a busy machine. The repetitions
# interleaved in a random order: back to back, the 3 of a case can all fall in one
# disturbance (on 2026-12-04 fit_degree(4) read 20% slow in all 3, on every mesh).
step "speed benchmarks"
"$build/benchmark/bench_estimators" "${quick[@]}" --benchmark_enable_random_interleaving=true \
  --benchmark_out="$raw/speed.json" --benchmark_out_format=json

step "accuracy runner"
"$build/benchmark/accuracy_runner" "${quick[@]}" --out "$raw"

# Each estimator but the slow ones in a fresh process, on the largest grid and the bunny.
step "first calls in fresh processes"
meshes=(grid_1001 bunny00)
[ ${#quick[@]} -gt 0 ] && meshes=(grid_101 bunny00)
: > "$raw/first_calls.jsonl"
for name in $(/usr/bin/python3 -c 'import json, sys
print(" ".join(e["name"] for e in json.load(open(sys.argv[1]))["estimators"] if not e.get("slow")))' \
              "$raw/estimators.json"); do
  for mesh in "${meshes[@]}"; do
    "$build/benchmark/first_calls" "$name" "$mesh" >> "$raw/first_calls.jsonl"
  done
done

step "the tool end to end"
grid=1000
[ ${#quick[@]} -gt 0 ] && grid=200
bash benchmark/tool_end_to_end.sh "$build/tools/curvature" "$grid" > "$raw/end_to_end.txt"

step "instructions per vertex of the default (callgrind)"
grid=317
[ ${#quick[@]} -gt 0 ] && grid=101
bash benchmark/instructions.sh "$build/tools/curvature" "$grid" > "$raw/instructions.txt"

elapsed=$(( $(date +%s) - start ))
step "report"
/usr/bin/python3 benchmark/make_report.py "${quick[@]}" --bench-json "$raw/speed.json" --accuracy-dir "$raw" \
  --end-to-end "$raw/end_to_end.txt" --instructions "$raw/instructions.txt" --first-calls "$raw/first_calls.jsonl" \
  --build-dir "$build" --out-dir "$report_dir" \
  --duration "$((elapsed / 60)) min $((elapsed % 60)) s up to the report step (dependencies, build, benchmarks, accuracy)"
step "done: $report_dir/REPORT.md"
