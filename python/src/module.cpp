// SPDX-License-Identifier: GPL-3.0-or-later
// curvature_estimation._core: numpy arrays in, numpy arrays out, through the command-line
// tool's own parts (tools/): its mesh of a polygon soup with its repair, its registry of
// methods and option checks, its rows and its tetrahedral path, so that a call gives the
// tool's values bit for bit. The inputs are converted under the GIL; the estimation runs
// without it. The package's Python layer (curvature_estimation/__init__.py) names the outputs.
#include "arrays.h"
#include "point_sets.h"
#include "surface_rows.h"

#include "command_line.h"
#include "mesh_readers.h"
#include "registry.h"
#include "soup_repair.h"
#include "surface_estimation.h"
#include "tetrahedral.h"
#include "tool_error.h"

#include <pybind11/stl.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ce_python {

namespace {

using namespace ce_tool;

// The integer settings as the tool's options parse them: within the registry's range.
void check_range(const std::optional<int>& value, const char* name, Setting setting)
{
  const Integer_range r = integer_range(setting);
  if (value && (*value < r.min || *value > r.max))
    refuse(std::string(name) + " must be an integer from " + std::to_string(r.min) + " to " + std::to_string(r.max) +
           ", got " + std::to_string(*value));
}

// The string "auto" or "auto:A:B" of --radius auto, else nothing.
std::optional<std::string> auto_radius_text(const py::object& radius)
{
  if (!py::isinstance<py::str>(radius))
    return std::nullopt;
  std::string text = radius.cast<std::string>();
  if (text.compare(0, 4, "auto") != 0)
    return std::nullopt;
  return text;
}

// --radius: a length in mesh units, or a string "Nx" of N mean edge lengths (not auto).
std::optional<Radius> radius_of(const py::object& radius)
{
  if (radius.is_none() || auto_radius_text(radius))
    return std::nullopt;
  if (py::isinstance<py::str>(radius))
    return parse_radius("radius", radius.cast<std::string>());
  if (py::isinstance<py::bool_>(radius) || !(py::isinstance<py::float_>(radius) || py::isinstance<py::int_>(radius)))
    refuse("radius must be a number or a string such as '4x', got " + py::repr(radius).cast<std::string>());
  const double value = radius.cast<double>();
  if (!(value > 0) || !std::isfinite(value))
    refuse("radius must be a positive finite length, got " + py::repr(radius).cast<std::string>());
  return Radius{value, false};
}

// The tool's option checks name its flags (--fit-degree); a Python caller gives keywords (fit_degree).
std::string with_keywords(const std::string& message)
{
  const auto in_flag = [&](std::size_t i) {
    return i < message.size() && (std::islower(static_cast<unsigned char>(message[i])) || message[i] == '-');
  };
  std::string text;
  for (std::size_t i = 0; i < message.size();) {
    if (message.compare(i, 2, "--") == 0 && i + 2 < message.size() &&
        std::islower(static_cast<unsigned char>(message[i + 2])))
    {
      for (i += 2; in_flag(i); ++i)
        text += message[i] == '-' ? '_' : message[i];
    } else {
      text += message[i++];
    }
  }
  return text;
}

Options options(const Method* method, std::optional<int> rings, const py::object& radius, std::optional<int> order,
                std::optional<int> fit_degree, std::optional<int> degree, std::optional<int> monge_degree, int threads,
                bool tetrahedral)
{
  check_range(rings, "rings", Setting::rings);
  check_range(order, "order", Setting::extrapolation_order);
  check_range(fit_degree, "fit_degree", Setting::fit_degree);
  check_range(degree, "degree", Setting::jet_degree);
  check_range(monge_degree, "monge_degree", Setting::monge_degree);
  Options o;
  o.method = method;
  o.rings = rings;
  o.radius = radius_of(radius);
  if (const auto text = auto_radius_text(radius))
    o.radius_range = parse_radius_range("radius", *text);
  o.order = order;
  o.fit_degree = fit_degree;
  o.degree = degree;
  o.monge_degree = monge_degree;
  o.threads = thread_count(threads);
  o.tetrahedral = tetrahedral;
  try {
    check_options(o);
  } catch (const Tool_error& e) {
    refuse(with_keywords(one_line(e.what())));
  }
  return o;
}

// The lines the soup repair wrote, without the tool's prefix.
std::vector<std::string> note_lines(const std::string& text)
{
  const std::string prefix = "curvature: note: ";
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line.compare(0, prefix.size(), prefix) == 0 ? line.substr(prefix.size()) : line);
  return lines;
}

