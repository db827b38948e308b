// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of every estimator of benchmark/estimators.h, in ns per vertex (the
// `time_per_vertex` counter: seconds per vertex, e.g. 95n), and heap allocations per
// vertex and call (`allocations_per_vertex`, all threads), the peak of the heap the
// calls held at once, per vertex (`peak_heap_bytes_per_vertex`), and the minor page faults
// per vertex and call (`page_faults_per_vertex`), on Surface_mesh:
// grids of .1(cos pi x + cos pi y) with about 10k, 100k and 1M vertices and CGAL's
// bunny, armadillo, elephant and Chinese dragon; sequential and parallel (TBB,
// at most 2 threads; CGAL 6's estimators have no parallel version: sequential only).
// Benchmark names are ESTIMATOR/MESH/seq|par, which benchmark/make_report.py parses;
// the JSON context holds `cgal_version`, the CGAL compiled against.
//
//   ./build/benchmark/bench_estimators [--quick] [--benchmark_filter=...] [--benchmark_out=f.json ...]
//
// --quick: a smoke run on a 2.6k- and a 10k-vertex grid, the bunny and the elephant,
// with short minimum times and no repetitions. Otherwise every case runs for at least
// 1 s, or once if one run takes longer (jet fitting on 1M vertices: tens of seconds),
// and most cases are repeated 3 times; the full run takes about 15 minutes on two cores
// (a few more with CGAL 6's estimators).
#include "estimators.h"
#include "heap_counter.h"

#include <benchmark/benchmark.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace ce_bench;

// The report's targets speak of two cores: parallel runs use at most 2 threads.
constexpr int parallel_threads = 2;

struct Built_input
{
  Mesh mesh;
  double h; // its mean edge length
};

// Inputs (speed_input) are built on first use and kept for the process: the 1M-vertex
// grid takes seconds to build, longer than the fast estimators take to run on it.
Built_input& built(const std::string& input)
{
  static std::map<std::string, std::unique_ptr<Built_input>> cache;
  std::unique_ptr<Built_input>& b = cache[input];
  if (!b) {
    Mesh mesh = speed_input(input);
    const double h = CE::mean_edge_length(mesh);
    b = std::make_unique<Built_input>(Built_input{std::move(mesh), h});
  }
  return *b;
}

// `threads` as ce_tool::run takes it: 1 for the sequential runs, 0 for the parallel ones
// (as many threads as main allows).
void time_estimator(benchmark::State& state, const Estimator& estimator, const std::string& input, int threads)
{
  Built_input* b = nullptr;
  try {
    b = &built(input);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  Mesh* mesh = &b->mesh;
  ce_tool::Outputs outputs = ce_tool::add_outputs(*mesh, "v:bench_");
  Normal_map given = mesh->add_property_map<vertex_descriptor, Kernel::Vector_3>("v:bench_normal").first;
  if (estimator.given_normals)
    CE::estimate_vertex_normals(*mesh, given); // not timed: "given" means someone else computed them

  const unsigned long long allocations_before = heap_allocations();
  const long faults_before = minor_page_faults();
  long long peak_heap = 0; // of the calls, the largest
  for (auto _ : state) {
    reset_peak_heap();
    run(estimator, *mesh, given, b->h, outputs, threads);
    peak_heap = std::max(peak_heap, peak_heap_bytes());
    benchmark::DoNotOptimize(outputs.H[*vertices(*mesh).begin()]);
    benchmark::ClobberMemory();
  }
  const double n = static_cast<double>(num_vertices(*mesh));
  state.counters["allocations_per_vertex"] =
    double(heap_allocations() - allocations_before) / (n * double(state.iterations()));
  state.counters["page_faults_per_vertex"] =
    double(minor_page_faults() - faults_before) / (n * double(state.iterations()));
  // Heap beyond the mesh and the output maps (allocated above): the estimator's temporaries.
  state.counters["peak_heap_bytes_per_vertex"] = double(peak_heap) / n;
  state.counters["vertices"] = n;
  state.counters["threads"] = threads == 1 ? 1 : parallel_threads;
  // Seconds per vertex, printed with an SI prefix (e.g. 95n = 95 ns).
  state.counters["time_per_vertex"] =
    benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  ce_tool::remove_outputs(*mesh, outputs);
  mesh->remove_property_map(given);
}

// The machine is shared: make_report.py takes the best of the repetitions, the least
// disturbed run; the slow estimators (Estimator::slow) run once. The 2-ring jet and
// ICC's defaults are repeated like the paraboloid fit, as the report divides them by it.
void register_all(bool quick)
{
  std::vector<std::string> inputs;
  for (int n : quick ? std::vector<int>{51, 101} : std::vector<int>{101, 317, 1001})
    inputs.push_back("grid_" + std::to_string(n));
  if (quick) {
    inputs.push_back("bunny00");
    inputs.push_back("elephant");
  } else {
    inputs.insert(inputs.end(), real_mesh_names().begin(), real_mesh_names().end());
  }
  const double min_time = quick ? 0.05 : 1.0;
  const auto repetitions = [quick](const Estimator& e) { return quick || e.slow ? 1 : 3; };

  for (const std::string& input : inputs)
    for (const Estimator& e : estimators()) {
      const std::string base = e.name + "/" + input;
      benchmark::RegisterBenchmark((base + "/seq").c_str(),
                                   [&e, input](benchmark::State& s) { time_estimator(s, e, input, 1); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(min_time)
        ->Repetitions(repetitions(e))
        ->DisplayAggregatesOnly(true); // the JSON file still has every repetition
#ifdef CGAL_LINKED_WITH_TBB
      if (!e.parallel())
        continue;
      benchmark::RegisterBenchmark((base + "/par").c_str(),
                                   [&e, input](benchmark::State& s) { time_estimator(s, e, input, 0); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime() // wall clock: CPU time of the main thread says nothing of a parallel run
        ->MinTime(min_time)
        ->Repetitions(repetitions(e))
        ->DisplayAggregatesOnly(true);
#endif
    }
}

} // namespace

int main(int argc, char** argv)
{
  // Our own flag first: Google Benchmark rejects flags it does not know.
  bool quick = false;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else
      argv[kept++] = argv[i];
  }
  argc = kept;

#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, parallel_threads);
#endif
  register_all(quick);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::AddCustomContext("quick", quick ? "yes" : "no");
  benchmark::AddCustomContext("parallel_threads", std::to_string(parallel_threads));
  benchmark::AddCustomContext("cgal_version", CGAL_VERSION_STR);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
