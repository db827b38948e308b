// Vertex normals of a surface mesh as weighted averages of face normals.
//
// The per-vertex kernel `internal::face_average_normal()` is a pure function of
// one vertex's star, allocation-free, meant to be called from the vertex loop of
// an estimator; `estimate_vertex_normals()` is the public function that fills a
// property map for every vertex of a `FaceGraph`.
#ifndef CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H
#define CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H

#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// How a normal is estimated at a vertex of a surface mesh.
///
/// The three face-averaging methods return the normalised weighted sum
/// \f$ \sum_f w_f\, n_f \f$ of the unit normals \f$ n_f \f$ of the faces incident to the
/// vertex; they differ by the weights \f$ w_f \f$. On a mesh inscribed in a smooth surface
/// their error is in general of first order in the edge length (second order only on
/// symmetric stars), which is why curvature estimators default to `quadric_fit`.
enum class Vertex_normal_method : unsigned char
{
  /// The normal of a local quadric fit (a second-order estimate, also at boundary
  /// vertices). The default of the curvature estimators that need normals.
  /// Not implemented yet by `estimate_vertex_normals()`, which throws
  /// `std::invalid_argument` when asked for it.
  quadric_fit,
  /// Weights are the face areas: the normalised sum of the (unnormalised) face normal
  /// vectors. The default of `estimate_vertex_normals()`.
  area_weighted,
  /// Weights are the interior angles of the faces at the vertex (Thürmer and Wüthrich 1998).
  /// At a reflex vertex of a non-convex polygonal face the angle is larger than \f$ \pi \f$.
  angle_weighted,
  /// Centroid weights \f$ w_f = 1/\|G_f - v\|^2 \f$, with \f$ G_f \f$ the centroid (mean of
  /// the vertices) of face \f$ f \f$ (Chen and Wu 2004; Chen, Wu and Chi 2005, eq. 23 and 25).
  centroid_weighted
};

