// SPDX-License-Identifier: GPL-3.0-or-later
// Realistic meshes with exact curvature: marching tetrahedra of implicit surfaces F = 0
// (F < 0 inside), every vertex projected onto the exact surface by Newton steps.
//
// The grid is n x n x n cubes over a cube around the surface, each cube split into the 6 Kuhn
// tetrahedra around its diagonal (i,j,k)-(i+1,j+1,k+1); a tetrahedron the level set crosses gives
// one triangle (one vertex on the other side) or two (two and two, split along a fixed diagonal
// of the quad). Vertices lie on the tetrahedra's edges (cube edges, face diagonals, the cube
// diagonal) and are shared by every tetrahedron around the edge, so the soup is closed,
// manifold and consistently oriented, outward. Nothing is merged or dropped (no two vertices coincide
// and no triangle has zero area at the resolutions tested): the slivers and the
// nearly coincident vertices of marching tetrahedra are the point of this family.
//
// Header-only, no GoogleTest dependency; everything lives in namespace `ce_test`.
#ifndef CE_TEST_COMMON_MARCHING_TETRAHEDRA_H
#define CE_TEST_COMMON_MARCHING_TETRAHEDRA_H

#include "test_surfaces.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ce_test {

/// An implicit surface F = 0 with F < 0 inside, its analytic gradient and Hessian, and the
/// half width of an axis-aligned cube centred at the origin that contains it with a margin.
struct Implicit_surface
{
  std::string name;
  std::function<double(const Eigen::Vector3d&)> value;
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> gradient;
  std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> hessian;
  double half_width;
};

/// The ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 - 1 = 0.
inline Implicit_surface implicit_ellipsoid(double a, double b, double c)
{
  const Eigen::Vector3d inv_sq(1.0 / (a * a), 1.0 / (b * b), 1.0 / (c * c));
  return {"ellipsoid", [inv_sq](const Eigen::Vector3d& p) { return p.cwiseProduct(p).dot(inv_sq) - 1.0; },
          [inv_sq](const Eigen::Vector3d& p) { return Eigen::Vector3d(2.0 * p.cwiseProduct(inv_sq)); },
          [inv_sq](const Eigen::Vector3d&) { return Eigen::Matrix3d(2.0 * inv_sq.asDiagonal()); },
          1.1 * std::max({a, b, c})};
}

/// The torus of `torus_point` (R > r > 0): (sqrt(x^2 + y^2) - R)^2 + z^2 - r^2 = 0, smooth away
/// from the z-axis (its gradient and Hessian are evaluated on the surface only).
inline Implicit_surface implicit_torus(double R, double r)
{
  return {"torus",
          [R, r](const Eigen::Vector3d& p) {
            const double q = std::hypot(p.x(), p.y()) - R;
            return q * q + p.z() * p.z() - r * r;
          },
          [R](const Eigen::Vector3d& p) {
            const double rho = std::hypot(p.x(), p.y()), q = rho - R;
            return Eigen::Vector3d(2.0 * q * p.x() / rho, 2.0 * q * p.y() / rho, 2.0 * p.z());
          },
          [R](const Eigen::Vector3d& p) {
            const double rho = std::hypot(p.x(), p.y()), q = rho - R;
            const double x = p.x(), y = p.y(), rho2 = rho * rho, rho3 = rho2 * rho;
            Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
            h(0, 0) = 2.0 * (x * x / rho2 + q * y * y / rho3);
            h(1, 1) = 2.0 * (y * y / rho2 + q * x * x / rho3);
            h(0, 1) = h(1, 0) = 2.0 * x * y * (1.0 / rho2 - q / rho3);
            h(2, 2) = 2.0;
            return h;
          },
          1.1 * (R + r)};
}

