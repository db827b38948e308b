// SPDX-License-Identifier: GPL-3.0-or-later
// Test surfaces with exact curvature, mesh builders and error statistics,
// shared by the tests and the accuracy benchmarks of CGAL::Curvature_estimation.
//
// Header-only, no GoogleTest dependency; everything lives in namespace `ce_test`.
//
// Curvature sign convention (the library's, see DESIGN.md "Conventions"):
// with outward normals a sphere of radius r has k_max = k_min = H = 1/r and K = 1/r^2.
// For a graph z = f(x,y) the normal is the UPWARD one, n = (-f_x, -f_y, 1)/l,
// l = sqrt(1 + f_x^2 + f_y^2), and the curvatures are the eigenvalues of
//     -(1/l) Hess(f) G^{-1},   G = [[1+f_x^2, f_x f_y], [f_x f_y, 1+f_y^2]],
// so the upper hemisphere z = sqrt(4 - x^2 - y^2) has k = +1/2 (its upward normal is outward).
// This is MINUS the curvature of Hamann's thesis (eq. 4.15 uses +(1/l) Hess G^{-1}).
//
// Soups and meshes: every builder returns a `Soup` (points, counter-clockwise triangles,
// parameters). `to_mesh<Mesh>(soup)` builds any CGAL FaceGraph through
// `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh`, which adds one vertex per
// soup point, in soup order. Consequently, for `CGAL::Surface_mesh` and `CGAL::Polyhedron_3`
// (both checked in test_common_surfaces.cpp), the i-th vertex of `vertices(mesh)` is soup
// point i; `soup_order_vertices(mesh)` returns that vector, so per-vertex values of an
// estimator can be compared index by index with the exact values of the soup.

#ifndef CE_TEST_COMMON_TEST_SURFACES_H
#define CE_TEST_COMMON_TEST_SURFACES_H

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Dense>

