// SPDX-License-Identifier: GPL-3.0-or-later
// Hamann's paraboloid fitting over the vertex platelet, on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_PARABOLOID_FITTING_H
#define CGAL_CURVATURE_ESTIMATION_PARABOLOID_FITTING_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_graph_platelet.h>
#include <CGAL/Curvature_estimation/internal/gauss_map_differential.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <stdexcept>
#include <type_traits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Hamann's fit at one vertex, with the given normal or one estimated by `method`.
// With the quadric_fit normal, where no ring determines the fit (nearly always
// because the normal's fit is not determined: samples near a conic through the
// vertex, as on the creases of CAD meshes triangulated by long thin fans), status
// fallback: jet fitting's fit (Platelet_fit_core::fit_in_plane_frame), which does
// not pass through the vertex, and where that is not determined either, the Gauss
// map's least-squares estimate
// (gauss_map_curvatures() with the same settings): it differentiates normals,
// first-order data, which such stencils determine where the heights'
// second-order terms are not. Not where the neighborhood, on every ring reached,
// has fewer neighbors than Hamann's fit has unknowns (a lone triangle): no
// paraboloid is determined even through them, which tells nothing of the
// curvature, and the vertex stays not_estimable. The Gauss map's normals are
// computed on demand: the fallback is rare (0.3% of the vertices of CGAL's data
// meshes), and a table of all normals would cost a second fit per vertex
// everywhere; for the same reason its fitter circulates the halfedges rather
// than build a second Vertex_adjacency.
//
// Jet fitting's fit also replaces, where it is determined, Hamann's fit at a
// boundary vertex that only test (b) accepts (for the normal or the fit), with
// status fallback: Hamann's fit has no linear terms, so the tilt of a normal that
// a one-sided, anisotropic stencil leaves uncertain goes into its curvatures (an
// interior stencil cancels it to first order), while jet fitting's linear terms
// take it. Over CGAL's data meshes, at the 85 such vertices with a reference
// (jet fitting of degree 4 on 3 rings), the median distance to it is 0.29
// instead of 1.31 (66 vertices closer, 19 further) and the largest 92 instead of
// 1,540. Against exact curvatures, at the boundary vertices of grids of 10:3
// and 5:1 triangles over Hamann's test functions, the median H error is 1.1 to
// 2.2 times smaller (test_paraboloid_fitting; at 10:1, on 6 of the 8 curved
// functions). At interior vertices that only test (b) accepts, Hamann's fit
// stays: it is the closer one there (with jet fitting's fit at those vertices
// too, the median distance to the reference would be 2.4 to 3.8 times larger on
// camel.off, dino.off and lion.off).
template <typename FaceGraph, typename VertexPointMap>
class Paraboloid_estimator
{
public:
  Paraboloid_estimator(const FaceGraph& g, VertexPointMap vpm, const Fit_parameters& fit)
      : fitter_(g, vpm, fit.settings)
      , method_(fit.normal_method)
      , gauss_map_(
          g, vpm,
          Vertex_normal_estimator<FaceGraph, VertexPointMap>{
            Platelet_fitter<FaceGraph, VertexPointMap>(g, vpm, fit.settings, nullptr), fit.normal_method, true})
  {}

