// Hamann's platelet fit (thesis §4.3) at one vertex of a tetrahedral complex whose
// vertices are points of R^4: gather the k-ring, express it in a tangent frame
// of R^4, fit the trivariate paraboloid, widen while ill-conditioned; and the
// second-order normal that the fit uses by default.
//
// This is, line for line, the tetrahedral twin of Platelet_fitter in
// platelet_fit.h (same settings, same constants, same Taylor_fit /
// graph_curvature / tangent_basis core with D = 3 instead of 2):
//   Platelet_fitter::gather          <-> Tetrahedral_platelet_fitter::gather
//   Platelet_fitter::reach           <-> reach
//   Platelet_fitter::fit_widening    <-> fit_widening
//   Platelet_fitter::fit_normal      <-> fit_normal (cubic at boundary, >= 3 rings,
//                                        Gaussian weights, threshold x1e3, fallback to degree 2)
//   Platelet_fitter::fit_in_frame    <-> fit_in_frame
//   Platelet_fitter::fit_curvature   <-> fit_curvature
//   corner_normal_sum (face normals) <-> cell_normal_sum (4D cross products of the cells)
//   Ring_collector<FaceGraph>        <-> Tetrahedral_ring_collector (CSR neighbours)
// Only the neighbourhood source, the ambient dimension N (3 or 4) and the
// initial (first-order) normal differ.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TETRAHEDRAL_PLATELET_FIT_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TETRAHEDRAL_PLATELET_FIT_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Tetrahedral_complex_traits.h>
#include <CGAL/Curvature_estimation/internal/platelet_fit.h>
#include <CGAL/Curvature_estimation/internal/quadric_fit.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
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
  Eigen::Vector3d curvatures = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());  // decreasing
  Eigen::Matrix<double, 4, 3> directions =
    Eigen::Matrix<double, 4, 3>::Constant(std::numeric_limits<double>::quiet_NaN());  // column i for curvature i
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

// k-rings over the neighbours of Tetrahedral_complex_stars, one ring at a time.
// A stamp per vertex (allocated on first use, so that copying an unused
// collector is cheap) replaces the surface collector's linear search, since
// tetrahedral rings hold hundreds of vertices.
class Tetrahedral_ring_collector
{
public:
  template <typename Stars>
  void start(std::size_t center, const Stars& stars)
  {
    if (stamps_.size() != stars.size()) {
      stamps_.assign(stars.size(), 0);
      stamp_ = 0;
    }
    if (++stamp_ == 0) {
      std::fill(stamps_.begin(), stamps_.end(), 0);
      stamp_ = 1;
    }
    vertices_.clear();
    ring_ends_.clear();
    vertices_.push_back(center);
    stamps_[center] = stamp_;
    ring_ends_.push_back(1);
    add_neighbors(center, stars);
    ring_ends_.push_back(vertices_.size());
  }

  // Adds the next ring; returns false when it is empty (the component is exhausted).
  template <typename Stars>
  bool extend(const Stars& stars)
  {
    const std::size_t first = ring_ends_[ring_ends_.size() - 2];
    const std::size_t last = ring_ends_.back();
    for (std::size_t i = first; i < last; ++i)
      add_neighbors(vertices_[i], stars);
    ring_ends_.push_back(vertices_.size());
    return ring_ends_.back() > last;
  }

  int rings() const { return static_cast<int>(ring_ends_.size()) - 1; }
  const std::vector<std::size_t>& vertices() const { return vertices_; }
  std::size_t ring_end(int r) const { return ring_ends_[r]; }

private:
  template <typename Stars>
  void add_neighbors(std::size_t v, const Stars& stars)
  {
    for (std::size_t k = stars.neighbor_offsets[v]; k < stars.neighbor_offsets[v + 1]; ++k) {
      const std::size_t w = stars.neighbors[k];
      if (stamps_[w] != stamp_) {
        stamps_[w] = stamp_;
        vertices_.push_back(w);
      }
    }
  }

  std::vector<unsigned> stamps_;
  unsigned stamp_ = 0;
  std::vector<std::size_t> vertices_;
  std::vector<std::size_t> ring_ends_;
};

// `Stars` is a Tetrahedral_complex_stars; `points` holds the R^4 points in its
// dense vertex order (converted once, on the calling thread).
template <typename Stars>
class Tetrahedral_platelet_fitter
{
public:
  using Vector4 = Eigen::Vector4d;
  using Tangents = Eigen::Matrix<double, 4, 3>;

  Tetrahedral_platelet_fitter(const Stars& stars, const std::vector<Vector4>& points,
                              const Platelet_fit_settings& settings)
    : stars_(&stars), points_(&points), settings_(settings)
  {}