/// A smooth blend of three Gaussian blobs, F = level - sum_i exp(-|x - c_i|^2 / s^2), with
/// level = 0.45, s = 0.55 and the centres (-0.45, -0.2, 0), (0.45, -0.25, 0.1), (0.05, 0.45, -0.15):
/// one closed component of genus 0 with convex lobes and saddle-shaped necks.
inline Implicit_surface gaussian_blobs()
{
  const std::array<Eigen::Vector3d, 3> centres = {Eigen::Vector3d(-0.45, -0.2, 0.0), Eigen::Vector3d(0.45, -0.25, 0.1),
                                                  Eigen::Vector3d(0.05, 0.45, -0.15)};
  const double level = 0.45, inv_s2 = 1.0 / (0.55 * 0.55);
  return {"blobs",
          [=](const Eigen::Vector3d& p) {
            double f = level;
            for (const auto& c : centres)
              f -= std::exp(-(p - c).squaredNorm() * inv_s2);
            return f;
          },
          [=](const Eigen::Vector3d& p) {
            Eigen::Vector3d g = Eigen::Vector3d::Zero();
            for (const auto& c : centres)
              g += 2.0 * inv_s2 * std::exp(-(p - c).squaredNorm() * inv_s2) * (p - c);
            return g;
          },
          [=](const Eigen::Vector3d& p) {
            Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
            for (const auto& c : centres) {
              const Eigen::Vector3d d = p - c;
              const double e = std::exp(-d.squaredNorm() * inv_s2);
              h += 2.0 * inv_s2 * e * (Eigen::Matrix3d::Identity() - 2.0 * inv_s2 * d * d.transpose());
            }
            return h;
          },
          1.5};
}

/// Moves p onto F = 0 by Newton steps along the gradient, p <- p - F grad F / |grad F|^2,
/// until |F| < 1e-14 or after 10 steps.
inline Eigen::Vector3d project_onto(const Implicit_surface& s, Eigen::Vector3d p)
{
  for (int step = 0; step < 10; ++step) {
    const double f = s.value(p);
    if (std::abs(f) < 1e-14)
      break;
    const Eigen::Vector3d g = s.gradient(p);
    p -= (f / g.squaredNorm()) * g;
  }
  return p;
}