  Surface_estimate estimate(typename boost::graph_traits<FaceGraph>::vertex_descriptor v, const Eigen::Vector3d* given)
  {
    if (given != nullptr)
      return fitter_.fit(v, *given);
    const Surface_estimate result = fitter_.fit(v, method_);
    if (method_ != Vertex_normal_method::quadric_fit)
      return result;
    const bool refused = result.status == Estimation_status::not_estimable;
    if (refused ? fitter_.neighbors() < std::size_t(Taylor_fit<2, 2, 2>::unknowns) : !fitter_.whitened_at_border())
      return result;
    const Surface_estimate in_plane_frame = fitter_.fit_in_plane_frame(v);
    if (in_plane_frame.status != Estimation_status::not_estimable)
      return in_plane_frame;
    return refused ? as_fallback(gauss_map_.estimate(v, nullptr)) : result;
  }

private:
  Platelet_fitter<FaceGraph, VertexPointMap> fitter_;
  Vertex_normal_method method_;
  Gauss_map_estimator<FaceGraph, VertexPointMap, Vertex_normal_estimator<FaceGraph, VertexPointMap>> gauss_map_;
};

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// Estimates principal curvatures and directions, mean and Gaussian curvature at
/// every vertex of a surface mesh by Hamann's method (Hamann 1993): the vertex's
/// platelet (its 1-ring) is expressed in the tangent frame of the vertex normal,
/// the osculating paraboloid d = 1/2 (c20 u^2 + 2 c11 uv + c02 v^2) is fitted to
/// it by least squares, and the curvatures are those of the paraboloid at the
/// vertex.
///
/// **Normals.** With a `vertex_normal_map` the given normals are trusted, as in
/// the paper. Without one, the default `Vertex_normal_method::quadric_fit` fits
/// the paraboloid with linear terms in the frame of the area-weighted normal,
/// corrects the normal by the fitted gradient and fits again in the corrected
/// frame: the normal is then second order also at boundary vertices, where a
/// face average tilts by O(h) and, divided by the one-sided platelet's size,
/// gives an O(1) curvature error. With that normal, at an interior vertex, the
/// curvature fit keeps the linear terms, h(u, v) = g . (u, v) + 1/2 (u, v) C (u, v)^T,
/// and the curvatures are those of that graph at the vertex: the normal's remaining
/// error is absorbed by g instead of leaking into C through an uneven 1-ring. On
/// marching-tetrahedra meshes (80 cells per axis, test
/// `MarchingTetrahedraConvergence`) this lowered the largest H error of Hamann's fit
/// in the same normal's frame 4 to 6 times, and on Delaunay meshes of random points
/// 3 to 9 times. That fit is then solved again with the heights less the
/// quartic term that its own curvatures imply, (x^T C x) |C x|^2 / 8 for the Hessian C
/// (the whole quartic part of a sphere's or a cylinder's height, which a degree-2 fit
/// otherwise takes into C as an O(h^2) error): on spheres and cylinders the error is
/// then O(h^4) (H errors below 1e-8 on the Delaunay test meshes, where jet fitting's
/// are 1e-5 to 1e-4), and elsewhere the leading error is unchanged. Where that fit is
/// ill-conditioned on the starting rings, it is widened with cubic terms too
/// (Gaussian weights of width the mean 1-ring edge), since a paraboloid over a wider
/// neighborhood has an error growing as the square of its radius; this happens at
/// the vertices of marching-cubes meshes whose nearly coincident neighbors leave a
/// 1-ring of three directions. On the marching-tetrahedra and Delaunay test meshes the
/// H error is then below jet fitting's at every level, in RMS and maximum (tests
/// `MarchingTetrahedraConvergence`, `DelaunayAgainstJetFitting`).
/// Where the linear terms are not determined on any ring,
/// and at boundary vertices (whose cubic normal is accurate enough that Hamann's
/// fit does better there), the paraboloid is fitted without them.
/// `area_weighted`, `angle_weighted` and `centroid_weighted` use the face average as
/// is, in Hamann's fit (the paper's method with approximated normals).
///
/// **Fallback.** With the `quadric_fit` normal and no `vertex_normal_map`, a vertex
/// where no ring up to `max_neighborhood_rings` determines the fit gets, with the
/// status `fallback`, the estimate of jet fitting's fit of degree 2 (as
/// `jet_fitting_curvatures()` fits it: a quadratic polynomial with constant and
/// linear terms over the vertex and its rings, in the frame of their least-squares
/// plane), from the starting rings, widened until its condition number is at most
/// 1000 times `max_condition_number`; where no ring gives that either, the estimate of
/// `gauss_map_curvatures()` with the same parameters.
/// This happens where the samples lie near a conic through the vertex, so that the
/// normal's quadratic fit (five unknowns) is not determined: the two rows of a single
/// band of triangles, or the creases of CAD meshes triangulated by fans of long thin
/// triangles, whose near and far ends are two clusters. A fit that does not pass
/// through the vertex is determined there more often; the Gauss map differentiates
/// the vertex normals, first-order data that such stencils do determine. Over CGAL's
/// data meshes, at the 743 vertices where Hamann's fit is not determined, the median
/// distance to jet fitting of degree 4 on 3 rings is 1.88 for the jet fit, 2.89 for
/// the Gauss map. At a boundary vertex where only the whitened test (see
/// `max_condition_number`) accepts Hamann's fit or its normal's, the estimate is that
/// of jet fitting's fit too, status `fallback`, where it is determined: Hamann's fit
/// has no linear terms, so the tilt of a normal that a one-sided, anisotropic stencil
/// leaves uncertain goes into its curvatures, while jet fitting's linear terms take it
/// (over the 85 such vertices of CGAL's data meshes, median distance 0.29 instead of
/// 1.31; at interior vertices, where the stencil cancels that tilt to first order,
/// Hamann's fit is the closer one and stays). A vertex
/// with fewer than three neighbors on all those rings together (a lone triangle) is
/// not estimable: not even Hamann's three coefficients are determined. Over the
/// surface meshes of CGAL's data (414,841 vertices) the fit alone refuses 2,709;
/// with the fallback, see `test_cgal_data_meshes` for the counts and for how close
/// the fallback's values are to jet fitting's.
/// `area_weighted`, `angle_weighted` and `centroid_weighted` use the face average as
/// is, in Hamann's fit (the paper's method with approximated normals).
///
/// **Higher degrees.** With `fit_degree(3)` or `fit_degree(4)` the fit is a Taylor
/// polynomial of that degree with linear terms, h(u, v) = g . (u, v) + 1/2 (u, v) C (u, v)^T
/// + cubic [+ quartic] terms, over 2 or 3 rings (or `neighborhood_rings` if more), in the
/// frame of the given normal or else of the area-weighted normal; for degree 4 without a
/// given normal, first of the least-squares plane of the vertex and its 3 rings, as CGAL's
/// jet fitting does (over 3 lopsided, curved rings a frame that leaves the far samples
/// steep spoils a quartic graph, even the exact normal's), where the fit is
/// well-conditioned in it. The fitted gradient corrects the frame's normal to the fit's
/// order, and the curvatures are those of the fitted graph at the vertex. On irregular meshes (Delaunay meshes of
/// random points, marching-tetrahedra meshes, jittered tori) these converge at orders about 2 and 3 where degree 2 is
/// of first order, at about 2 and 4 times the cost (see the benchmark report); degree 4 is about as accurate as CGAL's
/// jet fitting of degree 4 on 3 rings. Widening, test (b) and the fallback are as for degree 2, with condition
/// thresholds of 100 and 1e5 times `max_condition_number`, up to `max_neighborhood_rings` rings or one ring more than
/// the degree's. The degree-3 fit is solved again less the curvature's quartic term, as above. The normal these fits
/// read their curvatures in (the frame's normal corrected by the fitted gradient, of order 3 and 4) is what
/// `estimate_vertex_normals()` writes with the same `fit_degree`. These fits, and those over a ball or over more than
/// one starting ring, read the rings from a table of every vertex's neighbors, built once
/// per call where vertex descriptors are indices (`Surface_mesh`): 4 bytes per vertex and
/// 4 per halfedge of temporary memory (28 bytes per vertex of valence 6).
///
/// **Curvature at a scale.** With `ball_radius(r)` the neighborhood is not a number
/// of rings but the part of the mesh inside the ball of radius r about the vertex
/// that is joined to it by edges inside the ball (so that the other side of a thin
/// part is not taken), for meshes whose noise a 1-ring would measure instead of the
/// surface (scans, reconstructions). `r = k * mean_edge_length(g)` is "a radius of k
/// edges". The fit is the Taylor polynomial of `fit_degree` with a constant term and
/// linear terms, h(u, v) = c + g . (u, v) + 1/2 (u, v) C (u, v)^T [+ cubic [+ quartic]
/// terms], unweighted, in the frame of the area-weighted normal (or of the given one);
/// the curvatures are those of the fitted graph at the vertex (its gradient takes the
/// frame's tilt: a second fit in the frame of the corrected normal changed the errors by
/// at most 4%). With the constant term the
/// vertex is a sample like the others, not a point the fit passes through: its own
/// noise would otherwise enter H divided by r^2. While the noise dominates, the H error
/// then falls about as r^-3: the coefficient of |x|^2 / 2 fitted to N samples spread
/// over a disc of radius r, heights with noise sigma, has the standard deviation
/// sqrt(48) sigma / (sqrt(N) r^2). On an ellipsoid of 10,242 vertices (semi-axes 1, 0.8,
/// 0.6) with Gaussian noise of 7% of the mean edge length per coordinate, H RMS is 0.12
/// at 4 edges (about that bound; CGAL's jet fitting of degree 2 on the same ball: 0.12
/// too), 0.04 at 6 and 0.034 at 8, where the default 1-ring fit gives 5.9 (test
/// `test_ball_radius`). Without noise, at a fixed number of edges, the fit of degree d
/// converges at order about d - 1 on Delaunay meshes of random points. A ball with fewer
/// vertices than twice the fit's unknowns (6, 10 or 15) grows by steps of 25% until it
/// has them, and an ill-conditioned fit (condition thresholds 10 times those of the
/// ring fits of the same degree: a ball whose vertex is at its edge is one-sided for
/// the constant term too) grows it up to twice that radius; the status is then `widened`.
/// With `neighbor_weighting(Neighbor_weighting::smooth)` the vertices of the ball are
/// weighted by (1 - d^2 / r^2)^2 at the distance d, which falls smoothly to 0 at the ball's
/// radius r: less bias from the surface's higher-order terms (on that ellipsoid without noise
/// H RMS 0.0048 against 0.0078 at 4 edges) but more noise (0.20 against 0.12 at 4 edges with
/// it): it pays without noise, or with a radius large for the noise (0.033 against 0.034 at 8
/// edges, 0.047 against 0.075 at 12). The rings' parameters are not read, and the degree-2 fit's
/// fallback (below) applies unchanged.
///
/// **Widening.** A vertex whose normal equations are ill-conditioned (condition
/// number above `max_condition_number`, which includes singular ones and
/// stencils with fewer points than unknowns) is fitted again over one more ring,
/// up to `max_neighborhood_rings` rings; beyond that it is not estimable.
/// Conditioning, not a vanishing determinant, is the test: a stencil singular
/// in the parameter plane is still solvable in floating point once tilted, and
/// its solution is garbage.
///
/// **Conventions.** Curvatures are positive where the surface bends away from the
/// normal (a sphere with outward normals has `max_curvature == min_curvature == 1/r`),
/// `max_curvature >= min_curvature`, H is their mean, K their product. The fit is
/// made in coordinates scaled by the mean 1-ring edge length, so scaling the mesh
/// by s scales the curvatures by 1/s, to rounding. A vertex that cannot be
/// estimated (isolated, all neighbors coincident, non-finite coordinates,
/// ill-conditioned up to the widest ring) gets NaN in every output.
///
/// Only the outputs whose maps are passed are written; passing none does nothing.
///
/// \ceConcurrencyTag
/// \tparam FaceGraph a model of `FaceGraph` (faces may be any polygons).
/// \tparam NamedParameters a sequence of named parameters, built with the functions of
/// `CGAL::Curvature_estimation::parameters`
///
/// \param g the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \ceGivenNormalParameter
///   \cgalParamNBegin{vertex_normal_method}
///     \cgalParamDescription{how normals are estimated when no `vertex_normal_map` is given}
///     \cgalParamType{`CGAL::Curvature_estimation::Vertex_normal_method`}
///     \cgalParamDefault{`Vertex_normal_method::quadric_fit`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fit_degree}
///     \cgalParamDescription{the degree of the fitted polynomial: 2 is Hamann's paraboloid (with the default
///                           normal, the Taylor fit with linear terms described above), 3 and 4 the Taylor fits of
///                           those degrees over 2 and 3 rings (see Higher degrees above)}
///     \cgalParamType{`int`, 2, 3 or 4}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{ball_radius}
///     \cgalParamDescription{the radius of the ball that is the neighborhood instead of the rings (see
///                           Curvature at a scale above); CGAL 6's name for the same idea in
///                           `interpolated_corrected_curvatures()`}
///     \cgalParamType{`double`, positive, in the units of the mesh (see `mean_edge_length()`)}
///     \cgalParamDefault{none: the rings}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighbor_weighting}
///     \cgalParamDescription{with a `ball_radius` only: the weights of the ball's vertices, `uniform` or `smooth`
///                           ((1 - d^2 / r^2)^2 at the distance d, for the radius r of the ball: see Curvature at a
///                           scale above)}
///     \cgalParamType{`CGAL::Curvature_estimation::Neighbor_weighting`}
///     \cgalParamDefault{`Neighbor_weighting::uniform`}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{number of rings an interior vertex's fit starts with (1: Hamann's platelet)}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_neighborhood_rings}
///     \cgalParamDescription{number of rings a boundary vertex's fit starts with (Hamann's tables use 2)}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{the value of `neighborhood_rings`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_neighborhood_rings}
///     \cgalParamDescription{the widest neighborhood an ill-conditioned fit is widened to}
///     \cgalParamType{`int`, at least the two values above}
///     \cgalParamDefault{`3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_condition_number}
///     \cgalParamDescription{the largest 1-norm condition number of the normal equations of a fit
///                           (the curvature fit and the normal's) that is accepted. The fit is widened
///                           ring by ring while it exceeds this value in tangent coordinates scaled by
///                           the mean 1-ring edge length; where it does on every ring up to
///                           `max_neighborhood_rings`, the widest neighborhood is accepted if the
///                           condition number is below this value in tangent coordinates whitened by
///                           the neighborhood's own second moments, with the linear terms included.
///                           That number does not change under a linear change of the tangent
///                           coordinates: a neighborhood of long thin triangles is accepted, one whose
///                           points lie on a line or on a conic through the vertex (a degenerate
///                           neighborhood, also once tilted) is not. The cubic fit of a boundary normal
///                           is allowed 1000 times this value.}
///     \cgalParamType{`double`, greater than 1}
///     \cgalParamDefault{`1e3`}
///   \cgalParamNEnd
///   \ceSurfaceOutputParameters{K = k1 k2, `ok`\, `widened` (see Widening above)\, `fallback` (see Fallback above) or
///   `not_estimable`}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void paraboloid_fitting_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const internal::Fit_parameters fit = internal::curvature_fit_parameters(np, "paraboloid_fitting_curvatures", 4, true);
  internal::estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    return internal::Paraboloid_estimator<FaceGraph, std::decay_t<decltype(vpm)>>(g, vpm, fit);
  });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_PARABOLOID_FITTING_H