  // Hamann's fit in the frame of the given `normal` (any length).
  Hypersurface_estimate fit(std::size_t v, const Vector4& normal)
  {
    const double length = normal.norm();
    if (!(length > 0) || !std::isfinite(length) || !gather(v))
      return Hypersurface_estimate();
    return fit_curvature(normal / length);
  }

  // The same with the normal estimated by `method` (quadric_fit or area_weighted,
  // the latter meaning the 3-volume-weighted mean of the cells' normals).
  Hypersurface_estimate fit(std::size_t v, Vertex_normal_method method)
  {
    Vector4 normal;
    if (!gather(v) || !estimate_normal(v, method, normal))
      return Hypersurface_estimate();
    return fit_curvature(normal);
  }

  // The unit normal by `method`; false where there is none.
  bool normal(std::size_t v, Vertex_normal_method method, Vector4& normal)
  {
    return gather(v) && estimate_normal(v, method, normal);
  }

private:
  bool gather(std::size_t v)
  {
    center_ = (*points_)[v];
    if (!center_.allFinite())
      return false;
    rings_.start(v, *stars_);
    offsets_.clear();
    offsets_.push_back(Vector4::Zero());
    double length_sum = 0;
    int length_count = 0;
    for (std::size_t i = 1; i < rings_.ring_end(1); ++i) {
      const Vector4 offset = (*points_)[rings_.vertices()[i]] - center_;
      offsets_.push_back(offset);
      double length = offset.norm();
      if (!(length > 1e-150 && length < 1e150))
        length = offset.stableNorm();
      if (std::isfinite(length)) {
        length_sum += length;
        ++length_count;
      }
    }
    if (length_count == 0 || !(length_sum > 0))
      return false;
    scale_ = length_sum / length_count;
    for (Vector4& offset : offsets_)
      offset /= scale_;
    on_border_ = stars_->on_boundary[v] != 0;
    return true;
  }

  int start_rings() const { return on_border_ ? settings_.boundary_rings : settings_.rings; }

  bool reach(int rings)
  {
    while (rings_.rings() < rings) {
      if (!rings_.extend(*stars_))
        return false;
      for (std::size_t i = offsets_.size(); i < rings_.vertices().size(); ++i)
        offsets_.push_back(((*points_)[rings_.vertices()[i]] - center_) / scale_);
    }
    return true;
  }

  template <typename Fit>
  int fit_widening(const Vector4& normal, const Tangents& tangents, int rings, int max_rings, double max_condition,
                   Fit& fit)
  {
    for (; rings <= max_rings && reach(rings); ++rings)
      if (fit_in_frame(normal, tangents, rings, max_condition, fit))
        return rings;
    return 0;
  }

  bool estimate_normal(std::size_t v, Vertex_normal_method method, Vector4& normal)
  {
    const bool fitted = method == Vertex_normal_method::quadric_fit;
    normal = cell_normal_sum(v);
    if (!normal.allFinite() || !(normal.squaredNorm() > 0))
      return false;
    normal.normalize();
    if (!fitted)
      return true;
    const Vector4 first = normal;
    if (fit_normal(normal))
      return true;
    // Not on surfaces: a Delaunay hull's flat slivers, vertical once lifted to R^4,
    // can tilt the cells' mean so far that the tangent coordinates collapse and
    // every fit is ill-conditioned. Start again from the normal of the best-fitting
    // hyperplane through the 1-ring (oriented as the cells' mean).
    normal = hyperplane_normal();
    if (normal.dot(first) < 0)
      normal = -normal;
    return normal.allFinite() && fit_normal(normal);
  }

  // The least-squares hyperplane's normal through the center and its 1-ring: the
  // eigenvector of the smallest eigenvalue of their scatter matrix.
  Vector4 hyperplane_normal() const
  {
    const std::size_t count = rings_.ring_end(1);
    Vector4 mean = Vector4::Zero();
    for (std::size_t i = 0; i < count; ++i)
      mean += offsets_[i];
    mean /= double(count);
    Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
    for (std::size_t i = 0; i < count; ++i)
      scatter.noalias() += (offsets_[i] - mean) * (offsets_[i] - mean).transpose();
    // Cyclic Jacobi rotations (Eigen's iterative 4x4 solver warns under GCC 12's -Wmaybe-uninitialized).
    Eigen::Matrix4d vectors = Eigen::Matrix4d::Identity();
    for (int sweep = 0; sweep < 50; ++sweep) {
      double off = 0;
      for (int p = 0; p < 4; ++p)
        for (int q = p + 1; q < 4; ++q)
          off += scatter(p, q) * scatter(p, q);
      if (!(off > 1e-30 * scatter.squaredNorm()))
        break;
      for (int p = 0; p < 4; ++p)
        for (int q = p + 1; q < 4; ++q) {
          if (scatter(p, q) == 0)
            continue;
          const double theta = 0.5 * (scatter(q, q) - scatter(p, p)) / scatter(p, q);
          const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
          const double c = 1 / std::sqrt(t * t + 1), s = t * c;
          for (int k = 0; k < 4; ++k) {  // scatter <- J^T scatter J, vectors <- vectors J
            const double a = scatter(k, p), b = scatter(k, q);
            scatter(k, p) = c * a - s * b;
            scatter(k, q) = s * a + c * b;
          }
          for (int k = 0; k < 4; ++k) {
            const double a = scatter(p, k), b = scatter(q, k);
            scatter(p, k) = c * a - s * b;
            scatter(q, k) = s * a + c * b;
          }
          for (int k = 0; k < 4; ++k) {
            const double a = vectors(k, p), b = vectors(k, q);
            vectors(k, p) = c * a - s * b;
            vectors(k, q) = s * a + c * b;
          }
        }
    }
    int smallest = 0;
    scatter.diagonal().minCoeff(&smallest);
    return vectors.col(smallest);
  }

