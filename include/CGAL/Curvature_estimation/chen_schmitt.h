// SPDX-License-Identifier: GPL-3.0-or-later
// Chen and Schmitt's least-squares fit of Euler's formula, on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H
#define CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>
#include <CGAL/Curvature_estimation/internal/euler_fit.h>
#include <CGAL/Curvature_estimation/internal/normal_curvature_samples.h>

#include <CGAL/tags.h>

#include <vector>

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
///
/// Estimates principal curvatures and directions, mean and Gaussian curvature at
/// every vertex of a surface mesh by Chen and Schmitt's method (Chen and Schmitt
/// 1992, as reviewed by Chen, Wu and Chi 2005, section 3.1): the normal curvatures
/// `k_i = 2 <p - q_i, N> / |q_i - p|^2` along the unit
/// tangents `t_i = (costheta_i, sintheta_i)` towards the neighbors
/// `q_i` joined to the vertex p by an edge (as in `taubin_curvatures()`) are
/// fitted by unweighted least squares with Euler's formula
/// `k(theta) = C_1 cos^2theta + C_2 costheta sintheta + C_3 sin^2theta`;
/// the principal curvatures and directions are the eigenvalues and eigenvectors
/// of `[[C_1, C_2/2], [C_2/2, C_3]]` (eqs. 12-13). The angles are measured
/// in a tangent frame of the normal; the fit does not depend on which (the paper
/// measures them from the first edge).
///
/// A baseline: not consistent on irregular meshes. Normals come from
/// `vertex_normal_map` when given, else from `vertex_normal_method` (default
/// `Vertex_normal_method::quadric_fit`, the package's second-order normal).
///
/// **Conventions.** A sphere with outward normals has `max_curvature == min_curvature == 1/r`;
/// `max_curvature >= min_curvature`; directions are unit, tangent and orthogonal;
/// K is `max_curvature * min_curvature`. A vertex with no normal, or with fewer
/// than three neighbor directions distinct modulo pi (for instance a corner of a
/// grid), gets NaN in every output and the status `Estimation_status::not_estimable`.
///
/// Only the outputs whose maps are passed are written; passing none does nothing.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`. Sequential and parallel runs give
///         identical results. In parallel the vertex point map is read from several
///         threads; the property maps of `Surface_mesh` (and `Point_set_3`) are read and
///         written by the worker threads, every other map by the calling thread only.
/// \tparam FaceGraph a model of `FaceGraph` (faces may be any polygons).
/// \tparam NamedParameters a sequence of named parameters, built with the functions of `CGAL::Curvature_estimation::parameters`
///
/// \param g the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `g`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, g)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_map}
///     \cgalParamDescription{normals at the vertices, trusted as given (they need not be unit)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
///                    as key type and `GT::Vector_3` as value type}
///     \cgalParamDefault{normals estimated by `vertex_normal_method`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_method}
///     \cgalParamDescription{how normals are estimated when no `vertex_normal_map` is given (see `estimate_vertex_normals()`)}
///     \cgalParamType{`CGAL::Curvature_estimation::Vertex_normal_method`}
///     \cgalParamDefault{`Vertex_normal_method::quadric_fit`}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{`quadric_fit` normals only: rings an interior vertex's fit starts with}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_neighborhood_rings}
///     \cgalParamDescription{`quadric_fit` normals only: rings a boundary vertex's fit starts with}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{the value of `neighborhood_rings`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_neighborhood_rings}
///     \cgalParamDescription{`quadric_fit` normals only: the widest neighborhood an ill-conditioned fit is widened to}
///     \cgalParamType{`int`, at least the two values above}
///     \cgalParamDefault{`3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_condition_number}
///     \cgalParamDescription{`quadric_fit` normals only: fits whose normal equations have a larger condition
///                           number are widened (see `paraboloid_fitting_curvatures()`)}
///     \cgalParamType{`double`, greater than 1}
///     \cgalParamDefault{`1e3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_principal_curvatures_and_directions_map}
///     \cgalParamDescription{output: principal curvatures and directions}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
///                    as key type and `Principal_curvatures_and_directions<GT>` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_mean_curvature_map}
///     \cgalParamDescription{output: mean curvature H = (k1 + k2) / 2}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
///                    as key type and `GT::FT` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_Gaussian_curvature_map}
///     \cgalParamDescription{output: Gaussian curvature K = k1 k2}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
///                    as key type and `GT::FT` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_estimation_status_map}
///     \cgalParamDescription{output: the outcome at each vertex (`ok` or `not_estimable`)}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
///                    as key type and `CGAL::Curvature_estimation::Estimation_status` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, or if `ball_radius`
///         is given (neighborhoods are set in rings).
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void chen_schmitt_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  internal::normal_curvature_sample_curvatures<ConcurrencyTag>(
    g, np, "chen_schmitt_curvatures",
    [](const std::vector<internal::Normal_curvature_sample>& samples, Eigen::Matrix2d& shape) {
      // Unweighted, as Chen and Schmitt; the paper measures the angles from the
      // first edge, and the fit does not depend on that choice of frame. The
      // threshold only refuses directions that are (nearly) not three distinct ones.
      internal::Euler_fit fit;
      for (const internal::Normal_curvature_sample& sample : samples)
        fit.add(sample.direction, sample.curvature);
      return fit.solve(1e5, shape);
    });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H
