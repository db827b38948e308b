// SPDX-License-Identifier: GPL-3.0-or-later
/*!
\ingroup PkgCurvatureEstimationConcepts
\cgalConcept

A tetrahedral complex: a finite set of vertices and of tetrahedral cells, each cell
given by its four vertices. The estimator
`CGAL::Curvature_estimation::hypersurface_paraboloid_fitting_curvatures()` reads a model
through the traits class `CGAL::Curvature_estimation::Tetrahedral_complex_traits`, in the way
the BGL reads a graph through `boost::graph_traits`: a type is a model when the traits
class is specialized for it with the types and static functions below. Nothing else is
required; in particular no incidence structure: the vertex stars (incident cells, neighbors,
boundary flags) are built once from the cells by
`CGAL::Curvature_estimation::Tetrahedral_complex_stars`, never by scanning all cells per vertex.

Cells may be listed in any order and orientation, but the orientation decides the sign of the
estimated normals (see `CGAL::Curvature_estimation::Indexed_tetrahedral_mesh`). The complex
need not be a manifold: a vertex is fitted over the vertices it shares a cell with (and their
rings), whatever the shape of its star, or gets the status `not_estimable`.

\cgalHasModelsBegin
\cgalHasModels{CGAL::Curvature_estimation::Indexed_tetrahedral_mesh}
\cgalHasModels{Any CGAL 3D triangulation: CGAL::Triangulation_3, CGAL::Delaunay_triangulation_3,
CGAL::Regular_triangulation_3 and the triangulation of a Mesh_3 complex (c3t3.triangulation());
finite vertices and finite cells only (to use only the cells of a Mesh_3 complex, those of
cells_in_complex(), copy them into an Indexed_tetrahedral_mesh).}
\cgalHasModelsEnd
*/
class TetrahedralComplex
{
public:
  /// \name Types of Tetrahedral_complex_traits<TetrahedralComplex>
  /// @{

  /// A copyable handle or index of a vertex, usable as a property map key.
  typedef unspecified_type vertex_descriptor;

  /// A readable property map from `vertex_descriptor` to the vertex's point; the
  /// estimators need points of R^4 (see `CGAL::Curvature_estimation::to_vector_4()`),
  /// so a complex whose points are 3D needs a `vertex_point_map`, for instance from
  /// `CGAL::Curvature_estimation::make_graph_point_map()`.
  typedef unspecified_type Default_point_map;

  /// @}

  /// \name Static functions of Tetrahedral_complex_traits<TetrahedralComplex>
  /// @{

  /// The number of vertices that `for_each_vertex()` visits.
  static std::size_t number_of_vertices(const TetrahedralComplex& c);

  /// Calls `f(v)` once for every vertex `v`.
  template <typename F>
  static void for_each_vertex(const TetrahedralComplex& c, F f);

  /// Calls `f(v0, v1, v2, v3)` once for every cell, with its four vertices. A cell
  /// with a vertex that `for_each_vertex()` does not visit is an error (throw
  /// `std::invalid_argument`).
  template <typename F>
  static void for_each_cell(const TetrahedralComplex& c, F f);

  /// The point map used when no `vertex_point_map` is passed.
  static Default_point_map default_point_map(const TetrahedralComplex& c);

  /// @}
};
