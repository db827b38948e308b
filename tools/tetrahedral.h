// SPDX-License-Identifier: GPL-3.0-or-later
// Tetrahedral input: the graph W = f(x, y, z) over a Medit .mesh, f from a .sol,
// read, oriented, and estimated as a hypersurface of R^4.
#ifndef CE_TOOLS_TETRAHEDRAL_H
#define CE_TOOLS_TETRAHEDRAL_H

#include "command_line.h"
#include "estimation_settings.h"
#include "kernel.h"

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Tetrahedral_complex_traits.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ce_tool {

using Tetrahedral_mesh = CE::Indexed_tetrahedral_mesh<Point>;

struct Tetrahedral_input
{
  Tetrahedral_mesh mesh;
  std::vector<double> scalars; // f at the vertices
};

// Makes each tetrahedron positively oriented, which orients the hypersurface's normal
// towards increasing f (see hypersurface_paraboloid_fitting_curvatures); returns the
// index (from 0) of the first tetrahedron of zero volume, where it stops, if there is one.
std::optional<std::size_t> orient_tetrahedra(Tetrahedral_mesh& mesh);

// The syntax and the combinatorics are the reader's (mesh_readers.h); the geometry
// is checked here, with CGAL's exact orientation predicate (orient_tetrahedra): a flat
// tetrahedron is an error.
// f is read from the .sol `scalars` names, or from the .sol beside the .mesh if it is empty.
Tetrahedral_input read_tetrahedral_input(const std::string& mesh_path, const std::string& scalars);

struct Tetrahedral_row
{
  double k_1, k_2, k_3, mean, gaussian;
  CE::Estimation_status status;

  std::array<double, 5> values() const { return {k_1, k_2, k_3, mean, gaussian}; }
};

struct Tetrahedral_estimates
{
  std::vector<Tetrahedral_row> rows; // a row per vertex of the .mesh, in its order
  double seconds = 0;                // the estimator's time
  // With --radius: the balls' radius and the mean edge length, both in R^4 (the
  // points (x, y, z, f)), and the balls' mean size; zeros without it.
  double ball_radius = 0, mean_edge_length = 0;
  Ball_size ball_size;
};

// --radius Nx is N times the mean edge length of the graph in R^4, whose balls the
// fit takes.
Tetrahedral_estimates estimate_tetrahedral(const Options& o, const Tetrahedral_input& input);

} // namespace ce_tool

#endif // CE_TOOLS_TETRAHEDRAL_H