// The tool's mesh of the arrays (repaired as it repairs a file); the copies of the arrays
// are freed before the estimation. The repair swaps std::cerr's buffer while CGAL works:
// under the GIL, one call at a time.
Mesh mesh_of(const Float_array& points, const py::handle& faces, std::vector<V>& file_to_mesh, std::ostream& notes)
{
  const std::size_t n = static_cast<std::size_t>(points.shape(0));
  Soup soup;
  {
    const Index_rows polygons = index_array(faces, "faces", 0, n); // freed before the mesh is built
    soup = soup_of(points.data(), n, polygons.indices.data(), polygons.rows(), polygons.columns);
  }
  return build_mesh(soup, file_to_mesh, notes);
}

const Method* method_named(const std::string& name)
{
  const Method* method = find_method(name);
  if (!method) {
    std::string names;
    for (const Method& m : methods())
      names += std::string(names.empty() ? "" : ", ") + m.name;
    refuse("unknown method '" + name + "' (expected one of " + names + ")");
  }
  return method;
}

py::tuple mesh_curvatures(const py::handle& vertices, const py::handle& faces, const std::string& method_name,
                          std::optional<int> rings, const py::object& radius, std::optional<int> order,
                          std::optional<int> fit_degree, std::optional<int> degree, std::optional<int> monge_degree,
                          const py::object& normals, int threads)
{
  const Options o =
    options(method_named(method_name), rings, radius, order, fit_degree, degree, monge_degree, threads, false);

  const Float_array points = real_array(vertices, "vertices", 3);
  const std::size_t n = static_cast<std::size_t>(points.shape(0));
  std::ostringstream notes;
  std::vector<V> file_to_mesh;
  Mesh mesh = mesh_of(points, faces, file_to_mesh, notes);
  const std::vector<std::string> repairs = note_lines(notes.str());
  std::optional<Normal_map> given_normals;
  if (!normals.is_none()) {
    const Float_array values = real_array(normals, "normals", 3);
    if (static_cast<std::size_t>(values.shape(0)) != n)
      refuse("normals must have a row per vertex (" + std::to_string(n) + "), got " + std::to_string(values.shape(0)));
    bool repaired = !repairs.empty() || num_vertices(mesh) != n;
    for (std::size_t i = 0; i < n; ++i)
      repaired = repaired || file_to_mesh[i] != V(Mesh::size_type(i));
    if (repaired)
      refuse("normals are taken only for a mesh that needs no repair, and this one does" +
             (repairs.empty() ? std::string() : ": " + repairs.front()));
    given_normals = mesh.add_property_map<V, Kernel::Vector_3>("v:ce_python_normals").first;
    for (std::size_t i = 0; i < n; ++i)
      (*given_normals)[file_to_mesh[i]] = Kernel::Vector_3(values.at(i, 0), values.at(i, 1), values.at(i, 2));
  }

  auto k_max = new_array(n), k_min = new_array(n), mean = new_array(n), gaussian = new_array(n);
  auto d_max = new_array(n, 3), d_min = new_array(n, 3);
  py::array_t<std::uint8_t> status(static_cast<py::ssize_t>(n));
  Surface_outputs out{k_max.mutable_data(), k_min.mutable_data(), mean.mutable_data(),  gaussian.mutable_data(),
                      d_max.mutable_data(), d_min.mutable_data(), status.mutable_data()};
  auto reach = new_array(n);
  out.reach = reach.mutable_data();
  auto radius_out = new_array(o.radius_range ? n : 0), noise_out = new_array(o.radius_range ? n : 0);
  if (o.radius_range) {
    out.radius = radius_out.mutable_data();
    out.noise = noise_out.mutable_data();
  }
  {
    py::gil_scoped_release release;
    write_rows(estimate(o, mesh, std::move(file_to_mesh), given_normals), out);
  }
  const py::object selection = o.radius_range ? py::object(py::make_tuple(radius_out, noise_out)) : py::none();
  return py::make_tuple(k_max, k_min, mean, gaussian, d_max, d_min, status, repairs, selection, reach);
}

// The library's neighborhood_reach of a method of mesh_curvatures with these settings (an absolute radius):
// (rings, distance, grown distance).
py::tuple neighborhood_reach(const std::string& method_name, std::optional<int> rings, const py::object& radius,
                             std::optional<int> order, std::optional<int> fit_degree, std::optional<int> degree,
                             std::optional<int> monge_degree)
{
  const Options o =
    options(method_named(method_name), rings, radius, order, fit_degree, degree, monge_degree, 1, false);
  if (o.radius_range || (o.radius && o.radius->in_mean_edges))
    refuse("neighborhood_reach takes an absolute radius, got " + py::repr(radius).cast<std::string>());
  Settings settings = settings_of(o);
  if (o.radius)
    settings.ball_radius = o.radius->value;
  try {
    const CE::Neighborhood_reach r = reach(*o.method, settings);
    return py::make_tuple(r.rings, r.distance, r.grown_distance);
  } catch (const std::invalid_argument& e) {
    refuse(e.what());
  }
}

