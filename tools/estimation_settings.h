// SPDX-License-Identifier: GPL-3.0-or-later
// What every estimation of the tool shares: the concurrency --threads asks for,
// the rings --rings asks for, and the library's exceptions as the tool's errors.
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
#include <cstddef>
#include <exception>
#include <memory>
#include <new>
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
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      std::size_t(threads));
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

} // namespace ce_tool

#endif // CE_TOOLS_ESTIMATION_SETTINGS_H
