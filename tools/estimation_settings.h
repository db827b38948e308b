// SPDX-License-Identifier: GPL-3.0-or-later
// What every estimation of the tool shares: the concurrency --threads asks for,
// the rings --rings asks for, the radius --radius asks for and the mean size of
// its balls, and the library's exceptions as the tool's errors.
#ifndef CE_TOOLS_ESTIMATION_SETTINGS_H
#define CE_TOOLS_ESTIMATION_SETTINGS_H

#include "command_line.h"
#include "tool_error.h"

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ce_tool {

// Runs `estimate(tag)` with the concurrency tag --threads asks for, and turns
// the library's exceptions into the tool's errors; returns the time it took, in seconds.
template <typename Estimate>
double run_with_threads(int threads, Estimate estimate)
{
  const auto start = std::chrono::steady_clock::now();
  try {
    if (threads == 1) {
      estimate(CGAL::Sequential_tag());
    } else {
#ifdef CGAL_LINKED_WITH_TBB
      std::unique_ptr<tbb::global_control> limit;
      if (threads > 1)
        limit =
          std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
      estimate(CGAL::Parallel_tag());
#else
      estimate(CGAL::Sequential_tag());
#endif
    }
  } catch (const std::invalid_argument& e) {
    fail(std::string("invalid parameter: ") + e.what(), 2);
  } catch (const std::bad_alloc&) {
    fail("out of memory while estimating curvature");
  } catch (const std::exception& e) {
    fail(std::string("estimation failed: ") + e.what());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --rings N: start on N rings, widen up to max(3, N), as for every method with rings.
template <typename NamedParameters>
auto with_rings(const Options& o, const NamedParameters& np)
{
  const int rings = o.rings.value_or(1);
  return np.neighborhood_rings(rings).max_neighborhood_rings(std::max(3, rings));
}

// --radius in the input's units: R, or N times `mean_edge_length` for Nx. Fails
// where that is no positive finite length (1e308x of a mesh whose edges are long).
inline double ball_radius(const Radius& radius, double mean_edge_length)
{
  const double r = radius.in_mean_edges ? radius.value * mean_edge_length : radius.value;
  if (!(r > 0) || !std::isfinite(r)) {
    std::ostringstream message;
    message << "--radius " << radius.value << "x is no positive finite length: the mean edge length of the mesh is "
            << mean_edge_length;
    fail(message.str(), 2);
  }
  return r;
}

// The number of vertices in the ball of a radius about a vertex, as the ball_radius
// estimators gather it before they grow it (the vertex and the mesh joined to it by
// edges inside the ball): its mean over `sampled` vertices, all of them up to
// max_ball_samples, else at most that many, evenly spaced in the vertex order. On
// CGAL's bunny, Chinese dragon, armadillo and elephant at 2, 4 and 8 mean edge
// lengths, counting every ball took 40% to 65% of the time of the sequential
// paraboloid estimate, and the sample's mean was within 2% of the mean over all
// vertices.
struct Ball_size
{
  double mean = 0;
  std::size_t sampled = 0;
};
constexpr std::size_t max_ball_samples = 1000;

// Ball_size over vertices 0 to n - 1, `ball_size(i)` the size of vertex i's ball.
template <typename BallSizeOf>
Ball_size mean_ball_size(std::size_t n, const BallSizeOf& ball_size)
{
  const std::size_t stride = std::max<std::size_t>(1, (n + max_ball_samples - 1) / max_ball_samples);
  std::size_t sum = 0;
  Ball_size result;
  for (std::size_t i = 0; i < n; i += stride) {
    sum += ball_size(i);
    ++result.sampled;
  }
  if (result.sampled != 0)
    result.mean = double(sum) / double(result.sampled);
  return result;
}

} // namespace ce_tool

#endif // CE_TOOLS_ESTIMATION_SETTINGS_H
