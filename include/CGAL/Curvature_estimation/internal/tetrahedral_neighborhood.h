// SPDX-License-Identifier: GPL-3.0-or-later
// The neighborhood policy that runs the fits of vertex_fitter.h (Hamann's thesis
// §4.3) at the vertices of a tetrahedral complex whose vertices are points of
// R^4: rings over the stars, and the 3-volume-weighted mean of the cells'
// normals as the first-order normal.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TETRAHEDRAL_NEIGHBORHOOD_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TETRAHEDRAL_NEIGHBORHOOD_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Tetrahedral_complex_traits.h>
#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/vertex_fitter.h>

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The estimate at one vertex of a hypersurface of R^4. A not-estimable vertex keeps the NaN defaults.
struct Hypersurface_estimate
{
  Estimation_status status = Estimation_status::not_estimable;
  Eigen::Vector3d curvatures = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()); // decreasing
  Eigen::Matrix<double, 4, 3> directions =
    Eigen::Matrix<double, 4, 3>::Constant(std::numeric_limits<double>::quiet_NaN()); // column i for curvature i
  Eigen::Vector4d normal = Eigen::Vector4d::Constant(std::numeric_limits<double>::quiet_NaN());
};

// The generalized cross product of three vectors of R^4: the n with
// n . x = det(a, b, c, x) for every x (orthogonal to a, b, c; its length is the
// 3-volume of their parallelepiped).
inline Eigen::Vector4d cross_product_4(const Eigen::Vector4d& a, const Eigen::Vector4d& b, const Eigen::Vector4d& c)
{
  auto minor = [&](int i, int j, int k) {
    return a[i] * (b[j] * c[k] - b[k] * c[j]) - a[j] * (b[i] * c[k] - b[k] * c[i]) + a[k] * (b[i] * c[j] - b[j] * c[i]);
  };
  return Eigen::Vector4d(-minor(1, 2, 3), minor(0, 2, 3), -minor(0, 1, 3), minor(0, 1, 2));
}

// `Stars` is a Tetrahedral_complex_stars; `points` holds the R^4 points in its
// dense vertex order (converted once, on the calling thread). Every normal
// method starts from the cells' mean (the estimator accepts quadric_fit and
// area_weighted only).
template <typename Stars>
class Tetrahedral_neighborhood
{
public:
  static constexpr int ambient_dimension = 4;
  // Not on surfaces: a Delaunay hull's flat slivers, vertical once lifted to R^4,
  // can tilt the cells' mean so far that the tangent coordinates collapse and
  // every fit is ill-conditioned; the fit then starts again from the 1-ring's
  // best-fitting hyperplane.
  static constexpr bool restart_from_hyperplane = true;
  using Vertex = std::size_t;
  using Estimate = Hypersurface_estimate;

  Tetrahedral_neighborhood(const Stars& stars, const std::vector<Eigen::Vector4d>& points)
      : stars_(&stars)
      , points_(&points)
  {}

  const Eigen::Vector4d& point(Vertex v) const { return (*points_)[v]; }
  void start(Vertex v) { rings_.start(v, *stars_); }
  bool extend() { return rings_.extend(*stars_); }
  int rings() const { return rings_.rings(); }
  const std::vector<Vertex>& vertices() const { return rings_.vertices(); }
  std::size_t ring_end(int r) const { return rings_.ring_end(r); }
  bool center_on_border(Vertex v) const { return stars_->on_boundary[v] != 0; }

  bool grow_ball(double radius, const Eigen::Vector4d& center)
  {
    return rings_.grow_ball(*stars_, radius * radius, [&](Vertex w) { return (point(w) - center).squaredNorm(); });
  }
  bool inside_ball(std::size_t i) const { return rings_.inside_ball(i); }
  std::size_t ball_size() const { return rings_.ball_size(); }

  static bool gathers_for_normal(Vertex_normal_method) { return true; }

  // The sum over the incident cells (a, b, c, d) of cross_product_4(b - a, c - a, d - a),
  // in coordinates relative to the center scaled by `scale`: the 3-volume-weighted
  // mean of the cells' normals, first order.
  Eigen::Vector4d initial_normal(Vertex v, Vertex_normal_method, bool, const std::vector<Eigen::Vector4d>&,
                                 const std::vector<char>&, double scale) const
  {
    const Eigen::Vector4d& center = point(v);
    Eigen::Vector4d sum = Eigen::Vector4d::Zero();
    for (std::size_t k = stars_->cell_offsets[v]; k < stars_->cell_offsets[v + 1]; ++k) {
      const auto& cell = stars_->cells[stars_->incident_cells[k]];
      const Eigen::Vector4d a = (point(cell[0]) - center) / scale;
      const Eigen::Vector4d n =
        cross_product_4((point(cell[1]) - center) / scale - a, (point(cell[2]) - center) / scale - a,
                        (point(cell[3]) - center) / scale - a);
      if (n.allFinite())
        sum += n;
    }
    return sum;
  }

  static void set_estimate(Hypersurface_estimate& e, Estimation_status status, const Graph_curvature<4>& curvature,
                           double scale)
  {
    e.status = status;
    e.curvatures = curvature.curvatures / scale;
    e.directions = curvature.directions;
    e.normal = curvature.normal;
  }

private:
  const Stars* stars_;
  const std::vector<Eigen::Vector4d>* points_;
  Tetrahedral_ring_collector rings_;
};

// The fits of vertex_fitter.h at the vertices of a tetrahedral complex, whose points are `points`.
template <typename Stars>
class Hypersurface_fitter : public Vertex_fitter<Tetrahedral_neighborhood<Stars>>
{
public:
  Hypersurface_fitter(const Stars& stars, const std::vector<Eigen::Vector4d>& points, const Fit_settings& settings)
      : Vertex_fitter<Tetrahedral_neighborhood<Stars>>(Tetrahedral_neighborhood<Stars>(stars, points), settings)
  {}
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TETRAHEDRAL_NEIGHBORHOOD_H
