// SPDX-License-Identifier: GPL-3.0-or-later
// What every estimation of the tool shares: its time, the library's exceptions as
// the tool's errors, the rings --rings asks for, the radius --radius asks for and
// the mean size of its balls.
#ifndef CE_TOOLS_ESTIMATION_SETTINGS_H
#define CE_TOOLS_ESTIMATION_SETTINGS_H

#include "command_line.h"
#include "tool_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace ce_tool {

// Runs `estimate()` and turns the library's exceptions into the tool's errors;
// returns the time it took, in seconds.
template <typename Estimate>
double timed_estimate(Estimate estimate)
{
  const auto start = std::chrono::steady_clock::now();
  try {
    estimate();
  } catch (const std::invalid_argument& e) {
    fail(std::string("invalid parameter: ") + e.what(), 2);
  } catch (const std::bad_alloc&) {
    fail("out of memory while estimating curvature");
  } catch (const std::exception& e) {
    fail(std::string("estimation failed: ") + e.what());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --rings N: start on N rings (default 1) and widen up to max(3, N), as for every
// method with rings (jet fitting too, whose own default widens further).
inline int rings(const Options& o) { return o.rings.value_or(1); }
inline int max_rings(const Options& o) { return std::max(3, rings(o)); }

// --radius in the input's units: R, or N times `mean_edge_length` for Nx (`unit`
// names it in the message). Fails where that is no positive finite length (1e308x
// of a mesh whose edges are long).
inline double ball_radius(const Radius& radius, double mean_edge_length,
                          const char* unit = "the mean edge length of the mesh")
{
  const double r = radius.in_mean_edges ? radius.value * mean_edge_length : radius.value;
  if (!(r > 0) || !std::isfinite(r)) {
    std::ostringstream message;
    message << "--radius " << radius.value << "x is no positive finite length: " << unit << " is " << mean_edge_length;
    fail(message.str(), 2);
  }
  return r;
}

// --radius auto[:A:B] in the input's units, the lengths in `unit` units for Ax and Bx
// (`unit_name` names the unit in the message, `units` the input's units). Fails where
// A > B.
inline std::pair<double, double> radius_range(const Radius_range& range, double unit, const char* unit_name,
                                              const char* units)
{
  const double min = ball_radius(range.min, unit, unit_name), max = ball_radius(range.max, unit, unit_name);
  if (min > max) {
    std::ostringstream message;
    message << "--radius auto:A:B needs A <= B: here A is " << min << " and B " << max << " in " << units;
    fail(message.str(), 2);
  }
  return {min, max};
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
