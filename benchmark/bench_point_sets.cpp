// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of point_set_curvatures (issue 44) against CGAL's jet fitting on the same k
// nearest neighbors, in the same run: ns per point, the heap the call holds beyond its
// inputs and outputs, and the H RMS against the exact curvature on the same sample, so
// that the speeds compare at equal footing. The sample: N points (default 1M) uniformly
// random by area on the torus (R, r) = (1, 0.4) (ce_test::torus_samples, seed 44), whose
// H and K take both signs' worth of shapes (K < 0 inside). Cases, for k = 16 and 32,
// each sequential (seq) and on 2 threads (par, TBB):
//  - ours: point_set_curvatures with number_of_neighbors(k), no normals given (the normals
//    fitted and oriented by the propagation), writing H, K, the principal curvatures and
//    directions, the status and the estimated normal;
//  - ours_given_normals: the same with the exact normals given (no orientation pass);
//  - search: our search alone (internal/point_set_search.h): the tree built and the k
//    nearest of every point found;
//  - cgal_jet: what CGAL's users write: a CGAL::Kd_tree of the points, an
//    Orthogonal_k_neighbor_search of k + 1 points (the point first) and
//    Monge_via_jet_fitting of degree 2 and Monge degree 2 at every point (the package's
//    jet wrapper's defaults), the same outputs; its H takes the side of the exact normal
//    (the jet orients nothing) before its RMS is taken;
//  - cgal_search: that tree and those queries alone;
//  - nanoflann_search (where nanoflann's header is installed): nanoflann's kd-tree over
//    the points in the order of our search (their Morton order, not timed: in the input's
//    random order its queries take about 4 times as long) and the k + 1 nearest of every
//    point: the fastest search measured here, a floor for any search.
// Counters: time_per_point (s), peak_heap_bytes_per_point (operator new's bytes held at
// once during the call, beyond the inputs and outputs allocated before it; Eigen's own
// mallocs, of the jet's per-point matrices, are not counted), allocations_per_point,
// h_rms and not_estimable (ours and cgal_jet).
//
//   ./build/benchmark/bench_point_sets [--points N] [--benchmark_out=f.json ...]
//
// benchmark/point_sets.py runs it and writes benchmark/POINT_SETS.md.
#include "heap_counter.h"
#include "test_surfaces.h"

#include <CGAL/Curvature_estimation/internal/point_set_search.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/property_map.h>
#include <CGAL/version.h>

#include <benchmark/benchmark.h>

#if __has_include(<nanoflann.hpp>)
#include <nanoflann.hpp>
#define CE_BENCH_NANOFLANN 1
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

namespace {

namespace CE = CGAL::Curvature_estimation;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Pcd = CE::Principal_curvatures_and_directions<Kernel>;

constexpr int parallel_threads = 2; // the target speaks of 2 cores

struct Sample
{
  std::vector<Point> points;
  std::vector<Vector> normals; // exact
  std::vector<double> H;       // exact
};

Sample& sample(std::size_t n = 0)
{
  static Sample s;
  if (s.points.empty()) {
    std::vector<Eigen::Vector3d> p;
    std::vector<ce_test::Exact_curvature> exact;
    ce_test::torus_samples(n, 44, p, exact);
    for (std::size_t i = 0; i < n; ++i) {
      s.points.emplace_back(p[i].x(), p[i].y(), p[i].z());
      s.normals.emplace_back(exact[i].normal.x(), exact[i].normal.y(), exact[i].normal.z());
      s.H.push_back(exact[i].H);
    }
  }
  return s;
}

// The outputs of a case, allocated before it is timed.
struct Outputs
{
  explicit Outputs(std::size_t n)
      : H(n)
      , K(n)
      , pcd(n)
      , status(n)
      , normal(n)
  {}
  std::vector<double> H, K;
  std::vector<Pcd> pcd;
  std::vector<CE::Estimation_status> status;
  std::vector<Vector> normal;
};

// f(begin, end) over the points [0, n): at once, or by TBB's blocks.
template <typename ConcurrencyTag, typename F>
void for_points(std::size_t n, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
    return;
  }
#endif
  f(std::size_t(0), n);
}

template <typename ConcurrencyTag>
void ours(const std::vector<std::size_t>& indices, std::size_t k, bool given_normals, Outputs& o)
{
  const Sample& s = sample();
  const auto np = CE::parameters::point_map(CGAL::make_property_map(s.points))
                    .number_of_neighbors(k)
                    .vertex_mean_curvature_map(CGAL::make_property_map(o.H))
                    .vertex_Gaussian_curvature_map(CGAL::make_property_map(o.K))
                    .vertex_principal_curvatures_and_directions_map(CGAL::make_property_map(o.pcd))
                    .vertex_estimation_status_map(CGAL::make_property_map(o.status))
                    .estimated_normal_map(CGAL::make_property_map(o.normal));
  if (given_normals)
    CE::point_set_curvatures<ConcurrencyTag>(indices, np.normal_map(CGAL::make_property_map(s.normals)));
  else
    CE::point_set_curvatures<ConcurrencyTag>(indices, np);
}

