// SPDX-License-Identifier: GPL-3.0-or-later
// Surface estimation: the registry's method --method picks, with the settings
// of the options, and its outputs as one row per vertex of the input file.
#ifndef CE_TOOLS_SURFACE_ESTIMATION_H
#define CE_TOOLS_SURFACE_ESTIMATION_H

#include "command_line.h"
#include "estimation_settings.h"
#include "kernel.h"
#include "registry.h"

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace ce_tool {

// The tool's name of a status: the library's, except "failed" for not_estimable.
inline const char* status_name(CE::Estimation_status status)
{
  return status == CE::Estimation_status::not_estimable ? "failed" : CE::to_string(status);
}

struct Row
{
  double k_max, k_min, mean, gaussian;
  std::array<double, 3> d_max, d_min;
  CE::Estimation_status status;

  std::array<double, 10> values() const
  {
    return {k_max, k_min, mean, gaussian, d_max[0], d_max[1], d_max[2], d_min[0], d_min[1], d_min[2]};
  }
};

// The estimates at the file's vertices, read from the mesh's property maps:
// rows[i] is the row of the file's vertex i, failed where the vertex is in no face
// (file_to_mesh from build_mesh) or not estimable.
struct Surface_estimates
{
  Outputs maps;
  std::vector<V> file_to_mesh;
  double seconds = 0; // the estimator's time
  // With --radius: the balls' radius in mesh units and the mean edge length of the
  // mesh; 0 without it (or where the mesh is empty).
  double ball_radius = 0, mean_edge_length = 0;
  // With --radius auto: the range in mesh units (the mean edge length as above), and the
  // radius chosen and the noise estimated per vertex.
  std::optional<Settings::Radius_selection> radius_selection;

  std::size_t size() const { return file_to_mesh.size(); }
  Row operator[](std::size_t i) const;
  // With --radius auto: the chosen radius and the noise of the file's vertex i; NaN
  // where its row is failed.
  std::array<double, 2> radius_and_noise(std::size_t i) const;
  // The library's vertex_reach_map at the file's vertex i (0 where it is in no face).
  double reach(std::size_t i) const;
};

// The settings of the options but a radius (--radius, --radius auto): rings where the method reads them and
// no radius is given, the degrees and the extrapolation order.
Settings settings_of(const Options& o);

// Runs the method --method picks; its outputs are property maps added to `mesh`.
// --radius Nx (and --radius auto's bounds Nx) is N times the mean edge length of `mesh`. `given_normals` (the Python
// module's; the tool has none) are the mesh's vertex normals, for the methods that read them.
Surface_estimates estimate(const Options& o, Mesh& mesh, std::vector<V> file_to_mesh,
                           const std::optional<Normal_map>& given_normals = std::nullopt);

// Ball_size (estimation_settings.h) of the balls of radius `radius` in `mesh`.
Ball_size mean_ball_size(const Mesh& mesh, double radius);

} // namespace ce_tool

#endif // CE_TOOLS_SURFACE_ESTIMATION_H