#include "random_numbers.h"

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ce_test {

constexpr double pi = 3.14159265358979323846;

// ===========================================================================
// 1. Hamann's test functions (thesis Table 4.1)
// ===========================================================================

/// A bivariate function with analytic first and second derivatives.
struct Graph_function
{
  std::string name;
  std::function<double(double, double)> f, fx, fy, fxx, fxy, fyy;
};

/// The 9 functions of Hamann's thesis Table 4.1, in the table's order, all on [-1,1]^2:
///   1 plane .2(x+y)              2 cylinder sqrt(2-x^2)        3 sphere sqrt(4-(x^2+y^2))
///   4 paraboloid .4(x^2+y^2)     5 hyperboloid .4(x^2-y^2)     6 monkey saddle .2(x^3-3xy^2)
///   7 cubic .15(x^3+2x^2y-xy+2y^2)  8 exponential exp(-(x^2+y^2)/2)  9 trigonometric .1(cos pi x + cos pi y)
/// (The printed table has typos, e.g. the monkey saddle without its factor .2; these formulas are the verified ones.)
/// Names: "plane", "cylinder", "sphere", "paraboloid", "hyperboloid", "monkey_saddle",
/// "cubic", "exponential", "trigonometric".
inline std::vector<Graph_function> hamann_table1_functions()
{
  using std::cos;
  using std::exp;
  using std::sin;
  using std::sqrt;
  std::vector<Graph_function> fs;

  fs.push_back({"plane", [](double x, double y) { return 0.2 * (x + y); }, [](double, double) { return 0.2; },
                [](double, double) { return 0.2; }, [](double, double) { return 0.0; },
                [](double, double) { return 0.0; }, [](double, double) { return 0.0; }});

  // s = sqrt(2 - x^2): s_x = -x/s, s_xx = -(s^2 + x^2)/s^3 = -2/s^3.
  fs.push_back({"cylinder", [](double x, double) { return sqrt(2.0 - x * x); },
                [](double x, double) { return -x / sqrt(2.0 - x * x); }, [](double, double) { return 0.0; },
                [](double x, double) {
                  const double s = sqrt(2.0 - x * x);
                  return -2.0 / (s * s * s);
                },
                [](double, double) { return 0.0; }, [](double, double) { return 0.0; }});

  // s = sqrt(4 - x^2 - y^2): s_x = -x/s, s_xx = -(4 - y^2)/s^3, s_xy = -xy/s^3, s_yy = -(4 - x^2)/s^3.
  fs.push_back({"sphere", [](double x, double y) { return sqrt(4.0 - x * x - y * y); },
                [](double x, double y) { return -x / sqrt(4.0 - x * x - y * y); },
                [](double x, double y) { return -y / sqrt(4.0 - x * x - y * y); },
                [](double x, double y) {
                  const double s = sqrt(4.0 - x * x - y * y);
                  return -(4.0 - y * y) / (s * s * s);
                },
                [](double x, double y) {
                  const double s = sqrt(4.0 - x * x - y * y);
                  return -x * y / (s * s * s);
                },
                [](double x, double y) {
                  const double s = sqrt(4.0 - x * x - y * y);
                  return -(4.0 - x * x) / (s * s * s);
                }});

  fs.push_back({"paraboloid", [](double x, double y) { return 0.4 * (x * x + y * y); },
                [](double x, double) { return 0.8 * x; }, [](double, double y) { return 0.8 * y; },
                [](double, double) { return 0.8; }, [](double, double) { return 0.0; },
                [](double, double) { return 0.8; }});

  fs.push_back({"hyperboloid", [](double x, double y) { return 0.4 * (x * x - y * y); },
                [](double x, double) { return 0.8 * x; }, [](double, double y) { return -0.8 * y; },
                [](double, double) { return 0.8; }, [](double, double) { return 0.0; },
                [](double, double) { return -0.8; }});

  fs.push_back({"monkey_saddle", [](double x, double y) { return 0.2 * (x * x * x - 3.0 * x * y * y); },
                [](double x, double y) { return 0.6 * (x * x - y * y); },
                [](double x, double y) { return -1.2 * x * y; }, [](double x, double) { return 1.2 * x; },
                [](double, double y) { return -1.2 * y; }, [](double x, double) { return -1.2 * x; }});

  fs.push_back({"cubic", [](double x, double y) { return 0.15 * (x * x * x + 2.0 * x * x * y - x * y + 2.0 * y * y); },
                [](double x, double y) { return 0.15 * (3.0 * x * x + 4.0 * x * y - y); },
                [](double x, double y) { return 0.15 * (2.0 * x * x - x + 4.0 * y); },
                [](double x, double y) { return 0.15 * (6.0 * x + 4.0 * y); },
                [](double x, double) { return 0.15 * (4.0 * x - 1.0); }, [](double, double) { return 0.6; }});

  fs.push_back({"exponential", [](double x, double y) { return exp(-0.5 * (x * x + y * y)); },
                [](double x, double y) { return -x * exp(-0.5 * (x * x + y * y)); },
                [](double x, double y) { return -y * exp(-0.5 * (x * x + y * y)); },
                [](double x, double y) { return (x * x - 1.0) * exp(-0.5 * (x * x + y * y)); },
                [](double x, double y) { return x * y * exp(-0.5 * (x * x + y * y)); },
                [](double x, double y) { return (y * y - 1.0) * exp(-0.5 * (x * x + y * y)); }});

  fs.push_back({"trigonometric", [](double x, double y) { return 0.1 * (cos(pi * x) + cos(pi * y)); },
                [](double x, double) { return -0.1 * pi * sin(pi * x); },
                [](double, double y) { return -0.1 * pi * sin(pi * y); },
                [](double x, double) { return -0.1 * pi * pi * cos(pi * x); }, [](double, double) { return 0.0; },
                [](double, double y) { return -0.1 * pi * pi * cos(pi * y); }});

  return fs;
}

/// One row of Hamann's Table 4.1: RMS errors over the 51x51 grid on [-1,1]^2.
///
/// Column meaning in OUR convention: Hamann uses the upward normal with the opposite sign
/// (his curvatures are the eigenvalues of +(1/l) Hess G^{-1}, i.e. minus ours) and his k1
/// column is the SMALLER of his two curvatures, which is -(our k_max). Hence
///   k1 = RMS error of our k_max,   k2 = RMS error of our k_min,
///   H  = RMS error of our H (= (k_max + k_min)/2, sign flipped, same RMS),
///   K  = RMS error of our K (= k_max * k_min, sign-invariant).
struct Table1_row
{
  double k1, k2, H, K;
};

/// The published values of Hamann's Table 4.1, in the order of `hamann_table1_functions()`.
inline std::vector<Table1_row> hamann_table1_published()
{
  return {
    {0.0, 0.0, 0.0, 0.0},                     // 1 plane
    {0.000291, 0.000035, 0.000132, 0.000025}, // 2 cylinder
    {0.000159, 0.000046, 0.000080, 0.000080}, // 3 sphere
    {0.003073, 0.001342, 0.001358, 0.001684}, // 4 paraboloid
    {0.002058, 0.002058, 0.001057, 0.001767}, // 5 hyperboloid
    {0.004483, 0.004483, 0.001591, 0.007247}, // 6 monkey saddle
    {0.002258, 0.003598, 0.001665, 0.002242}, // 7 cubic
    {0.001757, 0.005546, 0.002722, 0.002602}, // 8 exponential
    {0.002998, 0.002821, 0.001013, 0.003541}, // 9 trigonometric
  };
}

// ===========================================================================
// 2. Exact curvature
// ===========================================================================

/// Exact curvature at a surface point, in the library's convention.
/// k_max >= k_min, H = (k_max + k_min)/2, K = k_max * k_min; `normal` is the unit normal
/// the signs refer to (upward for graphs, outward for closed surfaces); d_max and d_min are
/// unit tangent principal directions with d_max x d_min = normal. At an umbilic point
/// (k_max == k_min) the directions are an arbitrary orthonormal tangent pair.
struct Exact_curvature
{
  double k_max, k_min, H, K;
  Eigen::Vector3d normal, d_max, d_min;
};

namespace internal {

/// Eigen-decomposition of the symmetric shape matrix [[a, b], [b, c]] given in the
/// orthonormal tangent frame (e1, e2), e1 x e2 = n.
inline Exact_curvature from_shape_matrix(const Eigen::Vector3d& n, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                                         double a, double b, double c)
{
  Exact_curvature r;
  const double m = 0.5 * (a + c);
  const double d = std::hypot(0.5 * (a - c), b);
  r.k_max = m + d;
  r.k_min = m - d;
  r.H = m;
  r.K = a * c - b * b;
  // The k_max eigenvector of [[a,b],[b,c]] is (cos t, sin t), t = atan2(2b, a-c)/2
  // (t = 0 at an umbilic, where any direction is principal).
  const double t = 0.5 * std::atan2(2.0 * b, a - c);
  r.normal = n;
  r.d_max = (std::cos(t) * e1 + std::sin(t) * e2).normalized();
  r.d_min = n.cross(r.d_max).normalized();
  return r;
}

/// Some unit vector orthogonal to the unit vector n.
inline Eigen::Vector3d any_orthogonal(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d axis = (std::abs(n.x()) < 0.6)   ? Eigen::Vector3d::UnitX()
                               : (std::abs(n.y()) < 0.6) ? Eigen::Vector3d::UnitY()
                                                         : Eigen::Vector3d::UnitZ();
  return (axis - axis.dot(n) * n).normalized();
}

} // namespace internal

/// Exact curvature of the graph z = g.f(x,y) at (x, y), upward normal, library sign
/// convention (eigenvalues of -(1/l) Hess(f) G^{-1}). Directions: the generalized eigenvectors
/// (a,b) of (-Hess/l) a = k G a mapped to a x_u + b x_v, x_u = (1,0,f_x), x_v = (0,1,f_y), normalised.
///
/// Closed form: e1 = x_u/|x_u|, e2 = n x e1 is an orthonormal tangent frame. Any tangent vector
/// t = a x_u + b x_v has parameter coordinates (a, b) = (t_x, t_y), so with P = [[e1_x, e2_x],
/// [e1_y, e2_y]] the shape operator in the frame is the symmetric S = P^T (-Hess/l) P, whose
/// eigenvalues and eigenvectors are computed in closed form.
inline Exact_curvature graph_curvature(const Graph_function& g, double x, double y)
{
  const double fx = g.fx(x, y), fy = g.fy(x, y);
  const double fxx = g.fxx(x, y), fxy = g.fxy(x, y), fyy = g.fyy(x, y);
  const double l = std::sqrt(1.0 + fx * fx + fy * fy);
  const Eigen::Vector3d n = Eigen::Vector3d(-fx, -fy, 1.0) / l;
  const Eigen::Vector3d e1 = Eigen::Vector3d(1.0, 0.0, fx).normalized();
  const Eigen::Vector3d e2 = n.cross(e1).normalized();
  Eigen::Matrix2d P;
  P << e1.x(), e2.x(), e1.y(), e2.y();
  Eigen::Matrix2d II;
  II << -fxx / l, -fxy / l, -fxy / l, -fyy / l;
  const Eigen::Matrix2d S = P.transpose() * II * P;
  return internal::from_shape_matrix(n, e1, e2, S(0, 0), 0.5 * (S(0, 1) + S(1, 0)), S(1, 1));
}

/// Exact curvature of the sphere of the given radius centred at the origin, at (the radial
/// projection of) p, outward normal: k_max = k_min = H = 1/radius, K = 1/radius^2.
inline Exact_curvature sphere_curvature(double radius, const Eigen::Vector3d& p)
{
  Exact_curvature r;
  r.normal = p.normalized();
  r.k_max = r.k_min = r.H = 1.0 / radius;
  r.K = 1.0 / (radius * radius);
  r.d_max = internal::any_orthogonal(r.normal);
  r.d_min = r.normal.cross(r.d_max).normalized();
  return r;
}

/// Point of the torus with major radius R (centre circle in the xy-plane, around the z-axis)
/// and minor radius r, at parameters (u, v): ((R + r cos v) cos u, (R + r cos v) sin u, r sin v).
/// x_u x x_v points outward.
inline Eigen::Vector3d torus_point(double R, double r, double u, double v)
{
  const double w = R + r * std::cos(v);
  return Eigen::Vector3d(w * std::cos(u), w * std::sin(u), r * std::sin(v));
}

/// Exact curvature of the torus (R > r > 0) at parameters (u, v), outward normal:
/// k_max = 1/r along the tube (the meridian, direction x_v), k_min = cos v/(R + r cos v)
/// along the parallel (direction x_u). On the outer equator (v = 0) both are positive,
/// on the inner equator (v = pi) k_min = -1/(R - r) < 0.
inline Exact_curvature torus_curvature(double R, double r, double u, double v)
{
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  Exact_curvature c;
  c.normal = Eigen::Vector3d(cv * cu, cv * su, sv);
  c.k_max = 1.0 / r;
  c.k_min = cv / (R + r * cv);
  c.H = 0.5 * (c.k_max + c.k_min);
  c.K = c.k_max * c.k_min;
  c.d_max = Eigen::Vector3d(-sv * cu, -sv * su, cv);
  c.d_min = c.normal.cross(c.d_max); // = (su, -cu, 0): along the parallel
  return c;
}

/// Exact torus curvature at the point of the torus nearest to p (u = atan2(y, x),
/// v = atan2(z, sqrt(x^2 + y^2) - R)).
inline Exact_curvature torus_curvature_at(double R, double r, const Eigen::Vector3d& p)
{
  const double u = std::atan2(p.y(), p.x());
  const double v = std::atan2(p.z(), std::hypot(p.x(), p.y()) - R);
  return torus_curvature(R, r, u, v);
}

/// n points uniformly random by area on the torus (R, r) = (1, 0.4), appended to `points`, with their
/// exact curvature appended to `exact`. Deterministic given the seed.
inline void torus_samples(std::size_t n, std::uint32_t seed, std::vector<Eigen::Vector3d>& points,
                          std::vector<Exact_curvature>& exact)
{
  const double R = 1, r = 0.4;
  std::mt19937 gen(seed);
  while (points.size() < n) { // uniform by area: accept with probability (R + r cos v) / (R + r)
    const double u = uniform(gen, 0, 2 * pi), v = uniform(gen, 0, 2 * pi);
    if (uniform(gen, 0, R + r) > R + r * std::cos(v))
      continue;
    points.push_back(torus_point(R, r, u, v));
    exact.push_back(torus_curvature(R, r, u, v));
  }
}

/// Exact curvature of the implicit surface F = 0 at a point where grad F = `gradient` (non-zero)
/// and the Hessian of F is `hessian`; the normal is gradient/|gradient| and the shape operator is
/// the Hessian restricted to the tangent plane, divided by |gradient|. With this sign the sphere
/// F = |x|^2 - r^2 (outward gradient) has k = +1/r, and the graph F = z - f(x,y) (upward
/// gradient) agrees with `graph_curvature`: the library's convention.
inline Exact_curvature implicit_curvature(const Eigen::Vector3d& gradient, const Eigen::Matrix3d& hessian)
{
  const double len = gradient.norm();
  const Eigen::Vector3d n = gradient / len;
  const Eigen::Vector3d e1 = internal::any_orthogonal(n);
  const Eigen::Vector3d e2 = n.cross(e1).normalized();
  const Eigen::Vector3d h1 = hessian * e1, h2 = hessian * e2;
  return internal::from_shape_matrix(n, e1, e2, e1.dot(h1) / len, 0.5 * (e1.dot(h2) + e2.dot(h1)) / len,
                                     e2.dot(h2) / len);
}

/// Exact curvature of the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 at the point p on it
/// (outward normal; a = b = c = r gives the sphere's 1/r).
inline Exact_curvature ellipsoid_curvature(double a, double b, double c, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d inv_sq(1.0 / (a * a), 1.0 / (b * b), 1.0 / (c * c));
  return implicit_curvature(2.0 * p.cwiseProduct(inv_sq), Eigen::Matrix3d(2.0 * inv_sq.asDiagonal()));
}

// ===========================================================================
// 3. Soups and meshes
// ===========================================================================

/// A triangle soup. `faces` are counter-clockwise (seen from +z for graphs, from outside for
/// closed surfaces). `params` has one entry per point: (x, y) for graphs, (u, v) for the torus,
/// (azimuth, polar angle) for the icosphere.
struct Soup
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 3>> faces;
  std::vector<Eigen::Vector2d> params;
};

