#!/usr/bin/env bash
# Regenerates the benchmark report in one command: installs the dependencies,
# builds the benchmarks (Release), runs the speed benchmarks (Google Benchmark,
# JSON) and the accuracy runner (CSV), then writes the report with plots.
#
#   scripts/make_report.sh            full run (about 20-25 minutes on 2 cores):
#                                     writes benchmark/REPORT.md and benchmark/figures/*.png
#   scripts/make_report.sh --quick    smoke run (a few minutes, small meshes): writes
#                                     BUILD/report_quick/REPORT.md, so that the committed
#                                     report is never replaced by smoke numbers
#
# Environment: CE_BUILD_DIR (default: build), CE_JOBS (parallel compile jobs, default 2).
# Raw outputs (speed.json, accuracy.csv, the bunny's CSVs) stay in BUILD/report[_quick]/.
set -euo pipefail

cd "$(dirname "$0")/.."
quick=()
for arg in "$@"; do
  case "$arg" in
    --quick) quick=(--quick) ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "make_report: unknown argument '$arg' (expected --quick)" >&2; exit 2 ;;
  esac
done

build="${CE_BUILD_DIR:-build}"
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

step "configure and build ($build, Release, -j$jobs)"
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCE_BUILD_BENCHMARKS=ON > "$build/make_report_configure.log" 2>&1 ||
  { cat "$build/make_report_configure.log" >&2; exit 1; }
cmake --build "$build" --target accuracy_runner bench_estimators -j "$jobs"
mkdir -p "$raw"

# Speed first: it is the part that suffers most from a busy machine.
step "speed benchmarks"
"$build/benchmark/bench_estimators" "${quick[@]}" \
  --benchmark_out="$raw/speed.json" --benchmark_out_format=json

step "accuracy runner"
"$build/benchmark/accuracy_runner" "${quick[@]}" --out "$raw"

elapsed=$(( $(date +%s) - start ))
step "report"
/usr/bin/python3 benchmark/make_report.py "${quick[@]}" --bench-json "$raw/speed.json" --accuracy-dir "$raw" \
  --build-dir "$build" --out-dir "$report_dir" \
  --duration "$((elapsed / 60)) min $((elapsed % 60)) s up to the report step (dependencies, build, benchmarks, accuracy)"
step "done: $report_dir/REPORT.md"
