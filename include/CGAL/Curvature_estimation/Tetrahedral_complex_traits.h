// SPDX-License-Identifier: GPL-3.0-or-later
// The TetrahedralComplex concept's adapters (CGAL::Triangulation_3 and an indexed
// tetrahedral mesh), vertex stars gathered once, and points of R^4.
#ifndef CGAL_CURVATURE_ESTIMATION_TETRAHEDRAL_COMPLEX_TRAITS_H
#define CGAL_CURVATURE_ESTIMATION_TETRAHEDRAL_COMPLEX_TRAITS_H

#include <CGAL/Handle_hash_function.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// A plain tetrahedral mesh: a vector of points and a vector of cells, each the
/// four indices of its vertices in `points`. A model of `TetrahedralComplex`
/// whose vertex descriptor is the index `std::size_t`.
///
/// The cells' orientation decides the orientation of the estimated normals: a
/// cell (a, b, c, d) contributes the generalized cross product of b-a, c-a, d-a
/// (in R^4), and for the graph of a function over positively oriented tetrahedra
/// of R^3 (as in `CGAL::Triangulation_3`) that normal points to increasing W.
///
/// \tparam Point the point type; for the estimators, a point of R^4 or
///         (with a point map built by `make_graph_point_map()`) of R^3.
template <typename Point>
struct Indexed_tetrahedral_mesh
{
  using Point_type = Point;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 4>> cells;
};

/// \ingroup PkgCurvatureEstimationRef
/// The traits of a model of the `TetrahedralComplex` concept: the vertex
/// descriptor, the vertices (`for_each_vertex(c, f)` calls `f(v)` for every vertex
/// once), the cells (`for_each_cell(c, f)` calls `f(v0, v1, v2, v3)` for every cell
/// with its four vertices), and the default vertex point map.
/// The incident cells of each vertex are built from these once, in O(number of cells),
/// by `Tetrahedral_complex_stars`. Specialized for `Indexed_tetrahedral_mesh` and
/// `CGAL::Triangulation_3` (finite cells and vertices only; so also the
/// triangulation of a Mesh_3 `C3T3`).
template <typename Complex, typename Enable = void>
struct Tetrahedral_complex_traits;

template <typename Point>
struct Tetrahedral_complex_traits<Indexed_tetrahedral_mesh<Point>>
{
  using Complex = Indexed_tetrahedral_mesh<Point>;
  using vertex_descriptor = std::size_t;
  /// reads `points[i]`
  using Default_point_map = typename CGAL::Pointer_property_map<Point>::const_type;

  static std::size_t number_of_vertices(const Complex& c) { return c.points.size(); }
  template <typename F>
  static void for_each_vertex(const Complex& c, F f)
  {
    for (std::size_t i = 0; i < c.points.size(); ++i)
      f(i);
  }
  template <typename F>
  static void for_each_cell(const Complex& c, F f)
  {
    for (const auto& cell : c.cells) {
      for (std::size_t v : cell)
        if (v >= c.points.size())
          throw std::invalid_argument("Indexed_tetrahedral_mesh: a cell index is out of range");
      f(cell[0], cell[1], cell[2], cell[3]);
    }
  }
  static Default_point_map default_point_map(const Complex& c) { return CGAL::make_property_map(c.points.data()); }
};

// Any CGAL 3D triangulation (Triangulation_3, Delaunay_triangulation_3,
// Regular_triangulation_3, the triangulation of a Mesh_3 C3T3): recognised by its
// finite-cell and finite-vertex iterators.
template <typename Tr>
struct Tetrahedral_complex_traits<
  Tr, std::void_t<decltype(std::declval<const Tr&>().finite_cells_begin()),
                  decltype(std::declval<const Tr&>().finite_vertices_begin()), typename Tr::Vertex_handle>>
{
  using Complex = Tr;
  using vertex_descriptor = typename Complex::Vertex_handle;
  /// reads `v->point()` (a point of R^3: pass an R^4 point map, e.g. from `make_graph_point_map()`)
  struct Default_point_map
  {
    using key_type = vertex_descriptor;
    using value_type = typename Complex::Point;
    using reference = const value_type&;
    using category = boost::readable_property_map_tag;
    friend reference get(const Default_point_map&, key_type v) { return v->point(); }
  };

  static std::size_t number_of_vertices(const Complex& c) { return c.number_of_vertices(); }
  template <typename F>
  static void for_each_vertex(const Complex& c, F f)
  {
    for (auto v = c.finite_vertices_begin(); v != c.finite_vertices_end(); ++v)
      f(vertex_descriptor(v));
  }
  template <typename F>
  static void for_each_cell(const Complex& c, F f)
  {
    if (c.dimension() < 3)
      return;
    for (auto cell = c.finite_cells_begin(); cell != c.finite_cells_end(); ++cell)
      f(cell->vertex(0), cell->vertex(1), cell->vertex(2), cell->vertex(3));
  }
  static Default_point_map default_point_map(const Complex&) { return Default_point_map(); }
};