/// Which diagonal splits each grid quad ((i,j),(i+1,j),(i+1,j+1),(i,j+1)).
enum class Diagonal
{
  main, ///< (i,j)-(i+1,j+1): triangles ((i,j),(i+1,j),(i+1,j+1)) and ((i,j),(i+1,j+1),(i,j+1)), as printed in Hamann's
        ///< thesis
  anti  ///< (i+1,j)-(i,j+1): triangles ((i,j),(i+1,j),(i,j+1)) and ((i+1,j),(i+1,j+1),(i,j+1)); reproduces Hamann's
        ///< numbers
};

namespace internal {

inline void add_grid_quads(std::vector<std::array<std::size_t, 3>>& faces, std::size_t v00, std::size_t v10,
                           std::size_t v11, std::size_t v01, Diagonal d)
{
  if (d == Diagonal::main) {
    faces.push_back({v00, v10, v11});
    faces.push_back({v00, v11, v01});
  } else {
    faces.push_back({v00, v10, v01});
    faces.push_back({v10, v11, v01});
  }
}

inline double grid_coordinate(std::size_t i, std::size_t n, double lo, double hi)
{
  return (i + 1 == n) ? hi : lo + static_cast<double>(i) * (hi - lo) / static_cast<double>(n - 1);
}

inline void check_grid_args(std::size_t n, double lo, double hi)
{
  if (n < 2)
    throw std::invalid_argument("ce_test: a grid needs n >= 2");
  if (!(hi > lo))
    throw std::invalid_argument("ce_test: a grid needs lo < hi");
}

} // namespace internal

