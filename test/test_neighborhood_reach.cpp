// SPDX-License-Identifier: GPL-3.0-or-later
// neighborhood_reach: the vertices (points) beyond an estimator's reach from a vertex can move without
// changing its estimate there, bit for bit, status included; on clean and on noisy irregular meshes (the
// noise widens fits and calls fallbacks), for every estimator and the settings that change the reach;
// over balls also with the estimators' per-vertex reach (vertex_reach_map).
#include <CGAL/Curvature_estimation/neighborhood_reach.h>

#include "common/estimator_runs.h"
#include "common/random_numbers.h"
#include "common/test_surfaces.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <deque>
#include <iostream>
#include <random>
#include <vector>

namespace CE = CGAL::Curvature_estimation;
namespace params = CE::parameters;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using ce_test::Soup;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The Delaunay mesh of 900 random points over a graph, its heights moved by up to `noise` mean edges.
Soup graph_mesh(double noise)
{
  const ce_test::Graph_function g = ce_test::hamann_table1_functions()[1];
  Soup soup = ce_test::delaunay_graph_soup(g, 900, -1, 1, 7);
  const double edge = ce_test::mean_edge_length(soup);
  std::mt19937 gen(11);
  for (Eigen::Vector3d& p : soup.points)
    p.z() += noise * edge * ce_test::uniform_symmetric(gen);
  return soup;
}

// Whether each vertex lies within reach.rings edges of a vertex within `distance` of `center`.
std::vector<char> within_reach(const Mesh& mesh, Mesh::Vertex_index center, int rings, double distance)
{
  std::vector<int> depth(num_vertices(mesh), -1);
  std::deque<Mesh::Vertex_index> queue;
  for (Mesh::Vertex_index v : vertices(mesh))
    if (v == center || std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(center))) <= distance) {
      depth[v] = 0;
      queue.push_back(v);
    }
  while (!queue.empty()) {
    const Mesh::Vertex_index v = queue.front();
    queue.pop_front();
    if (depth[v] == rings)
      continue;
    for (Mesh::Vertex_index w : vertices_around_target(mesh.halfedge(v), mesh))
      if (depth[w] < 0) {
        depth[w] = depth[v] + 1;
        queue.push_back(w);
      }
  }
  std::vector<char> inside(depth.size());
  for (std::size_t i = 0; i < depth.size(); ++i)
    inside[i] = depth[i] >= 0;
  return inside;
}

// Moves every vertex outside `inside` away from `center` by a random 1 to 10% of its distance (so that
// it stays outside any ball about the center it was outside of).
Mesh moved_outside(const Mesh& mesh, Mesh::Vertex_index center, const std::vector<char>& inside, std::uint32_t seed)
{
  Mesh moved = mesh;
  std::mt19937 gen(seed);
  const Kernel::Point_3 c = mesh.point(center);
  for (Mesh::Vertex_index v : vertices(moved))
    if (!inside[v])
      moved.point(v) = c + (mesh.point(v) - c) * (1 + ce_test::uniform(gen, 0.01, 0.1));
  return moved;
}

// Moves every vertex beyond the reach of sampled vertices and expects their estimates unchanged. The reach:
// neighborhood_reach's distance (grown_distance where the status is not ok), or with `per_vertex` the
// estimator's own (vertex_reach_map: the bound where balls grow, even past grown_distance), then its rings.
// Returns how many vertices checked reached past grown_distance.
template <typename Run, typename NamedParameters>
std::size_t expect_reach_bounds(const char* what, CE::Estimator estimator, Run run, const NamedParameters& np,
                                bool per_vertex = false)
{
  const CE::Neighborhood_reach reach = CE::neighborhood_reach(estimator, np);
  EXPECT_GE(reach.rings, 1) << what;
  std::size_t past = 0;
  for (const double noise : {0.0, 1.0}) {
    Mesh mesh = ce_test::to_mesh<Mesh>(graph_mesh(noise));
    const auto reached = mesh.add_property_map<Mesh::Vertex_index, double>("v:reach").first;
    const auto whole = ce_test::run_with_all_outputs<Kernel>(mesh, run, np.vertex_reach_map(reached));
    std::size_t checked = 0, widened = 0, past_here = 0;
    for (std::size_t i = 0; i < num_vertices(mesh); i += 53) { // the boundary (first 116 vertices) and inside
      const Mesh::Vertex_index v(static_cast<Mesh::size_type>(i));
      const bool ok = whole.status[i] == CE::Estimation_status::ok;
      widened += !ok;
      past_here += reached[v] > reach.grown_distance;
      if (per_vertex) {
        EXPECT_GE(reached[v], reach.distance / 2) << what << ", vertex " << i << ": at least its own ball";
      }
      const double distance = per_vertex ? reached[v] : ok ? reach.distance : reach.grown_distance;
      const std::vector<char> inside = within_reach(mesh, v, reach.rings, distance);
      const auto moved =
        ce_test::run_with_all_outputs<Kernel>(moved_outside(mesh, v, inside, std::uint32_t(i)), run, np);
      EXPECT_EQ(moved.status[i], whole.status[i]) << what << ", noise " << noise << ", vertex " << i;
      EXPECT_TRUE(same_bits(moved.mean[i], whole.mean[i]) && same_bits(moved.gaussian[i], whole.gaussian[i]))
        << what << ", noise " << noise << ", vertex " << i << ": H " << whole.mean[i] << " became " << moved.mean[i];
      ++checked;
    }
    EXPECT_GE(checked, 16u);
    std::cout << what << (per_vertex ? ", its own reach" : "") << (noise > 0 ? ", noisy: " : ", clean: ") << widened
              << " of " << checked << " not ok, " << past_here << " reached past grown_distance\n";
    past += past_here;
  }
  return past;
}