namespace internal {

/// Computes at vertex `v` of `g` the unit weighted average of the unit normals of the
/// faces incident to `v`, with the weights of `method` (one of `area_weighted`,
/// `angle_weighted`, `centroid_weighted`), in `double`.
///
/// - Faces may be any polygons: a face normal is given by Newell's method over all the
///   vertices of the face (twice the vector area of the face), the angle at `v` by the two
///   edges of the face incident to `v` (measured around the face normal, so that a
///   reflex vertex of a non-convex face gets an angle larger than pi), the centroid
///   as the mean of the vertices of the face.
/// - Border halfedges (null faces) are skipped. A face of zero vector area
///   contributes nothing; for `angle_weighted`, neither does a face with a zero-length
///   edge at `v`. For `centroid_weighted`, a face whose centroid is `v` (possible only
///   for a non-convex polygon), or so close to it that the weight overflows, has an
///   infinite weight: the result is then the average of the unit normals of such faces
///   alone (the limit of the weighted average as their centroids tend to `v`).
/// - The coordinates are taken relative to `v` and divided by the largest
///   coordinate difference between `v` and its neighbours, so the result does not depend
///   on the scale of the mesh (no overflow or underflow for tiny or huge meshes).
///
/// \returns a unit vector; or the zero vector when `v` is isolated, has no incident face,
/// or when all its incident faces are degenerate or their weighted normals cancel;
/// or a vector of quiet NaNs when the point of `v`, of a neighbour of `v`, or of a
/// vertex of an incident face is not finite (or a difference of them overflows).
/// Callers test `n.allFinite() && n.squaredNorm() > 0`.
///
/// Pure and allocation-free: it may be called concurrently for different vertices
/// provided `get(vpm, ·)` may (see the note on `Polyhedron_3`'s dynamic maps in the design).
///
/// \pre `method != Vertex_normal_method::quadric_fit` (otherwise `std::invalid_argument`
/// is thrown: that method is not an average of face normals).
///
/// \tparam FaceGraph a model of `FaceGraph`
/// \tparam VPM a model of `ReadablePropertyMap` from the vertex descriptor to a point
///         type with `x()`, `y()`, `z()` convertible by `CGAL::to_double()`
template <typename FaceGraph, typename VPM>
Eigen::Vector3d face_average_normal(typename boost::graph_traits<FaceGraph>::vertex_descriptor v,
                                    const FaceGraph& g,
                                    const VPM& vpm,
                                    Vertex_normal_method method)
{
  using Graph_traits = boost::graph_traits<FaceGraph>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;

  if (method == Vertex_normal_method::quadric_fit)
    throw std::invalid_argument(
      "CGAL::Curvature_estimation::internal::face_average_normal(): quadric_fit is not an "
      "average of face normals; use area_weighted, angle_weighted or centroid_weighted");

  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  constexpr double two_pi = 6.283185307179586476925286766559;

  // Isolated vertex: no halfedge to circulate around.
  if (halfedge(v, g) == Graph_traits::null_halfedge())
    return zero;

  auto point = [&vpm](vertex_descriptor u) -> Eigen::Vector3d {
    const auto& p = get(vpm, u);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };

  const Eigen::Vector3d pv = point(v);
  if (!pv.allFinite())
    return nan;

  // Local length scale: the largest coordinate difference between v and a neighbour.
  double scale = 0.;
  for (halfedge_descriptor h : halfedges_around_target(v, g)) {
    const double d = (point(source(h, g)) - pv).template lpNorm<Eigen::Infinity>();
    if (!(d <= (std::numeric_limits<double>::max)())) // NaN or infinite
      return nan;
    if (d > scale)
      scale = d;
  }
  if (!(scale > 0.)) // all neighbours coincide with v: every face is degenerate
    return zero;

  // Position of u relative to v, in units of `scale` (division, not multiplication by
  // 1/scale, which overflows when scale is subnormal).
  auto local = [&](vertex_descriptor u) -> Eigen::Vector3d { return (point(u) - pv) / scale; };

  Eigen::Vector3d sum = zero;
  Eigen::Vector3d sum_infinite_weights = zero; // centroid_weighted only
  for (halfedge_descriptor h : halfedges_around_target(v, g)) {
    if (is_border(h, g))
      continue;

    // One walk around the face starting at h (whose target is v, at the local origin):
    // Newell's normal sum_i q_i x q_{i+1} (the terms with q_v = 0 vanish), the sum of
    // the vertices, and the two neighbours of v in this face.
    Eigen::Vector3d newell = zero;
    Eigen::Vector3d vertex_sum = zero;
    Eigen::Vector3d previous = zero;   // q of the target of the previous halfedge
    Eigen::Vector3d next_of_v = zero;  // q of the vertex after v in the face
    int n_vertices = 0;
    for (halfedge_descriptor k : halfedges_around_face(h, g)) {
      const Eigen::Vector3d q = (n_vertices == 0) ? zero : local(target(k, g));
      if (n_vertices == 1)
        next_of_v = q;
      newell += previous.cross(q);
      vertex_sum += q;
      previous = q;
      ++n_vertices;
    }
    const Eigen::Vector3d& previous_of_v = previous; // target of prev(h), i.e. source(h)

    if (!newell.allFinite() || !vertex_sum.allFinite())
      return nan;
    const double twice_area = newell.norm();
    if (!(twice_area > 0.)) // degenerate face: no normal, no weight
      continue;

    switch (method) {
      case Vertex_normal_method::area_weighted:
        // area * unit normal = newell / 2; the common factor does not matter
        sum += newell;
        break;

      case Vertex_normal_method::angle_weighted: {
        const Eigen::Vector3d nf = newell / twice_area;
        if (next_of_v == zero || previous_of_v == zero) // zero-length edge at v
          break;
        // Angle from the edge to the next vertex to the edge to the previous one,
        // counter-clockwise around nf: in [0, 2 pi), larger than pi at a reflex vertex.
        double angle = std::atan2(next_of_v.cross(previous_of_v).dot(nf), next_of_v.dot(previous_of_v));
        if (angle < 0.)
          angle += two_pi;
        sum += angle * nf;
        break;
      }

      case Vertex_normal_method::centroid_weighted: {
        const double d2 = (vertex_sum / double(n_vertices)).squaredNorm(); // |G_f - v|^2 / scale^2
        const double w = 1. / d2;
        if (std::isfinite(w))
          sum += (w / twice_area) * newell;
        else // centroid at v (possible for non-convex polygons): infinite weight
          sum_infinite_weights += newell / twice_area;
        break;
      }

      default: // quadric_fit was refused above
        break;
    }
  }

  // Faces of infinite weight (centroid at v) dominate all others: this is the limit
  // of the weighted average as a centroid tends to v.
  if (sum_infinite_weights != zero)
    sum = sum_infinite_weights;

  // Normalise without overflow: first by the largest component.
  const double largest = sum.cwiseAbs().maxCoeff();
  if (!std::isfinite(largest))
    return nan;
  if (!(largest > 0.))
    return zero;
  const Eigen::Vector3d s = sum / largest;
  return s / s.norm();
}

} // namespace internal