// The sample's points as the search takes them.
std::vector<Eigen::Vector3d> sample_coordinates()
{
  std::vector<Eigen::Vector3d> coordinates;
  coordinates.reserve(sample().points.size());
  for (const Point& p : sample().points)
    coordinates.emplace_back(p.x(), p.y(), p.z());
  return coordinates;
}

template <typename ConcurrencyTag>
void our_search(std::size_t k, std::size_t& found_total)
{
  using Search = CE::internal::Point_set_search;
  std::vector<Eigen::Vector3d> coordinates = sample_coordinates();
  const Search search(coordinates, ConcurrencyTag());
  std::vector<Eigen::Vector3d>().swap(coordinates); // as point_set_curvatures does
  std::atomic<std::size_t> total{0};
  for_points<ConcurrencyTag>(search.size(), [&](std::size_t begin, std::size_t end) {
    Search::Found found;
    std::size_t count = 0;
    for (std::size_t i = begin; i < end; ++i) {
      search.nearest(Search::Index(i), k, found);
      count += found.size();
    }
    total += count;
  });
  found_total = total;
}

#ifdef CE_BENCH_NANOFLANN
// The points as nanoflann's adaptor reads them.
struct Nanoflann_points
{
  std::vector<Eigen::Vector3d> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t c) const { return points[i][int(c)]; }
  template <typename Box>
  bool kdtree_get_bbox(Box&) const
  {
    return false;
  }
};

// The sample in the order of our search, made once before the first timed run.
const Nanoflann_points& morton_ordered()
{
  static const Nanoflann_points ordered = [] {
    const CE::internal::Point_set_search search(sample_coordinates(), CGAL::Sequential_tag());
    return Nanoflann_points{search.points()};
  }();
  return ordered;
}

template <typename ConcurrencyTag>
void nanoflann_search(std::size_t k, std::size_t& found_total)
{
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Nanoflann_points>,
                                                   Nanoflann_points, 3, unsigned>;
  const Nanoflann_points& ordered = morton_ordered();
  Tree tree(3, ordered, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  std::atomic<std::size_t> total{0};
  for_points<ConcurrencyTag>(ordered.points.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<unsigned> indices(k + 1);
    std::vector<double> distances(k + 1);
    std::size_t count = 0;
    for (std::size_t i = begin; i < end; ++i)
      count += tree.knnSearch(ordered.points[i].data(), k + 1, indices.data(), distances.data()) - 1;
    total += count;
  });
  found_total = total;
}
#endif

using Traits = CGAL::Search_traits_3<Kernel>;
using Neighbor_search = CGAL::Orthogonal_k_neighbor_search<Traits>;
using Tree = Neighbor_search::Tree;
using Monge = CGAL::Monge_via_jet_fitting<Kernel>;

// CGAL's jet fitting as its users call it; `fit` false: the search alone (the
// neighborhoods gathered as for the fit). Outputs converted as the package's jet wrapper
// converts them (CGAL's curvatures are positive where the surface bends towards the normal).
template <typename ConcurrencyTag>
void cgal_jet(std::size_t k, bool fit, Outputs& o, std::size_t& found_total)
{
  const Sample& s = sample();
  Tree tree(s.points.begin(), s.points.end());
  tree.template build<ConcurrencyTag>();
  std::atomic<std::size_t> total{0};
  for_points<ConcurrencyTag>(s.points.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<Point> neighborhood;
    neighborhood.reserve(k + 1);
    std::size_t count = 0;
    for (std::size_t i = begin; i < end; ++i) {
      neighborhood.clear();
      const Neighbor_search search(tree, s.points[i], unsigned(k + 1));
      for (const auto& neighbor : search)
        neighborhood.push_back(neighbor.first);
      count += neighborhood.size();
      if (!fit)
        continue;
      Monge monge;
      const Monge::Monge_form form = monge(neighborhood.begin(), neighborhood.end(), 2, 2);
      const double k_max = -form.principal_curvatures(1), k_min = -form.principal_curvatures(0);
      o.H[i] = 0.5 * (k_max + k_min);
      o.K[i] = k_max * k_min;
      o.pcd[i] = Pcd(k_min, k_max, form.maximal_principal_direction(), form.minimal_principal_direction());
      o.normal[i] = form.normal_direction();
      o.status[i] = std::isfinite(o.H[i]) ? CE::Estimation_status::ok : CE::Estimation_status::not_estimable;
    }
    total += count;
  });
  found_total = total;
}

enum class Case
{
  ours,
  ours_given_normals,
  search,
  cgal_jet,
  cgal_search,
  nanoflann_search
};

const char* name(Case c)
{
  switch (c) {
    case Case::ours:
      return "ours";
    case Case::ours_given_normals:
      return "ours_given_normals";
    case Case::search:
      return "search";
    case Case::cgal_jet:
      return "cgal_jet";
    case Case::cgal_search:
      return "cgal_search";
    case Case::nanoflann_search:
      return "nanoflann_search";
  }
  return "";
}