const auto paraboloid = [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); };
const auto gauss_map = [](const Mesh& m, const auto& np) { CE::gauss_map_curvatures(m, np); };
const auto taubin = [](const Mesh& m, const auto& np) { CE::taubin_curvatures(m, np); };
const auto chen_schmitt = [](const Mesh& m, const auto& np) { CE::chen_schmitt_curvatures(m, np); };
const auto curve_network = [](const Mesh& m, const auto& np) { CE::curve_network_curvatures(m, np); };
const auto jet = [](const Mesh& m, const auto& np) { CE::jet_fitting_curvatures(m, np); };

double mean_edge() { return ce_test::mean_edge_length(graph_mesh(0)); }

} // namespace

TEST(NeighborhoodReach, ParaboloidFitting)
{
  const auto E = CE::Estimator::paraboloid_fitting;
  expect_reach_bounds("default", E, paraboloid, params::default_values());
  expect_reach_bounds("2 rings", E, paraboloid, params::neighborhood_rings(2));
  expect_reach_bounds("degree 3", E, paraboloid, params::fit_degree(3));
  expect_reach_bounds("degree 4", E, paraboloid, params::fit_degree(4));
  expect_reach_bounds("ball", E, paraboloid, params::ball_radius(3 * mean_edge()));
  expect_reach_bounds("ill-conditioned", E, paraboloid, params::max_condition_number(1.5));
  expect_reach_bounds("degree 4, ill-conditioned", E, paraboloid, params::fit_degree(4).max_condition_number(1.5));
  expect_reach_bounds("area-weighted normals", E, paraboloid,
                      params::vertex_normal_method(CE::Vertex_normal_method::area_weighted));
}

TEST(NeighborhoodReach, OtherEstimators)
{
  expect_reach_bounds("gauss map", CE::Estimator::gauss_map, gauss_map, params::default_values());
  expect_reach_bounds("gauss map, ball", CE::Estimator::gauss_map, gauss_map, params::ball_radius(2.5 * mean_edge()));
  expect_reach_bounds("taubin", CE::Estimator::taubin, taubin, params::default_values());
  expect_reach_bounds("chen-schmitt", CE::Estimator::chen_schmitt, chen_schmitt, params::default_values());
  expect_reach_bounds("curve network, order 3", CE::Estimator::curve_network, curve_network,
                      params::extrapolation_order(3));
  expect_reach_bounds("jet", CE::Estimator::jet_fitting, jet, params::default_values());
  expect_reach_bounds("jet, ill-conditioned", CE::Estimator::jet_fitting, jet, params::max_condition_number(1.5));
  expect_reach_bounds("jet, ball", CE::Estimator::jet_fitting, jet, params::ball_radius(3 * mean_edge()));
}

