// SPDX-License-Identifier: GPL-3.0-or-later
#include "arrays.h"

#include <cmath>
#include <limits>

namespace ce_python {

namespace {

std::string dtype_name(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

// `object` as an array of `dims` dimensions whose second is `columns` (any from 3 where
// `columns` is 0) and whose first is not 0.
py::array shaped_array(const py::handle& object, const char* name, py::ssize_t columns, py::ssize_t dims)
{
  const py::array a = py::array::ensure(object);
  if (!a)
    refuse(std::string(name) + " must be a numpy array or convertible to one");
  std::string expected = columns != 0 ? "(n, " + std::to_string(columns) + ")" : dims == 2 ? "(m, k >= 3)" : "(n,)";
  const bool shape_ok = a.ndim() == dims && (dims == 1 || (columns != 0 ? a.shape(1) == columns : a.shape(1) >= 3));
  if (!shape_ok) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(a.shape(d));
    shape += a.ndim() == 1 ? ",)" : ")";
    refuse(std::string(name) + " must have the shape " + expected + ", got " + shape);
  }
  if (a.shape(0) == 0)
    refuse(std::string(name) + " is empty");
  return a;
}

template <typename Integer>
void copy_indices(const py::array& a, const char* name, std::size_t n, Index_rows& rows)
{
  const auto typed = py::array_t<Integer, py::array::c_style | py::array::forcecast>::ensure(a);
  const Integer* data = typed.data();
  rows.indices.resize(static_cast<std::size_t>(typed.size()));
  for (std::size_t k = 0; k < rows.indices.size(); ++k) {
    const Integer index = data[k];
    if constexpr (std::numeric_limits<Integer>::is_signed) {
      if (index < 0)
        refuse(std::string(name) + " row " + std::to_string(k / rows.columns) + " holds the negative index " +
               std::to_string(index));
    }
    if (static_cast<std::uint64_t>(index) >= n)
      refuse(std::string(name) + " row " + std::to_string(k / rows.columns) + " refers to vertex " +
             std::to_string(index) + " but there are " + std::to_string(n) + " vertices");
    rows.indices[k] = static_cast<std::size_t>(index);
  }
}

} // namespace

void refuse(const std::string& message) { throw py::value_error(message); }

Float_array real_array(const py::handle& object, const char* name, py::ssize_t columns)
{
  const py::array a = shaped_array(object, name, columns, columns != 0 ? 2 : 1);
  if (a.dtype().kind() != 'f' || (a.itemsize() != 8 && a.itemsize() != 4))
    refuse(std::string(name) + " must be float64 or float32, got " + dtype_name(a));
  const Float_array values = Float_array::ensure(a);
  const double* data = values.data();
  for (py::ssize_t k = 0; k < values.size(); ++k)
    if (!std::isfinite(data[k]))
      refuse(std::string(name) + " row " + std::to_string(columns != 0 ? k / columns : k) +
             " holds a non-finite value (NaN or infinite)");
  return values;
}

Index_rows index_array(const py::handle& object, const char* name, py::ssize_t columns, std::size_t n)
{
  const py::array a = shaped_array(object, name, columns, 2);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    refuse(std::string(name) + " must be an integer array (int32 or int64), got " + dtype_name(a));
  Index_rows rows;
  rows.columns = static_cast<std::size_t>(a.shape(1));
  if (kind == 'u')
    copy_indices<std::uint64_t>(a, name, n, rows);
  else
    copy_indices<std::int64_t>(a, name, n, rows);
  return rows;
}

py::array_t<double> new_array(std::size_t n, std::size_t columns)
{
  if (columns == 0)
    return py::array_t<double>(static_cast<py::ssize_t>(n));
  return py::array_t<double>({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(columns)});
}

int thread_count(int threads)
{
  if (threads < 0)
    refuse("threads must be 0 (all cores), 1 (sequential) or more, got " + std::to_string(threads));
  return threads;
}

} // namespace ce_python