template <typename ConcurrencyTag>
void run(Case c, std::size_t k, const std::vector<std::size_t>& indices, Outputs& o, std::size_t& found)
{
  switch (c) {
    case Case::ours:
    case Case::ours_given_normals:
      ours<ConcurrencyTag>(indices, k, c == Case::ours_given_normals, o);
      break;
    case Case::search:
      our_search<ConcurrencyTag>(k, found);
      break;
    case Case::cgal_jet:
    case Case::cgal_search:
      cgal_jet<ConcurrencyTag>(k, c == Case::cgal_jet, o, found);
      break;
    case Case::nanoflann_search:
#ifdef CE_BENCH_NANOFLANN
      nanoflann_search<ConcurrencyTag>(k, found);
#endif
      break;
  }
}

void time_case(benchmark::State& state, Case c, std::size_t k, bool parallel)
{
  const Sample& s = sample();
  const std::size_t n = s.points.size();
  std::vector<std::size_t> indices(n);
  std::iota(indices.begin(), indices.end(), std::size_t(0));
  Outputs o(n);
  std::size_t found = 0;
  const unsigned long long allocations_before = ce_bench::heap_allocations();
  long long peak_heap = 0;
#ifdef CE_BENCH_NANOFLANN
  if (c == Case::nanoflann_search)
    morton_ordered();
#endif
  for (auto _ : state) {
    ce_bench::reset_peak_heap();
#ifdef CGAL_LINKED_WITH_TBB
    if (parallel)
      run<CGAL::Parallel_tag>(c, k, indices, o, found);
    else
#endif
      run<CGAL::Sequential_tag>(c, k, indices, o, found);
    peak_heap = std::max(peak_heap, ce_bench::peak_heap_bytes());
    benchmark::DoNotOptimize(o.H.data());
    benchmark::ClobberMemory();
  }
  const double points = double(n);
  state.counters["points"] = points;
  state.counters["k"] = double(k);
  state.counters["threads"] = parallel ? parallel_threads : 1;
  state.counters["peak_heap_bytes_per_point"] = double(peak_heap) / points;
  state.counters["allocations_per_point"] =
    double(ce_bench::heap_allocations() - allocations_before) / (points * double(state.iterations()));
  state.counters["time_per_point"] =
    benchmark::Counter(points, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  if (c == Case::search || c == Case::cgal_search || c == Case::nanoflann_search) {
    state.counters["neighbors_per_point"] = double(found) / points;
    return;
  }
  // The accuracy of the last call's H, not timed.
  ce_test::Error_accumulator error;
  std::size_t not_estimable = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (o.status[i] == CE::Estimation_status::not_estimable) {
      ++not_estimable;
      continue;
    }
    const bool flip = c == Case::cgal_jet && o.normal[i] * s.normals[i] < 0;
    error.add(s.H[i], flip ? -o.H[i] : o.H[i]);
  }
  state.counters["h_rms"] = error.stats().rms;
  state.counters["not_estimable"] = double(not_estimable);
}

void register_all(int repetitions)
{
  for (std::size_t k : {16, 32})
    for (Case c : {Case::ours, Case::ours_given_normals, Case::search, Case::cgal_jet, Case::cgal_search,
                   Case::nanoflann_search})
      for (bool parallel : {false, true}) {
#ifndef CE_BENCH_NANOFLANN
        if (c == Case::nanoflann_search)
          continue;
#endif
#ifndef CGAL_LINKED_WITH_TBB
        if (parallel)
          continue;
#endif
        const std::string label = std::string(name(c)) + "/k" + std::to_string(k) + (parallel ? "/par" : "/seq");
        benchmark::RegisterBenchmark(label.c_str(),
                                     [c, k, parallel](benchmark::State& s) { time_case(s, c, k, parallel); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime() // wall clock: the main thread's CPU time says nothing of a parallel run
          ->Iterations(1)
          ->Repetitions(c == Case::cgal_jet ? 1 : repetitions); // the jet takes tens of seconds
      }
}

} // namespace

int main(int argc, char** argv)
{
  // Our own flags first: Google Benchmark rejects flags it does not know.
  std::size_t points = 1000000;
  int repetitions = 3;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--points") == 0 && i + 1 < argc)
      points = std::stoul(argv[++i]);
    else if (std::strcmp(argv[i], "--repetitions") == 0 && i + 1 < argc)
      repetitions = std::stoi(argv[++i]);
    else
      argv[kept++] = argv[i];
  }
  argc = kept;

#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, parallel_threads);
#endif
  sample(points);
  register_all(repetitions);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::AddCustomContext("points", std::to_string(points));
  benchmark::AddCustomContext("surface", "torus R = 1, r = 0.4, uniformly random by area, seed 44");
  benchmark::AddCustomContext("parallel_threads", std::to_string(parallel_threads));
  benchmark::AddCustomContext("cgal_version", CGAL_VERSION_STR);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
