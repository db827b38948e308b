// SPDX-License-Identifier: GPL-3.0-or-later
// How far any choice of radius per vertex can go on the noisy family of test_scale_selection (issue 45). An oracle
// that knows the exact curvature and the noise's distribution takes, at each vertex, the radius of least expected
// squared error of the paraboloid fit (fit_degree 2) among the selection's candidates (1 to 16 mean edges in steps of
// 2^(1/4)), that error estimated over `realizations` other draws of the same noise (Monte Carlo: bias and variance
// together, as they do not add up independently at high noise). Printed per mesh, as interior H RMS against the best
// single radius of the test's grid (1 to 16 mean edges in steps of 2^(1/2)) on the test's own draw: the oracle's
// ratio, and the selection's (ball_radius_range of 1 to 16 mean edges), so that the gap between them is the room any
// rule of selection has left.
//
//   ./build/benchmark/scale_selection_oracle [--realizations M] (default 8)
#include "noisy_meshes.h"
#include "test_surfaces.h"

#include <CGAL/Curvature_estimation/mean_edge_length.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;

// H of the paraboloid fit at every vertex, over a fixed ball or with the radius selected in [min, max].
std::vector<double> mean_curvature(Mesh& mesh, double radius, double max = 0)
{
  auto H = mesh.add_property_map<Vertex, double>("v:oracle_H").first;
  if (max > 0)
    CE::paraboloid_fitting_curvatures<CGAL::Parallel_if_available_tag>(
      mesh, params::ball_radius_range(std::make_pair(radius, max)).vertex_mean_curvature_map(H));
  else
    CE::paraboloid_fitting_curvatures<CGAL::Parallel_if_available_tag>(
      mesh, params::ball_radius(radius).vertex_mean_curvature_map(H));
  std::vector<double> values;
  for (Vertex v : vertices(mesh))
    values.push_back(H[v]);
  mesh.remove_property_map(H);
  return values;
}

double squared_error(double H, double exact) { return std::isfinite(H) ? (H - exact) * (H - exact) : HUGE_VAL; }

} // namespace

int main(int argc, char** argv)
{
  int realizations = 8;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--realizations") == 0 && i + 1 < argc)
      realizations = std::stoi(argv[++i]);

  constexpr int candidates = 17; // 2^(k/4) mean edges, k = 0..16; the test's grid is k even
  std::printf("%-18s %10s %8s %10s %10s\n", "mesh", "best fixed", "at edges", "oracle", "selection");
  for (const ce_test::Noisy_shape shape :
       {ce_test::Noisy_shape::ellipsoid, ce_test::Noisy_shape::torus, ce_test::Noisy_shape::delaunay})
    for (const double fraction : ce_test::noisy_family_fractions()) {
      const ce_test::Noisy_family_soup family = ce_test::noisy_family_soup(shape, fraction);
      Mesh mesh = ce_test::to_mesh<Mesh>(family.soup);
      const double edge = CE::mean_edge_length(mesh);
      const std::size_t n = family.exact.size();

      // The expected squared error at each candidate radius, over other draws of the noise.
      std::vector<double> expected(n * candidates, 0);
      for (int s = 0; s < realizations; ++s) {
        Mesh drawn = ce_test::to_mesh<Mesh>(ce_test::noisy_family_soup(shape, fraction, 1000 + s).soup);
        for (int k = 0; k < candidates; ++k) {
          const std::vector<double> H = mean_curvature(drawn, std::exp2(k / 4.0) * edge);
          for (std::size_t i = 0; i < n; ++i)
            expected[i * candidates + k] += squared_error(H[i], family.exact[i].H) / realizations;
        }
      }

      // On the test's draw: each candidate, the best single radius of the test's grid, the oracle, the selection.
      std::vector<std::vector<double>> H(candidates);
      for (int k = 0; k < candidates; ++k)
        H[k] = mean_curvature(mesh, std::exp2(k / 4.0) * edge);
      double best = HUGE_VAL, best_edges = 0;
      for (int k = 0; k < candidates; k += 2) {
        const double e = ce_test::interior_rms(family, H[k]);
        if (e < best) {
          best = e;
          best_edges = std::exp2(k / 4.0);
        }
      }
      std::vector<double> oracle(n);
      for (std::size_t i = 0; i < n; ++i) {
        int chosen = 0;
        for (int k = 1; k < candidates; ++k)
          if (expected[i * candidates + k] < expected[i * candidates + chosen])
            chosen = k;
        oracle[i] = H[chosen][i];
      }
      const double selection = ce_test::interior_rms(family, mean_curvature(mesh, edge, 16 * edge));
      std::printf("%-18s %10.4g %8.2f %10.2f %10.2f\n", family.name.c_str(), best, best_edges,
                  ce_test::interior_rms(family, oracle) / best, selection / best);
      std::fflush(stdout);
    }
  return 0;
}