/// Graph of g.f over an n x n grid on [x_lo,x_hi] x [y_lo,y_hi]: x_i = x_lo + i (x_hi-x_lo)/(n-1)
/// (x_{n-1} = x_hi exactly), the same for y_j; point (x_i, y_j, f(x_i, y_j)) has index i + n*j
/// (x varies fastest); params = (x, y). Each quad ((i,j),(i+1,j),(i+1,j+1),(i,j+1)) gives two
/// counter-clockwise triangles (seen from +z), split along `d`. n^2 points, 2(n-1)^2 faces.
inline Soup rectangle_grid_graph_soup(const Graph_function& g, std::size_t n, double x_lo, double x_hi, double y_lo,
                                      double y_hi, Diagonal d = Diagonal::anti)
{
  internal::check_grid_args(n, x_lo, x_hi);
  internal::check_grid_args(n, y_lo, y_hi);
  Soup s;
  s.points.reserve(n * n);
  s.params.reserve(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double x = internal::grid_coordinate(i, n, x_lo, x_hi), y = internal::grid_coordinate(j, n, y_lo, y_hi);
      s.points.emplace_back(x, y, g.f(x, y));
      s.params.emplace_back(x, y);
    }
  s.faces.reserve(2 * (n - 1) * (n - 1));
  for (std::size_t j = 0; j + 1 < n; ++j)
    for (std::size_t i = 0; i + 1 < n; ++i)
      internal::add_grid_quads(s.faces, i + n * j, i + 1 + n * j, i + 1 + n * (j + 1), i + n * (j + 1), d);
  return s;
}

/// rectangle_grid_graph_soup on the square [lo,hi]^2. Hamann's set-up is n = 51, lo = -1, hi = 1.
inline Soup grid_graph_soup(const Graph_function& g, std::size_t n, double lo = -1.0, double hi = 1.0,
                            Diagonal d = Diagonal::anti)
{
  return rectangle_grid_graph_soup(g, n, lo, hi, lo, hi, d);
}