/**
 * \ingroup PkgCurvatureEstimationRef
 *
 * estimates a unit normal at every vertex of `g` as a weighted average of the normals of
 * its incident faces, and writes it into `normals`.
 *
 * Faces may be any (simple) polygons. Face normals are oriented by the orientation of the
 * faces, so a closed, consistently oriented mesh gets outward normals when its faces are
 * oriented counter-clockwise seen from outside. The computation is done in `double`
 * (see `internal::face_average_normal()`), independently of the scale of the mesh.
 *
 * A vertex gets no normal when it is isolated, when all its incident faces are degenerate
 * (zero area) or their weighted normals cancel, or when a point of its star is not finite.
 * Its normal is then a vector of three quiet NaNs (the null vector if `FT` has no NaN, as
 * for exact number types), and its status `Estimation_status::not_estimable`.
 * An empty mesh is not an error: nothing is written.
 *
 * @tparam FaceGraph a model of `FaceListGraph` (faces may be any polygons)
 * @tparam VertexNormalMap a model of `WritablePropertyMap` with
 *         `boost::graph_traits<FaceGraph>::%vertex_descriptor` as key type and
 *         `GT::Vector_3` as value type, where `GT` is the type of the geometric traits
 * @tparam NamedParameters a sequence of named parameters, built with the functions of
 *         `CGAL::Curvature_estimation::parameters`
 *
 * @param g the surface mesh
 * @param normals the property map in which the unit normals are written
 * @param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `g`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
 *                    as key type and `GT::Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, g)`}
 *     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
 *                     must be available in `FaceGraph`.}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class, which gives `FT` and `Vector_3`
 *                           and constructs the vectors written}
 *     \cgalParamType{a class model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
 *     \cgalParamExtra{The geometric traits class must be compatible with the vertex point type.}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{vertex_normal_method}
 *     \cgalParamDescription{the weights of the face normals:
 *                           `Vertex_normal_method::area_weighted` (face areas),
 *                           `Vertex_normal_method::angle_weighted` (interior angles at the vertex) or
 *                           `Vertex_normal_method::centroid_weighted` (inverse squared distances from the
 *                           vertex to the face centroids, Chen, Wu and Chi 2005).
 *                           `Vertex_normal_method::quadric_fit` is not available yet: asking for it
 *                           throws `std::invalid_argument`.}
 *     \cgalParamType{`CGAL::Curvature_estimation::Vertex_normal_method`}
 *     \cgalParamDefault{`Vertex_normal_method::area_weighted`}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{vertex_estimation_status_map}
 *     \cgalParamDescription{an optional output property map receiving for each vertex
 *                           `Estimation_status::ok` when a normal was estimated and
 *                           `Estimation_status::not_estimable` when not (its normal is then NaN)}
 *     \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
 *                    as key type and `CGAL::Curvature_estimation::Estimation_status` as value type}
 *     \cgalParamDefault{none: no status is written}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws std::invalid_argument if `vertex_normal_method` is `Vertex_normal_method::quadric_fit`.
 */
template <typename FaceGraph,
          typename VertexNormalMap,
          typename NamedParameters = parameters::Default_named_parameters>
void estimate_vertex_normals(const FaceGraph& g,
                             VertexNormalMap normals,
                             const NamedParameters& np = parameters::default_values())
{
  using ::CGAL::parameters::choose_parameter;
  using ::CGAL::parameters::get_parameter;

  using GT = typename CGAL::GetGeomTraits<FaceGraph, NamedParameters>::type;
  using VPM = typename CGAL::GetVertexPointMap<FaceGraph, NamedParameters>::const_type;
  using FT = typename GT::FT;
  using Vector_3 = typename GT::Vector_3;
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  const GT traits = choose_parameter<GT>(get_parameter(np, ::CGAL::internal_np::geom_traits));
  const VPM vpm = choose_parameter(get_parameter(np, ::CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, g));
  const Vertex_normal_method method =
    choose_parameter(get_parameter(np, internal_np::vertex_normal_method),
                     Vertex_normal_method::area_weighted);

  constexpr bool write_status =
    !::CGAL::parameters::is_default_parameter<NamedParameters,
                                              internal_np::vertex_estimation_status_map_t>::value;

  if (method == Vertex_normal_method::quadric_fit)
  {
    // ======================= BEGIN quadric_fit branch =======================
    // Second-order normals from a local quadric fit (with linear terms), also at
    // boundary vertices. To be implemented; until then this method is refused.
    throw std::invalid_argument(
      "CGAL::Curvature_estimation::estimate_vertex_normals(): "
      "Vertex_normal_method::quadric_fit is not implemented yet; "
      "use area_weighted, angle_weighted or centroid_weighted");
    // ======================== END quadric_fit branch ========================
  }

  const auto construct_vector = traits.construct_vector_3_object();
  const FT no_value = std::numeric_limits<FT>::has_quiet_NaN ? std::numeric_limits<FT>::quiet_NaN()
                                                             : FT(0);
  const Vector_3 no_normal = construct_vector(no_value, no_value, no_value);

  for (vertex_descriptor v : vertices(g)) {
    const Eigen::Vector3d n = internal::face_average_normal(v, g, vpm, method);
    const bool estimated = n.allFinite() && n.squaredNorm() > 0.;
    put(normals, v, estimated ? construct_vector(FT(n.x()), FT(n.y()), FT(n.z())) : no_normal);
    if constexpr (write_status) {
      put(get_parameter(np, internal_np::vertex_estimation_status_map), v,
          estimated ? Estimation_status::ok : Estimation_status::not_estimable);
    }
  }
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H