py::tuple tetrahedral_curvatures(const py::handle& vertices, const py::handle& tetrahedra, const py::handle& scalars,
                                 std::optional<int> rings, const py::object& radius, std::optional<int> fit_degree,
                                 int threads)
{
  const Method* method = nullptr;
  for (const Method& m : methods())
    if (m.tetrahedral && !method)
      method = &m;
  const Options o = options(method, rings, radius, std::nullopt, fit_degree, std::nullopt, std::nullopt, threads, true);

  const Float_array points = real_array(vertices, "vertices", 3);
  const std::size_t n = static_cast<std::size_t>(points.shape(0));
  const Index_rows cells = index_array(tetrahedra, "tetrahedra", 4, n);
  const Float_array f = real_array(scalars, "scalars", 0);
  if (static_cast<std::size_t>(f.shape(0)) != n)
    refuse("scalars must have a value per vertex (" + std::to_string(n) + "), got " + std::to_string(f.shape(0)));
  Tetrahedral_input input;
  input.mesh.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    input.mesh.points.emplace_back(points.at(i, 0), points.at(i, 1), points.at(i, 2));
  input.mesh.cells.resize(cells.rows());
  for (std::size_t t = 0; t < cells.rows(); ++t)
    std::copy(cells.row(t), cells.row(t) + 4, input.mesh.cells[t].begin());
  if (const auto same = same_tetrahedra(input.mesh.cells))
    refuse("tetrahedra rows " + std::to_string(same->first) + " and " + std::to_string(same->second) +
           " have the same four vertices");
  if (const auto flat = orient_tetrahedra(input.mesh))
    refuse("tetrahedra row " + std::to_string(*flat) + " has zero volume (or repeats a vertex)");
  input.scalars.assign(f.data(), f.data() + n);

  auto k_1 = new_array(n), k_2 = new_array(n), k_3 = new_array(n), mean = new_array(n), gaussian = new_array(n);
  py::array_t<std::uint8_t> status(static_cast<py::ssize_t>(n));
  double* const out[] = {k_1.mutable_data(), k_2.mutable_data(), k_3.mutable_data(), mean.mutable_data(),
                         gaussian.mutable_data()};
  std::uint8_t* const out_status = status.mutable_data();
  {
    py::gil_scoped_release release;
    const Tetrahedral_estimates e = estimate_tetrahedral(o, input);
    for (std::size_t i = 0; i < n; ++i) {
      const auto values = e.rows[i].values();
      for (std::size_t c = 0; c < values.size(); ++c)
        out[c][i] = values[c];
      out_status[i] = static_cast<std::uint8_t>(e.rows[i].status);
    }
  }
  return py::make_tuple(k_1, k_2, k_3, mean, gaussian, status);
}

} // namespace

} // namespace ce_python

PYBIND11_MODULE(_core, m)
{
  namespace py = pybind11;
  using namespace ce_python;
  m.doc() = "The C++ core of curvature_estimation; use the functions of the package, which name the outputs.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const ce_tool::Tool_error& e) {
      PyErr_SetString(PyExc_ValueError, ce_tool::one_line(e.what()).c_str());
    }
  });

  py::dict status;
  for (const auto s : {CE::Estimation_status::ok, CE::Estimation_status::widened, CE::Estimation_status::not_estimable,
                       CE::Estimation_status::fallback})
    status[ce_tool::status_name(s)] = static_cast<int>(s);
  m.attr("STATUS") = status;
  py::list names;
  for (const ce_tool::Method& method : ce_tool::methods())
    names.append(method.name);
  m.attr("METHODS") = names;

  m.def("mesh_curvatures", &mesh_curvatures, py::arg("vertices"), py::arg("faces"), py::arg("method"), py::arg("rings"),
        py::arg("radius"), py::arg("order"), py::arg("fit_degree"), py::arg("degree"), py::arg("monge_degree"),
        py::arg("normals"), py::arg("threads"));
  m.def("neighborhood_reach", &neighborhood_reach, py::arg("method"), py::arg("rings"), py::arg("radius"),
        py::arg("order"), py::arg("fit_degree"), py::arg("degree"), py::arg("monge_degree"));
  m.def("point_set_reach", &point_set_reach, py::arg("number_of_neighbors"), py::arg("neighbor_radius"),
        py::arg("fit_degree"));
  m.def("tetrahedral_curvatures", &tetrahedral_curvatures, py::arg("vertices"), py::arg("tetrahedra"),
        py::arg("scalars"), py::arg("rings"), py::arg("radius"), py::arg("fit_degree"), py::arg("threads"));
  m.def("point_set_curvatures", &point_set_curvatures, py::arg("points"), py::arg("number_of_neighbors"),
        py::arg("neighbor_radius"), py::arg("radius"), py::arg("fit_degree"), py::arg("normals"),
        py::arg("unsigned_curvatures"), py::arg("threads"));
}