/// \ingroup PkgCurvatureEstimationRef
/// The vertex stars of a tetrahedral complex, gathered once in O(C log C) for C cells:
/// the vertices in a dense order, the cells as index quadruples, the incident cells and
/// the neighbors (vertices sharing a cell) of each vertex in CSR arrays, and whether a
/// vertex lies on the boundary (on a triangle that belongs to one cell only).
template <typename Complex>
struct Tetrahedral_complex_stars
{
  using Traits = Tetrahedral_complex_traits<Complex>;
  using vertex_descriptor = typename Traits::vertex_descriptor;

  std::vector<vertex_descriptor> vertices;               // dense index -> descriptor
  std::vector<std::array<std::size_t, 4>> cells;         // dense indices
  std::vector<std::size_t> cell_offsets, incident_cells; // CSR: cells of vertex i
  std::vector<std::size_t> neighbor_offsets, neighbors;  // CSR: 1-ring of vertex i
  std::vector<char> on_boundary;

  std::size_t size() const { return vertices.size(); }

  explicit Tetrahedral_complex_stars(const Complex& c)
  {
    vertices.reserve(Traits::number_of_vertices(c));
    if constexpr (std::is_integral<vertex_descriptor>::value) {
      Traits::for_each_vertex(c, [&](vertex_descriptor v) { vertices.push_back(v); });
      Traits::for_each_cell(c, [&](vertex_descriptor a, vertex_descriptor b, vertex_descriptor d, vertex_descriptor e) {
        cells.push_back({std::size_t(a), std::size_t(b), std::size_t(d), std::size_t(e)});
      });
    } else {
      std::unordered_map<vertex_descriptor, std::size_t, CGAL::Handle_hash_function> index;
      index.reserve(Traits::number_of_vertices(c));
      Traits::for_each_vertex(c, [&](vertex_descriptor v) {
        index.emplace(v, vertices.size());
        vertices.push_back(v);
      });
      Traits::for_each_cell(c, [&](vertex_descriptor a, vertex_descriptor b, vertex_descriptor d, vertex_descriptor e) {
        cells.push_back({index.at(a), index.at(b), index.at(d), index.at(e)});
      });
    }
    build();
  }

private:
  void build()
  {
    const std::size_t n = vertices.size();
    // Incident cells: counting sort.
    cell_offsets.assign(n + 1, 0);
    for (const auto& cell : cells)
      for (std::size_t v : cell)
        ++cell_offsets[v + 1];
    for (std::size_t i = 0; i < n; ++i)
      cell_offsets[i + 1] += cell_offsets[i];
    incident_cells.resize(cell_offsets[n]);
    {
      std::vector<std::size_t> fill(cell_offsets.begin(), cell_offsets.end() - 1);
      for (std::size_t k = 0; k < cells.size(); ++k)
        for (std::size_t v : cells[k])
          incident_cells[fill[v]++] = k;
    }
    // Neighbors: the other vertices of the incident cells, without repeats.
    neighbor_offsets.assign(n + 1, 0);
    neighbors.clear();
    neighbors.reserve(incident_cells.size() * 2);
    std::vector<std::size_t> mark(n, std::size_t(-1));
    for (std::size_t v = 0; v < n; ++v) {
      mark[v] = v;
      for (std::size_t k = cell_offsets[v]; k < cell_offsets[v + 1]; ++k)
        for (std::size_t w : cells[incident_cells[k]])
          if (mark[w] != v) {
            mark[w] = v;
            neighbors.push_back(w);
          }
      neighbor_offsets[v + 1] = neighbors.size();
    }
    // Boundary: triangles met once.
    std::vector<std::array<std::size_t, 3>> faces;
    faces.reserve(4 * cells.size());
    for (const auto& cell : cells)
      for (int skip = 0; skip < 4; ++skip) {
        std::array<std::size_t, 3> f;
        for (int i = 0, j = 0; i < 4; ++i)
          if (i != skip)
            f[j++] = cell[i];
        std::sort(f.begin(), f.end());
        faces.push_back(f);
      }
    std::sort(faces.begin(), faces.end());
    on_boundary.assign(n, 0);
    for (std::size_t i = 0; i < faces.size();) {
      std::size_t j = i + 1;
      while (j < faces.size() && faces[j] == faces[i])
        ++j;
      if (j - i == 1)
        for (std::size_t v : faces[i])
          on_boundary[v] = 1;
      i = j;
    }
  }
};

