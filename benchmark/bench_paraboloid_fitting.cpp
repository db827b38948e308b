// Speed of paraboloid_fitting_curvatures, in ns per vertex (the `time_per_vertex`
// counter: seconds per vertex, e.g. 95n), on grids of .1(cos pi x + cos pi y) with about 10k, 100k and 1M
// vertices and on the Stanford bunny; sequential and parallel; default
// (quadric-fit) normals, area-weighted normals, and given normals.
//
//   ./build/benchmark/bench_paraboloid_fitting [--benchmark_filter=...]
#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include "test_surfaces.h"

#include <map>
#include <memory>
#include <string>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
namespace CE = CGAL::Curvature_estimation;

// Inputs are built once per process; index 0 is the bunny, others are grids of n x n.
const Mesh& input(int n)
{
  static std::map<int, std::unique_ptr<Mesh>> cache;
  std::unique_ptr<Mesh>& mesh = cache[n];
  if (!mesh) {
    mesh = std::make_unique<Mesh>();
    if (n == 0) {
      if (!CGAL::IO::read_polygon_mesh(std::string(CE_DATA_DIR) + "/meshes/bunny00.off", *mesh))
        mesh->clear();
    } else {
      *mesh = ce_test::to_mesh<Mesh>(ce_test::grid_graph_soup(ce_test::hamann_table1_functions()[8], std::size_t(n)));
    }
  }
  return *mesh;
}

enum class Normals { fitted, area_weighted, given };

template <typename ConcurrencyTag>
void paraboloid_fitting(benchmark::State& state, Normals normals)
{
  const Mesh& mesh = input(int(state.range(0)));
  if (is_empty(mesh)) {
    state.SkipWithError("input mesh not available");
    return;
  }
  Mesh& m = const_cast<Mesh&>(mesh);
  auto mean = m.add_property_map<vertex_descriptor, double>("v:bench_H").first;
  auto principal = m.add_property_map<vertex_descriptor, CE::Principal_curvatures_and_directions<Kernel>>("v:bench_pcd").first;
  auto given = m.add_property_map<vertex_descriptor, Kernel::Vector_3>("v:bench_normal").first;
  CE::estimate_vertex_normals(mesh, given);

  const auto outputs = CE::parameters::vertex_mean_curvature_map(mean).vertex_principal_curvatures_and_directions_map(principal);
  for (auto _ : state) {
    switch (normals) {
      case Normals::fitted:
        CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, outputs);
        break;
      case Normals::area_weighted:
        CE::paraboloid_fitting_curvatures<ConcurrencyTag>(
          mesh, outputs.vertex_normal_method(CE::Vertex_normal_method::area_weighted));
        break;
      case Normals::given:
        CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, outputs.vertex_normal_map(given));
        break;
    }
    benchmark::DoNotOptimize(mean[*vertices(mesh).begin()]);
  }
  state.counters["vertices"] = double(num_vertices(mesh));
  // Seconds per vertex, printed with an SI prefix (e.g. 95n = 95 ns).
  state.counters["time_per_vertex"] =
    benchmark::Counter(double(num_vertices(mesh)), benchmark::Counter::kIsIterationInvariantRate |
                                                              benchmark::Counter::kInvert);
  m.remove_property_map(mean);
  m.remove_property_map(principal);
  m.remove_property_map(given);
}

// 0: bunny00.off (37,706 vertices); 101, 317, 1001: grids of about 10k, 100k, 1M vertices.
void sizes(benchmark::internal::Benchmark* b)
{
  b->Arg(0)->Arg(101)->Arg(317)->Arg(1001)->Unit(benchmark::kMillisecond)->UseRealTime();
}

void fitted_normals_sequential(benchmark::State& state) { paraboloid_fitting<CGAL::Sequential_tag>(state, Normals::fitted); }
void area_normals_sequential(benchmark::State& state) { paraboloid_fitting<CGAL::Sequential_tag>(state, Normals::area_weighted); }
void given_normals_sequential(benchmark::State& state) { paraboloid_fitting<CGAL::Sequential_tag>(state, Normals::given); }
BENCHMARK(fitted_normals_sequential)->Apply(sizes);
BENCHMARK(area_normals_sequential)->Apply(sizes);
BENCHMARK(given_normals_sequential)->Apply(sizes);
#ifdef CGAL_LINKED_WITH_TBB
void fitted_normals_parallel(benchmark::State& state) { paraboloid_fitting<CGAL::Parallel_tag>(state, Normals::fitted); }
BENCHMARK(fitted_normals_parallel)->Apply(sizes);
#endif

}  // namespace

BENCHMARK_MAIN();