  // The sum over the incident cells (a, b, c, d) of cross_product_4(b - a, c - a, d - a)
  // (scaled): the 3-volume-weighted mean of the cells' normals, first order.
  Vector4 cell_normal_sum(std::size_t v) const
  {
    Vector4 sum = Vector4::Zero();
    for (std::size_t k = stars_->cell_offsets[v]; k < stars_->cell_offsets[v + 1]; ++k) {
      const auto& cell = stars_->cells[stars_->incident_cells[k]];
      const Vector4 a = ((*points_)[cell[0]] - center_) / scale_;
      const Vector4 n = cross_product_4(((*points_)[cell[1]] - center_) / scale_ - a,
                                        ((*points_)[cell[2]] - center_) / scale_ - a,
                                        ((*points_)[cell[3]] - center_) / scale_ - a);
      if (n.allFinite())
        sum += n;
    }
    return sum;
  }

  bool fit_normal(Vector4& normal)
  {
    const Tangents tangents = tangent_basis<4>(normal);
    if (on_border_) {
      const int rings = (std::max)(cubic_normal_min_rings, start_rings());
      Taylor_fit<3, 1, 3> cubic;
      if (fit_widening(normal, tangents, rings, (std::max)(rings, settings_.max_rings),
                       cubic_normal_condition_factor * settings_.max_condition, cubic) != 0)
        return correct_normal(normal, tangents, cubic.gradient());
    }
    Taylor_fit<3, 1, 2> quadratic;
    return fit_widening(normal, tangents, start_rings(), settings_.max_rings, settings_.max_condition, quadratic) != 0 &&
           correct_normal(normal, tangents, quadratic.gradient());
  }

  static bool correct_normal(Vector4& normal, const Tangents& tangents, const Eigen::Vector3d& gradient)
  {
    normal = (normal - tangents * gradient).normalized();
    return normal.allFinite();
  }

  Hypersurface_estimate fit_curvature(const Vector4& normal)
  {
    Hypersurface_estimate result;
    const Tangents tangents = tangent_basis<4>(normal);
    Taylor_fit<3, 2, 2> fit;
    const int rings = fit_widening(normal, tangents, start_rings(), settings_.max_rings, settings_.max_condition, fit);
    if (rings == 0)
      return result;
    const Graph_curvature<4> curvature = graph_curvature<4>(fit.hessian(), fit.gradient(), tangents, normal);
    if (!curvature.curvatures.allFinite() || !curvature.directions.allFinite())
      return result;
    result.status = rings > 1 ? Estimation_status::widened : Estimation_status::ok;
    result.curvatures = curvature.curvatures / scale_;
    result.directions = curvature.directions;
    result.normal = normal;
    return result;
  }

  // Gaussian weights in the cubic fit only, as on surfaces; Hamann's fit is unweighted.
  template <typename Fit>
  bool fit_in_frame(const Vector4& normal, const Tangents& tangents, int rings, double max_condition, Fit& fit) const
  {
    constexpr bool weighted = Fit::unknowns > Taylor_fit<3, 1, 2>::unknowns;
    fit.clear();
    for (std::size_t i = 1; i < rings_.ring_end(rings); ++i) {
      const Vector4& q = offsets_[i];
      if (q.allFinite())
        fit.add(tangents.transpose() * q, normal.dot(q), weighted ? std::exp(-q.squaredNorm()) : 1.0);
    }
    return fit.solve(max_condition);
  }

  const Stars* stars_;
  const std::vector<Vector4>* points_;
  Platelet_fit_settings settings_;
  Tetrahedral_ring_collector rings_;
  std::vector<Vector4> offsets_;  // scaled p_w - p_v, aligned with rings_.vertices()
  Vector4 center_ = Vector4::Zero();
  double scale_ = 1;
  bool on_border_ = false;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TETRAHEDRAL_PLATELET_FIT_H