/// \ingroup PkgCurvatureEstimationRef
/// The coordinates of a point (or vector) of R^4 in double: accepts
/// `Eigen::Vector4d`, `std::array<T, 4>`, and CGAL's d-dimensional points and vectors
/// (`Epick_d<Dimension_tag<4>>::Point_d`, `Vector_d`), through `cartesian_begin()`.
template <typename P>
Eigen::Vector4d to_vector_4(const P& p)
{
  if constexpr (std::is_convertible<const P&, Eigen::Vector4d>::value) {
    return Eigen::Vector4d(p);
  } else if constexpr (std::is_same<P, std::array<typename P::value_type, 4>>::value) {
    return Eigen::Vector4d(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]), CGAL::to_double(p[3]));
  } else {
    if (p.dimension() != 4)
      throw std::invalid_argument("Curvature_estimation: the vertex points must be points of R^4 "
                                  "(for a graph W = f(x, y, z), use make_graph_point_map)");
    Eigen::Vector4d result;
    auto it = p.cartesian_begin();
    for (int i = 0; i < 4; ++i, ++it)
      result[i] = CGAL::to_double(*it);
    return result;
  }
}

/// \ingroup PkgCurvatureEstimationRef
/// A vector of R^4 of type `V` from coordinates: `Eigen::Vector4d`, `std::array<T, 4>`,
/// or any type constructible from a range of 4 coordinates (CGAL's `Vector_d`).
template <typename V>
V from_vector_4(const Eigen::Vector4d& v)
{
  if constexpr (std::is_same<V, Eigen::Vector4d>::value)
    return v;
  else if constexpr (std::is_same<V, std::array<typename V::value_type, 4>>::value)
    return V{typename V::value_type(v[0]), typename V::value_type(v[1]), typename V::value_type(v[2]),
             typename V::value_type(v[3])};
  else
    return V(v.data(), v.data() + 4);
}

/// \ingroup PkgCurvatureEstimationRef
/// A readable property map giving the point (x, y, z, f) of R^4, as a
/// `std::array<double, 4>`, from a map of points of R^3 and a map of scalars with
/// the same key: the vertices of the graph W = f(x, y, z). Made by `make_graph_point_map()`.
template <typename PointMap3, typename ScalarMap>
struct Graph_point_map
{
  using key_type = typename boost::property_traits<PointMap3>::key_type;
  using value_type = std::array<double, 4>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  PointMap3 points;
  ScalarMap scalars;

  friend value_type get(const Graph_point_map& map, const key_type& k)
  {
    const auto& p = get(map.points, k);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()),
            CGAL::to_double(get(map.scalars, k))};
  }
};

/// \ingroup PkgCurvatureEstimationRef
/// The R^4 point map (x, y, z, f) of the graph of a scalar field over a 3D point map.
template <typename PointMap3, typename ScalarMap>
Graph_point_map<PointMap3, ScalarMap> make_graph_point_map(PointMap3 points, ScalarMap scalars)
{
  return Graph_point_map<PointMap3, ScalarMap>{points, scalars};
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_TETRAHEDRAL_COMPLEX_TRAITS_H
