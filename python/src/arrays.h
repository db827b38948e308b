// SPDX-License-Identifier: GPL-3.0-or-later
// The numpy arrays of curvature_estimation._core: the checks of its inputs (each
// refusal a ValueError naming the argument) and the outputs it fills.
#ifndef CE_PYTHON_ARRAYS_H
#define CE_PYTHON_ARRAYS_H

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ce_python {

namespace py = pybind11;

using Float_array = py::array_t<double, py::array::c_style | py::array::forcecast>;

[[noreturn]] void refuse(const std::string& message);

// `object` (an array, or anything numpy makes one of) of float64 or float32, as a
// C-contiguous float64 array of shape (n, columns), or (n,) where columns is 0: not
// empty, every value finite.
Float_array real_array(const py::handle& object, const char* name, py::ssize_t columns);

// `object`, an integer array of shape (m, columns) (columns at least 3 where
// `columns` is 0), as m rows of std::size_t: not empty, every index in 0..n-1.
struct Index_rows
{
  std::vector<std::size_t> indices; // row after row
  std::size_t columns = 0;
  std::size_t rows() const { return columns != 0 ? indices.size() / columns : 0; }
  const std::size_t* row(std::size_t r) const { return indices.data() + r * columns; }
};
Index_rows index_array(const py::handle& object, const char* name, py::ssize_t columns, std::size_t n);

// A new float64 array of shape (n, columns), or (n,) where columns is 0.
py::array_t<double> new_array(std::size_t n, std::size_t columns = 0);

// A number of threads as --threads takes it: 0 (all cores) or more.
int thread_count(int threads);

} // namespace ce_python

#endif // CE_PYTHON_ARRAYS_H