/// The grid of `grid_graph_soup` (same indexing, anti diagonals) with its (x,y) positions
/// perturbed: interior vertices by independent uniform offsets in [-a, a) in x and in y,
/// a = jitter_fraction * h, h = (hi-lo)/(n-1); non-corner boundary vertices only along their
/// side; corners fixed. The domain stays exactly [lo,hi]^2. z = f(x,y) at the moved position.
/// For 0 <= jitter_fraction < 0.25 every triangle keeps a positive orientation (throws
/// std::invalid_argument otherwise). Deterministic: two random numbers are drawn per vertex,
/// in index order, from std::mt19937(seed).
inline Soup jittered_grid_graph_soup(const Graph_function& g, std::size_t n, double lo, double hi,
                                     double jitter_fraction, std::uint32_t seed = 1)
{
  internal::check_grid_args(n, lo, hi);
  if (!(jitter_fraction >= 0.0 && jitter_fraction < 0.25))
    throw std::invalid_argument("ce_test: jitter_fraction must be in [0, 0.25)");
  std::mt19937 gen(seed);
  const double a = jitter_fraction * (hi - lo) / static_cast<double>(n - 1);
  Soup s;
  s.points.reserve(n * n);
  s.params.reserve(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = a * uniform_symmetric(gen);
      const double dy = a * uniform_symmetric(gen);
      const bool x_side = (i == 0 || i + 1 == n), y_side = (j == 0 || j + 1 == n);
      double x = internal::grid_coordinate(i, n, lo, hi), y = internal::grid_coordinate(j, n, lo, hi);
      if (!x_side)
        x += dx; // x moves unless the vertex lies on a side x = lo or x = hi
      if (!y_side)
        y += dy;
      s.points.emplace_back(x, y, g.f(x, y));
      s.params.emplace_back(x, y);
    }
  s.faces.reserve(2 * (n - 1) * (n - 1));
  for (std::size_t j = 0; j + 1 < n; ++j)
    for (std::size_t i = 0; i + 1 < n; ++i)
      internal::add_grid_quads(s.faces, i + n * j, i + 1 + n * j, i + 1 + n * (j + 1), i + n * (j + 1), Diagonal::anti);
  return s;
}

/// Graph of g.f over a Delaunay triangulation (in the xy-plane, CGAL::Delaunay_triangulation_2
/// with Epick) of exactly n_points points of [lo,hi]^2 (n_points >= 9):
///  - with s = round(sqrt(n_points)) and h = (hi-lo)/(s-1) (the spacing of a grid of the same size):
///  - indices 0..3: the corners (lo,lo), (hi,lo), (hi,hi), (lo,hi);
///  - then s-2 points on each side (bottom, right, top, left), stratified: the k-th at
///    k*h + uniform[-0.3h, 0.3h) from the side's start, so neighbors are >= 0.4h apart;
///  - then the rest at random in the interior, by dart throwing: uniform in
///    [lo + h/4, hi - h/4]^2, rejected if closer than h/2 to an accepted point (no slivers from
///    near-coincident points).
/// Faces counter-clockwise seen from +z; params = (x, y); the boundary is the square.
/// Deterministic given the seed (std::mt19937 raw output only).
inline Soup delaunay_graph_soup(const Graph_function& g, std::size_t n_points, double lo = -1.0, double hi = 1.0,
                                std::uint32_t seed = 1)
{
  if (n_points < 9)
    throw std::invalid_argument("ce_test: delaunay_graph_soup needs n_points >= 9");
  if (!(hi > lo))
    throw std::invalid_argument("ce_test: delaunay_graph_soup needs lo < hi");
  std::mt19937 gen(seed);
  const std::size_t s = static_cast<std::size_t>(std::lround(std::sqrt(static_cast<double>(n_points))));
  const double L = hi - lo;
  const double h = L / static_cast<double>(s - 1);
  const std::size_t m = s - 2;

  std::vector<Eigen::Vector2d> xy;
  xy.reserve(n_points);
  xy.emplace_back(lo, lo);
  xy.emplace_back(hi, lo);
  xy.emplace_back(hi, hi);
  xy.emplace_back(lo, hi);
  const Eigen::Vector2d start[4] = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  const Eigen::Vector2d dir[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  for (int side = 0; side < 4; ++side)
    for (std::size_t k = 1; k <= m; ++k) {
      const double t = static_cast<double>(k) * h + 0.3 * h * uniform_symmetric(gen);
      xy.push_back(start[side] + t * dir[side]);
    }
  if (xy.size() > n_points)
    throw std::logic_error("ce_test: delaunay_graph_soup boundary count");

  // Dart throwing with a bucket grid of cell size r.
  const double r = 0.5 * h;
  const std::size_t nc = static_cast<std::size_t>(std::ceil(L / r)) + 1;
  std::vector<std::vector<std::size_t>> cells(nc * nc);
  auto cell_of = [&](double v) {
    const long c = static_cast<long>(std::floor((v - lo) / r));
    return static_cast<std::size_t>(std::min<long>(std::max<long>(c, 0), static_cast<long>(nc) - 1));
  };
  for (std::size_t i = 0; i < xy.size(); ++i)
    cells[cell_of(xy[i].x()) + nc * cell_of(xy[i].y())].push_back(i);
  const std::size_t max_attempts = 1000 + 200 * n_points;
  std::size_t attempts = 0;
  while (xy.size() < n_points) {
    if (++attempts > max_attempts)
      throw std::runtime_error("ce_test: delaunay_graph_soup could not place the interior points");
    const Eigen::Vector2d p(lo + 0.5 * r + uniform01(gen) * (L - r), lo + 0.5 * r + uniform01(gen) * (L - r));
    const std::size_t cx = cell_of(p.x()), cy = cell_of(p.y());
    bool ok = true;
    for (std::size_t yy = (cy > 0 ? cy - 1 : 0); ok && yy <= std::min(cy + 1, nc - 1); ++yy)
      for (std::size_t xx = (cx > 0 ? cx - 1 : 0); ok && xx <= std::min(cx + 1, nc - 1); ++xx)
        for (std::size_t q : cells[xx + nc * yy])
          if ((xy[q] - p).squaredNorm() < r * r) {
            ok = false;
            break;
          }
    if (!ok)
      continue;
    cells[cx + nc * cy].push_back(xy.size());
    xy.push_back(p);
  }

  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
  std::vector<std::pair<K::Point_2, std::size_t>> input;
  input.reserve(xy.size());
  for (std::size_t i = 0; i < xy.size(); ++i)
    input.emplace_back(K::Point_2(xy[i].x(), xy[i].y()), i);
  DT dt(input.begin(), input.end());
  if (dt.number_of_vertices() != xy.size())
    throw std::logic_error("ce_test: duplicate Delaunay points");

  Soup out;
  out.points.reserve(xy.size());
  out.params = xy;
  for (const Eigen::Vector2d& p : xy)
    out.points.emplace_back(p.x(), p.y(), g.f(p.x(), p.y()));
  out.faces.reserve(dt.number_of_faces());
  for (auto fh : dt.finite_face_handles()) // CGAL's finite faces are counter-clockwise
    out.faces.push_back({fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()});
  return out;
}

/// Icosphere of the given radius centred at the origin: the icosahedron, each triangle split
/// into 4 `subdivisions` times, every point projected onto the sphere. 10*4^s + 2 points,
/// 20*4^s faces, oriented outward. params = (azimuth atan2(y,x), polar angle acos(z/r)).
/// Exact curvature: `sphere_curvature(radius, p)`.
inline Soup sphere_soup(double radius, unsigned subdivisions)
{
  if (!(radius > 0.0))
    throw std::invalid_argument("ce_test: sphere_soup needs radius > 0");
  const double t = 0.5 * (1.0 + std::sqrt(5.0));
  std::vector<Eigen::Vector3d> pts = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : pts)
    p.normalize();
  std::vector<std::array<std::size_t, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& f : faces) { // make every face outward, whatever the table's orientation
    const Eigen::Vector3d nrm = (pts[f[1]] - pts[f[0]]).cross(pts[f[2]] - pts[f[0]]);
    if (nrm.dot(pts[f[0]] + pts[f[1]] + pts[f[2]]) < 0.0)
      std::swap(f[1], f[2]);
  }
  for (unsigned s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end())
        return it->second;
      pts.push_back((pts[a] + pts[b]).normalized());
      mid.emplace(key, pts.size() - 1);
      return pts.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> next;
    next.reserve(4 * faces.size());
    for (const auto& f : faces) {
      const std::size_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.push_back({f[0], a, c});
      next.push_back({f[1], b, a});
      next.push_back({f[2], c, b});
      next.push_back({a, b, c});
    }
    faces.swap(next);
  }
  Soup out;
  out.faces = std::move(faces);
  out.points.reserve(pts.size());
  out.params.reserve(pts.size());
  for (const auto& p : pts) {
    out.points.push_back(radius * p);
    out.params.emplace_back(std::atan2(p.y(), p.x()), std::acos(std::max(-1.0, std::min(1.0, p.z()))));
  }
  return out;
}

/// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1: the unit icosphere of `sphere_soup(1, subdivisions)`
/// scaled by (a, b, c), so oriented outward with 10*4^s + 2 points. With jitter > 0 (in [0, 0.25))
/// every point of the unit icosphere is first moved in its tangent plane by independent uniform
/// offsets in [-jitter*l, jitter*l) along two tangent directions, l its shortest incident edge,
/// and projected back: an irregular mesh whose points lie exactly on the surface (a, b, c all
/// equal give an irregular sphere). params = (azimuth, polar angle) of the unit-sphere point.
/// Exact curvature: `ellipsoid_curvatures(a, b, c, soup)`. Deterministic given the seed.
inline Soup ellipsoid_soup(double a, double b, double c, unsigned subdivisions, double jitter = 0.0,
                           std::uint32_t seed = 1)
{
  if (!(a > 0.0 && b > 0.0 && c > 0.0))
    throw std::invalid_argument("ce_test: ellipsoid_soup needs a, b, c > 0");
  if (!(jitter >= 0.0 && jitter < 0.25))
    throw std::invalid_argument("ce_test: ellipsoid jitter must be in [0, 0.25)");
  Soup s = sphere_soup(1.0, subdivisions);
  if (jitter > 0.0) {
    std::vector<double> shortest(s.points.size(), std::numeric_limits<double>::infinity());
    for (const auto& f : s.faces)
      for (int k = 0; k < 3; ++k) {
        const std::size_t i = f[k], j = f[(k + 1) % 3];
        const double len = (s.points[i] - s.points[j]).norm();
        shortest[i] = std::min(shortest[i], len);
        shortest[j] = std::min(shortest[j], len);
      }
    std::mt19937 gen(seed);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const Eigen::Vector3d& n = s.points[i];
      const Eigen::Vector3d t1 = internal::any_orthogonal(n), t2 = n.cross(t1);
      const double u = uniform_symmetric(gen), v = uniform_symmetric(gen);
      s.points[i] = (n + jitter * shortest[i] * (u * t1 + v * t2)).normalized();
    }
  }
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Eigen::Vector3d& p = s.points[i];
    s.params[i] = Eigen::Vector2d(std::atan2(p.y(), p.x()), std::acos(std::max(-1.0, std::min(1.0, p.z()))));
    s.points[i] = Eigen::Vector3d(a * p.x(), b * p.y(), c * p.z());
  }
  return s;
}

