// SPDX-License-Identifier: GPL-3.0-or-later
// From flat arrays to the tool's polygon soup, and from its rows of estimates to flat
// arrays: what mesh_curvatures does around the tool's mesh build and estimation, without
// Python, so that benchmark/python_overhead_peer (the C++ peer of the Python call) does
// the same work.
#ifndef CE_PYTHON_SURFACE_ROWS_H
#define CE_PYTHON_SURFACE_ROWS_H

#include "surface_estimation.h"
#include "surface_input.h"

#include <cstddef>
#include <cstdint>

namespace ce_python {

// The soup of n points (x, y, z after each other) and m polygons of k indices each
// (row after row, each below n).
ce_tool::Soup soup_of(const double* xyz, std::size_t n, const std::size_t* indices, std::size_t m, std::size_t k);

// Where the rows go: n values each, d_max and d_min n rows of 3; radius and noise
// where given (with --radius auto).
struct Surface_outputs
{
  double *k_max, *k_min, *mean, *gaussian, *d_max, *d_min;
  std::uint8_t* status;
  double *radius = nullptr, *noise = nullptr, *reach = nullptr;
};

// Row i of `rows` (the file's vertex i) into element i of each output.
void write_rows(const ce_tool::Surface_estimates& rows, const Surface_outputs& out);

} // namespace ce_python

#endif // CE_PYTHON_SURFACE_ROWS_H