// Balls of half a mean edge grow for lack of vertices (to at least twice the fit's unknowns), past the
// a-priori grown_distance at some vertices: the per-vertex reach still bounds what each estimate read.
TEST(NeighborhoodReach, PerVertexReachOverBalls)
{
  const double h = mean_edge();
  std::size_t past = 0;
  for (const double r : {0.5 * h, 2.5 * h}) {
    past += expect_reach_bounds("paraboloid, ball", CE::Estimator::paraboloid_fitting, paraboloid,
                                params::ball_radius(r), true);
    past += expect_reach_bounds("gauss map, ball", CE::Estimator::gauss_map, gauss_map, params::ball_radius(r), true);
    past += expect_reach_bounds("jet, ball", CE::Estimator::jet_fitting, jet, params::ball_radius(r), true);
  }
  EXPECT_GT(past, 0u); // the a-priori bound alone would not do
}

TEST(NeighborhoodReach, ParametersAreTheEstimatorsOwn)
{
  // A degree the estimator refuses, a radius where it takes none, rings past the widest.
  EXPECT_THROW(CE::neighborhood_reach(CE::Estimator::paraboloid_fitting, params::fit_degree(5)), std::invalid_argument);
  EXPECT_THROW(CE::neighborhood_reach(CE::Estimator::taubin, params::ball_radius(1.0)), std::invalid_argument);
  EXPECT_THROW(
    CE::neighborhood_reach(CE::Estimator::jet_fitting, params::neighborhood_rings(3).max_neighborhood_rings(2)),
    std::invalid_argument);
  // Point sets: the k nearest, 4k once widened twice (max_neighborhood_rings 3), or the radius.
  const CE::Neighborhood_reach k = CE::neighborhood_reach(CE::Estimator::point_set, params::number_of_neighbors(20));
  EXPECT_EQ(k.neighbors, 20u);
  EXPECT_EQ(k.widened_neighbors, 80u);
  const CE::Neighborhood_reach ball = CE::neighborhood_reach(CE::Estimator::point_set, params::neighbor_radius(0.5));
  EXPECT_EQ(ball.distance, 0.5);
  EXPECT_EQ(ball.neighbors, 0u);
}

// Point sets with given normals (no orientation over the whole set): the points beyond the k nearest
// (4k where not ok) move without changing a point's estimate.
TEST(NeighborhoodReach, PointSetsOverNearestNeighbors)
{
  std::vector<Eigen::Vector3d> samples;
  std::vector<ce_test::Exact_curvature> exact;
  ce_test::torus_samples(3000, 5, samples, exact);
  std::vector<Kernel::Point_3> points;
  std::vector<Kernel::Vector_3> normals;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    points.emplace_back(samples[i].x(), samples[i].y(), samples[i].z());
    normals.emplace_back(exact[i].normal.x(), exact[i].normal.y(), exact[i].normal.z());
  }
  const auto estimate = [&](const std::vector<Kernel::Point_3>& p, std::vector<double>& H,
                            std::vector<CE::Estimation_status>& status) {
    H.assign(p.size(), 0);
    status.assign(p.size(), CE::Estimation_status::not_estimable);
    std::vector<std::size_t> indices(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      indices[i] = i;
    CE::point_set_curvatures(indices, params::point_map(CGAL::make_property_map(p))
                                        .normal_map(CGAL::make_property_map(normals))
                                        .fit_degree(3)
                                        .vertex_mean_curvature_map(CGAL::make_property_map(H))
                                        .vertex_estimation_status_map(CGAL::make_property_map(status)));
  };
  const CE::Neighborhood_reach reach = CE::neighborhood_reach(CE::Estimator::point_set, params::fit_degree(3));
  std::vector<double> H, moved_H;
  std::vector<CE::Estimation_status> status, moved_status;
  estimate(points, H, status);
  for (std::size_t i = 0; i < points.size(); i += 97) {
    const std::size_t k = status[i] == CE::Estimation_status::ok ? reach.neighbors : reach.widened_neighbors;
    std::vector<double> distance(points.size());
    for (std::size_t j = 0; j < points.size(); ++j)
      distance[j] = std::sqrt(CGAL::squared_distance(points[i], points[j]));
    std::vector<double> sorted = distance;
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end()); // the point itself is sorted[0]
    std::vector<Kernel::Point_3> moved = points;
    std::mt19937 gen{std::uint32_t(i)};
    for (std::size_t j = 0; j < points.size(); ++j)
      if (distance[j] > sorted[k])
        moved[j] = points[i] + (points[j] - points[i]) * (1 + ce_test::uniform(gen, 0.01, 0.1));
    estimate(moved, moved_H, moved_status);
    EXPECT_EQ(moved_status[i], status[i]) << "point " << i;
    EXPECT_TRUE(same_bits(moved_H[i], H[i])) << "point " << i << ": H " << H[i] << " became " << moved_H[i];
  }
}
