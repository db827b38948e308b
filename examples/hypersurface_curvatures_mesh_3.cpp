// SPDX-License-Identifier: GPL-3.0-or-later
// Meshes the unit ball with CGAL Mesh_3, defines a scalar field f on its vertices,
// and estimates the three principal curvatures of the graph W = f(x, y, z), a
// hypersurface of R^4, directly on the C3T3's triangulation.
// Usage: hypersurface_curvatures_mesh_3 [out.csv]   (one row per vertex: x,y,z,f,k1,k2,k3,H,K,status)
#include <CGAL/Curvature_estimation/Tetrahedral_complex_traits.h>
#include <CGAL/Curvature_estimation/hypersurface_paraboloid_fitting.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

namespace CE = CGAL::Curvature_estimation;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
using Vertex_handle = Tr::Vertex_handle;

// The scalar field: f = 0.4 (x^2 + y^2 + z^2), Hamann's function 2.
double field(double x, double y, double z) { return 0.4 * (x * x + y * y + z * z); }

// f at a vertex, as a readable property map.
struct Field_map
{
  using key_type = Vertex_handle;
  using value_type = double;
  using reference = double;
  using category = boost::readable_property_map_tag;
  friend double get(const Field_map&, Vertex_handle v)
  {
    const auto& p = v->point();
    return field(p.x(), p.y(), p.z());
  }
};

int main(int argc, char** argv)
{
  // A small mesh of the unit ball.
  auto ball = [](const K::Point_3& p) { return CGAL::squared_distance(p, K::Point_3(CGAL::ORIGIN)) - 1.0; };
  const Domain domain = Domain::create_implicit_mesh_domain(ball, K::Sphere_3(CGAL::ORIGIN, 4.0));
  namespace P = CGAL::parameters;
  const Criteria criteria(P::facet_angle = 25, P::facet_size = 0.2, P::facet_distance = 0.02,
                          P::cell_radius_edge_ratio = 3, P::cell_size = 0.2);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, P::no_perturb(), P::no_exude());
  const Tr& tr = c3t3.triangulation();

  // The triangulation's points lifted to R^4 by the field, and the outputs.
  const auto points = CE::make_graph_point_map(CE::Tetrahedral_complex_traits<Tr>::Default_point_map(), Field_map());
  std::map<Vertex_handle, CE::Hypersurface_principal_curvatures_and_directions<std::array<double, 4>>> principal;
  std::map<Vertex_handle, double> H, Kg;
  std::map<Vertex_handle, CE::Estimation_status> status;
  CE::hypersurface_paraboloid_fitting_curvatures(
    tr, CE::parameters::vertex_point_map(points)
          .vertex_principal_curvatures_and_directions_map(boost::make_assoc_property_map(principal))
          .vertex_mean_curvature_map(boost::make_assoc_property_map(H))
          .vertex_Gaussian_curvature_map(boost::make_assoc_property_map(Kg))
          .vertex_estimation_status_map(boost::make_assoc_property_map(status)));

  // Summary. With the upward normal the graph of the convex f bends towards the
  // normal, so the curvatures are negative; at distance r from the axis the exact
  // ones are -0.8/l^3 (radial) and -0.8/l (twice), l = sqrt(1 + 0.64 r^2).
  std::size_t counts[3] = {0, 0, 0};
  double error2 = 0, kmin[3] = {1e300, 1e300, 1e300}, kmax[3] = {-1e300, -1e300, -1e300};
  std::size_t estimated = 0;
  std::ofstream csv;
  if (argc > 1) {
    csv.open(argv[1]);
    csv << "x,y,z,f,k1,k2,k3,H,K,status\n";
  }
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    const Vertex_handle vh = v;
    ++counts[static_cast<int>(status[vh])];
    const auto& p = principal[vh];
    const auto q = get(points, vh);
    if (csv)
      csv << q[0] << ',' << q[1] << ',' << q[2] << ',' << q[3] << ',' << p.max_curvature << ',' << p.mid_curvature
          << ',' << p.min_curvature << ',' << H[vh] << ',' << Kg[vh] << ',' << CE::to_string(status[vh]) << '\n';
    if (status[vh] == CE::Estimation_status::not_estimable)
      continue;
    const double k[3] = {p.max_curvature, p.mid_curvature, p.min_curvature};
    for (int i = 0; i < 3; ++i) {
      kmin[i] = (std::min)(kmin[i], k[i]);
      kmax[i] = (std::max)(kmax[i], k[i]);
    }
    const double r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    const double l = std::sqrt(1 + 0.64 * r2);
    const double exact_H = -(0.8 / (l * l * l) + 2 * 0.8 / l) / 3;
    error2 += (H[vh] - exact_H) * (H[vh] - exact_H);
    ++estimated;
  }
  std::printf("Mesh_3 ball: %zu vertices, %zu cells in the complex, %zu finite cells in the triangulation\n",
              tr.number_of_vertices(), std::size_t(c3t3.number_of_cells_in_complex()),
              std::size_t(tr.number_of_finite_cells()));
  std::printf("status: %zu ok, %zu widened, %zu not estimable\n", counts[0], counts[1], counts[2]);
  const char* names[3] = {"k1", "k2", "k3"};
  for (int i = 0; i < 3; ++i)
    std::printf("%s in [%.4f, %.4f]\n", names[i], kmin[i], kmax[i]);
  std::printf("RMS error of H against the exact value: %.4f (exact H in [%.4f, %.4f])\n",
              estimated ? std::sqrt(error2 / double(estimated)) : 0.0,
              -(0.8 / std::pow(1.64, 1.5) + 1.6 / std::sqrt(1.64)) / 3, -0.8);
  return estimated > 0 ? 0 : 1;
}