/// Torus (R > r > 0, see `torus_point`) triangulated on the periodic n_u x n_v parameter grid
/// u_i = 2 pi i/n_u, v_j = 2 pi j/n_v (n_u, n_v >= 3); point (i, j) has index i + n_u*j;
/// quads split along the anti diagonal, faces oriented outward. With jitter > 0 (a fraction of
/// the parameter spacings, in [0, 0.25)) every (u_i, v_j) is moved by independent uniform
/// offsets in [-jitter*2pi/n_u, +..) and [-jitter*2pi/n_v, +..): the points stay exactly on the torus.
/// params = the (possibly jittered, unwrapped) (u, v) of each point;
/// exact curvature: `torus_curvature(R, r, params[i].x(), params[i].y())`.
inline Soup torus_soup(double R, double r, std::size_t n_u, std::size_t n_v, double jitter = 0.0,
                       std::uint32_t seed = 1)
{
  if (!(R > r && r > 0.0))
    throw std::invalid_argument("ce_test: torus_soup needs R > r > 0");
  if (n_u < 3 || n_v < 3)
    throw std::invalid_argument("ce_test: torus_soup needs n_u, n_v >= 3");
  if (!(jitter >= 0.0 && jitter < 0.25))
    throw std::invalid_argument("ce_test: torus jitter must be in [0, 0.25)");
  std::mt19937 gen(seed);
  const double du = 2.0 * pi / static_cast<double>(n_u), dv = 2.0 * pi / static_cast<double>(n_v);
  Soup s;
  s.points.reserve(n_u * n_v);
  s.params.reserve(n_u * n_v);
  for (std::size_t j = 0; j < n_v; ++j)
    for (std::size_t i = 0; i < n_u; ++i) {
      const double ju = jitter * du * uniform_symmetric(gen);
      const double jv = jitter * dv * uniform_symmetric(gen);
      const double u = static_cast<double>(i) * du + ju, v = static_cast<double>(j) * dv + jv;
      s.points.push_back(torus_point(R, r, u, v));
      s.params.emplace_back(u, v);
    }
  s.faces.reserve(2 * n_u * n_v);
  for (std::size_t j = 0; j < n_v; ++j)
    for (std::size_t i = 0; i < n_u; ++i) {
      const std::size_t i1 = (i + 1) % n_u, j1 = (j + 1) % n_v;
      internal::add_grid_quads(s.faces, i + n_u * j, i1 + n_u * j, i1 + n_u * j1, i + n_u * j1, Diagonal::anti);
    }
  return s;
}

/// Exact curvatures of a graph soup at each point, from its params (x, y).
inline std::vector<Exact_curvature> graph_curvatures(const Graph_function& g, const Soup& s)
{
  std::vector<Exact_curvature> out;
  out.reserve(s.params.size());
  for (const auto& p : s.params)
    out.push_back(graph_curvature(g, p.x(), p.y()));
  return out;
}

/// Exact curvatures of a torus soup at each point, from its params (u, v).
inline std::vector<Exact_curvature> torus_curvatures(double R, double r, const Soup& s)
{
  std::vector<Exact_curvature> out;
  out.reserve(s.params.size());
  for (const auto& p : s.params)
    out.push_back(torus_curvature(R, r, p.x(), p.y()));
  return out;
}

/// Exact curvatures of a sphere soup (centred at the origin) at each point.
inline std::vector<Exact_curvature> sphere_curvatures(double radius, const Soup& s)
{
  std::vector<Exact_curvature> out;
  out.reserve(s.points.size());
  for (const auto& p : s.points)
    out.push_back(sphere_curvature(radius, p));
  return out;
}

/// Exact curvatures of an ellipsoid soup (`ellipsoid_soup(a, b, c, ...)`) at each point.
inline std::vector<Exact_curvature> ellipsoid_curvatures(double a, double b, double c, const Soup& s)
{
  std::vector<Exact_curvature> out;
  out.reserve(s.points.size());
  for (const auto& p : s.points)
    out.push_back(ellipsoid_curvature(a, b, c, p));
  return out;
}

// --- geometric checks on soups ---

/// Twice the signed area of face f projected to the xy-plane (> 0: counter-clockwise from +z).
inline double signed_area_xy(const Soup& s, std::size_t f)
{
  const auto& t = s.faces[f];
  const Eigen::Vector3d a = s.points[t[1]] - s.points[t[0]], b = s.points[t[2]] - s.points[t[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

/// Signed volume enclosed by a closed soup (> 0: oriented outward).
inline double signed_volume(const Soup& s)
{
  double v = 0.0;
  for (const auto& t : s.faces)
    v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]]));
  return v / 6.0;
}

/// A thick-walled pipe about the y-axis, shaped as CGAL's data mesh pipe.off: four circles of
/// n points (inner radius r_inner and outer r_outer, at y = -length/2 and +length/2) joined by
/// four walls of a single band of triangles each (inner and outer cylinder, two annular caps),
/// faces oriented outward. Every vertex lies on a 90-degree crease. No params.
inline Soup pipe_soup(double r_inner, double r_outer, double length, std::size_t n)
{
  if (!(r_outer > r_inner && r_inner > 0.0 && length > 0.0))
    throw std::invalid_argument("ce_test: pipe_soup needs r_outer > r_inner > 0 and length > 0");
  if (n < 3)
    throw std::invalid_argument("ce_test: pipe_soup needs n >= 3");
  const double radius[4] = {r_inner, r_outer, r_outer, r_inner};
  const double y[4] = {-0.5 * length, -0.5 * length, 0.5 * length, 0.5 * length};
  Soup s;
  for (std::size_t j = 0; j < 4; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double u = 2.0 * pi * static_cast<double>(i) / static_cast<double>(n);
      s.points.emplace_back(radius[j] * std::cos(u), y[j], radius[j] * std::sin(u));
    }
  for (std::size_t j = 0; j < 4; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t i1 = (i + 1) % n, j1 = (j + 1) % 4;
      internal::add_grid_quads(s.faces, i + n * j, i1 + n * j, i1 + n * j1, i + n * j1, Diagonal::anti);
    }
  if (signed_volume(s) < 0.0)
    for (auto& f : s.faces)
      std::swap(f[1], f[2]);
  return s;
}