/// Marching tetrahedra of `s` on `cells` x `cells` x `cells` cubes of side h = 2 half_width / cells,
/// the grid's corner at (-half_width + offset_i h) on each axis (offset a fraction of h, so that the
/// surface need not align with grid planes). A grid point where F = 0 counts as outside, so every
/// vertex starts strictly inside a tetrahedron edge, at the linear interpolation of F; it is then
/// projected onto the surface (`project_onto`). Faces are counter-clockwise seen from outside;
/// params is empty (the exact curvature is a function of the point: `implicit_curvatures`).
inline Soup marching_tetrahedra_soup(const Implicit_surface& s, std::size_t cells,
                                     const Eigen::Vector3d& offset = Eigen::Vector3d::Zero())
{
  if (cells < 2)
    throw std::invalid_argument("ce_test: marching_tetrahedra_soup needs cells >= 2");
  const std::size_t n = cells + 1; // grid points per axis
  const double h = 2.0 * s.half_width / static_cast<double>(cells);
  const Eigen::Vector3d corner = Eigen::Vector3d::Constant(-s.half_width) + h * offset;
  auto index = [n](std::size_t i, std::size_t j, std::size_t k) { return (k * n + j) * n + i; };
  auto grid_point = [&](std::size_t id) {
    return Eigen::Vector3d(corner.x() + h * static_cast<double>(id % n),
                           corner.y() + h * static_cast<double>(id / n % n),
                           corner.z() + h * static_cast<double>(id / (n * n)));
  };
  std::vector<double> values(n * n * n);
  for (std::size_t id = 0; id < values.size(); ++id)
    values[id] = s.value(grid_point(id));

  Soup out;
  std::unordered_map<std::uint64_t, std::size_t> edge_vertex;
  // Code c in [0, 8) of a cube corner: bit a set for a step of one along axis a.
  std::size_t corner_id[8];
  auto vertex_on = [&](int ca, int cb) { // a point of the edge between corners ca and cb of a Kuhn tetrahedron
    if ((ca & cb) != ca)
      std::swap(ca, cb); // the lower end: a Kuhn edge steps up along some axes
    const std::size_t a = corner_id[ca], b = corner_id[cb];
    const std::uint64_t key = 8 * static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(ca ^ cb);
    const auto found = edge_vertex.find(key);
    if (found != edge_vertex.end())
      return found->second;
    const double t = values[a] / (values[a] - values[b]);
    const Eigen::Vector3d pa = grid_point(a);
    out.points.push_back(project_onto(s, pa + t * (grid_point(b) - pa)));
    edge_vertex.emplace(key, out.points.size() - 1);
    return out.points.size() - 1;
  };
  // The 6 tetrahedra: from corner 0 to corner 7 one step along each axis, in the order of an
  // axis permutation; the odd permutations are listed with their last two corners swapped, so that
  // every tetrahedron (c0, c1, c2, c3) is positively oriented.
  const int axes[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  int tetrahedra[6][4];
  for (int p = 0; p < 6; ++p) {
    const int c1 = 1 << axes[p][0], c2 = c1 | (1 << axes[p][1]);
    const bool odd = p >= 3;
    tetrahedra[p][0] = 0;
    tetrahedra[p][1] = c1;
    tetrahedra[p][2] = odd ? 7 : c2;
    tetrahedra[p][3] = odd ? c2 : 7;
  }
  // The outward faces of a positively oriented tetrahedron, by the corner they are opposite to.
  const int opposite[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (std::size_t k = 0; k < cells; ++k)
    for (std::size_t j = 0; j < cells; ++j)
      for (std::size_t i = 0; i < cells; ++i) {
        int inside_corners = 0;
        for (int c = 0; c < 8; ++c) {
          corner_id[c] = index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          inside_corners += values[corner_id[c]] < 0.0;
        }
        if (inside_corners == 0 || inside_corners == 8)
          continue;
        for (const auto& tet : tetrahedra) {
          bool inside[4];
          int count = 0;
          for (int v = 0; v < 4; ++v)
            count += (inside[v] = values[corner_id[tet[v]]] < 0.0);
          if (count == 0 || count == 4)
            continue;
          if (count != 2) { // one corner on its own side: the triangle separating it, facing away from it when inside
            int lone = 0;
            while (inside[lone] != (count == 1))
              ++lone;
            const int* f = opposite[lone];
            const std::size_t a = vertex_on(tet[lone], tet[f[0]]), b = vertex_on(tet[lone], tet[f[1]]),
                              c = vertex_on(tet[lone], tet[f[2]]);
            out.faces.push_back(count == 1 ? std::array<std::size_t, 3>{a, b, c} : std::array<std::size_t, 3>{a, c, b});
            continue;
          }
          // Two inside (u, w) and two outside (x, y): the quad on edges ux, uy, wy, wx, outward when
          // (u, w, x, y) is an even permutation of the corners, as (0, 1, 2, 3) is.
          int order[4], in = 0, outside = 2;
          for (int v = 0; v < 4; ++v)
            order[inside[v] ? in++ : outside++] = v;
          int inversions = 0;
          for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
              inversions += order[a] > order[b];
          if (inversions % 2 == 1)
            std::swap(order[2], order[3]);
          const int u = tet[order[0]], w = tet[order[1]], x = tet[order[2]], y = tet[order[3]];
          const std::size_t ux = vertex_on(u, x), uy = vertex_on(u, y), wy = vertex_on(w, y), wx = vertex_on(w, x);
          out.faces.push_back({ux, uy, wy});
          out.faces.push_back({ux, wy, wx});
        }
      }
  return out;
}

/// Exact curvature of `s` at each point of a soup whose points lie on it.
inline std::vector<Exact_curvature> implicit_curvatures(const Implicit_surface& s, const Soup& soup)
{
  std::vector<Exact_curvature> out;
  out.reserve(soup.points.size());
  for (const auto& p : soup.points)
    out.push_back(implicit_curvature(s.gradient(p), s.hessian(p)));
  return out;
}

/// The aspect ratio of each face, 4 sqrt(3) area / (sum of its squared edge lengths): 1 for an
/// equilateral triangle, 0 for a degenerate one.
inline std::vector<double> aspect_ratios(const Soup& soup)
{
  std::vector<double> q;
  q.reserve(soup.faces.size());
  for (const auto& t : soup.faces) {
    const Eigen::Vector3d a = soup.points[t[1]] - soup.points[t[0]], b = soup.points[t[2]] - soup.points[t[0]];
    const double sum_sq = a.squaredNorm() + b.squaredNorm() + (b - a).squaredNorm();
    q.push_back(2.0 * std::sqrt(3.0) * a.cross(b).norm() / sum_sq);
  }
  return q;
}

} // namespace ce_test

#endif // CE_TEST_COMMON_MARCHING_TETRAHEDRA_H