/// Mean length of the (undirected) edges of the soup; a typical h for convergence studies.
inline double mean_edge_length(const Soup& s)
{
  std::map<std::pair<std::size_t, std::size_t>, double> e;
  for (const auto& t : s.faces)
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      e.emplace(std::make_pair(std::min(a, b), std::max(a, b)), (s.points[a] - s.points[b]).norm());
    }
  double sum = 0.0;
  for (const auto& kv : e)
    sum += kv.second;
  return e.empty() ? 0.0 : sum / static_cast<double>(e.size());
}

// --- meshes ---

/// Builds a `Mesh` (any CGAL FaceGraph supporting CGAL::Euler::add_face, e.g. Surface_mesh or
/// Polyhedron_3, with an internal vertex point map whose value type is constructible from
/// three doubles) from the soup with
/// `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh`. One vertex per soup point,
/// added in soup order: the i-th vertex of `vertices(mesh)` is soup point i (see
/// `soup_order_vertices`). Throws std::runtime_error if the soup is not a valid polygon mesh.
template <class Mesh>
Mesh to_mesh(const Soup& soup)
{
  using VPM = typename boost::property_map<Mesh, CGAL::vertex_point_t>::type;
  using Point = typename boost::property_traits<VPM>::value_type;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for (const auto& p : soup.points)
    points.push_back(Point(p.x(), p.y(), p.z()));
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.faces))
    throw std::runtime_error("ce_test::to_mesh: the soup is not a valid polygon mesh");
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.faces, mesh);
  if (static_cast<std::size_t>(num_vertices(mesh)) != soup.points.size() ||
      static_cast<std::size_t>(num_faces(mesh)) != soup.faces.size())
    throw std::runtime_error("ce_test::to_mesh: vertex or face count differs from the soup");
  return mesh;
}

/// The vertices of `mesh` in iteration order; for a mesh made by `to_mesh`, element i is the
/// vertex of soup point i.
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> soup_order_vertices(const Mesh& mesh)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> out;
  out.reserve(static_cast<std::size_t>(num_vertices(mesh)));
  for (auto v : vertices(mesh))
    out.push_back(v);
  return out;
}

/// A soup, the `Mesh` made of it by `to_mesh` and the exact curvature at its points.
template <class Mesh>
struct Sampled_surface
{
  Soup soup;
  Mesh mesh;
  std::vector<Exact_curvature> exact;
};

/// The torus of `torus_soup` (same arguments) as a `Mesh`, with its exact curvature.
template <class Mesh>
Sampled_surface<Mesh> sampled_torus(double R, double r, std::size_t n_u, std::size_t n_v, double jitter = 0.0,
                                    std::uint32_t seed = 1)
{
  Sampled_surface<Mesh> t{torus_soup(R, r, n_u, n_v, jitter, seed), Mesh(), {}};
  t.mesh = to_mesh<Mesh>(t.soup);
  t.exact = torus_curvatures(R, r, t.soup);
  return t;
}

// ===========================================================================
// 4. Error statistics
// ===========================================================================

/// RMS and maximum absolute error over `count` values. If any added error is NaN or
/// infinite, rms and max are NaN (a failed estimate must not hide in a statistic).
struct Error_stats
{
  double rms = 0.0;
  double max = 0.0;
  std::size_t count = 0;
};

/// Accumulates errors; `stats()` gives their RMS (sqrt of the mean square, as Hamann's eq. 4.32)
/// and maximum absolute value.
class Error_accumulator
{
public:
  /// Adds one error value (its sign does not matter).
  void add(double error)
  {
    ++count_;
    if (!std::isfinite(error)) {
      non_finite_ = true;
      return;
    }
    sum_sq_ += error * error;
    max_ = std::max(max_, std::abs(error));
  }
  /// Adds the error approx - exact.
  void add(double exact, double approx) { add(approx - exact); }

  Error_stats stats() const
  {
    Error_stats s;
    s.count = count_;
    if (non_finite_) {
      s.rms = s.max = std::numeric_limits<double>::quiet_NaN();
    } else if (count_ > 0) {
      s.rms = std::sqrt(sum_sq_ / static_cast<double>(count_));
      s.max = max_;
    }
    return s;
  }
  std::size_t count() const { return count_; }
  void clear() { *this = Error_accumulator(); }

private:
  double sum_sq_ = 0.0;
  double max_ = 0.0;
  std::size_t count_ = 0;
  bool non_finite_ = false;
};

/// The median of `values` (the upper of the two middle ones for an even count).
inline double median(std::vector<double> values)
{
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  return values[mid];
}

/// Observed convergence order p from errors e ~ C h^p at two mesh sizes:
/// p = log(e_coarse/e_fine) / log(h_coarse/h_fine).
inline double observed_order(double e_coarse, double e_fine, double h_coarse, double h_fine)
{
  return std::log(e_coarse / e_fine) / std::log(h_coarse / h_fine);
}

/// The observed order of one error along a refinement: `add(h, e)` at each mesh size h,
/// coarse to fine, gives the order of e against the previous size (none at the first).
class Convergence
{
public:
  std::optional<double> add(double h, double error)
  {
    std::optional<double> order;
    if (h_ > 0)
      order = observed_order(error_, error, h_, h);
    h_ = h;
    error_ = error;
    return order;
  }

private:
  double h_ = 0.0;
  double error_ = 0.0;
};

} // namespace ce_test

#endif // CE_TEST_COMMON_TEST_SURFACES_H
