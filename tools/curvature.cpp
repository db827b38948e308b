// SPDX-License-Identifier: GPL-3.0-or-later
// curvature: estimates curvature at the vertices of a surface mesh file, at the
// points of a point set, or of the graph W = f(x, y, z) of a scalar field over a
// tetrahedral mesh.
//
//   curvature [options] INPUT
//     -m, --method  a method of the registry (registry.cpp; --help lists them)
//     -o, --output  FILE.csv | FILE.ply     (without it: print a summary only)
//     --rings N --radius R|Nx --order N --fit-degree D --degree D --monge-degree D --threads N
//     --color-by Q --scalars FILE.sol
//
// Rows of the CSV (and vertices of the PLY) are the vertices of the INPUT file, in
// the file's order, even when the polygon soup had to be repaired before it could
// become a mesh. Errors: one line on stderr, non-zero exit, no output file.
//
// main only: the parts are in this directory (command_line, surface_input,
// soup_repair, registry, surface_estimation, point_set_input, point_set_estimation,
// tetrahedral, writers, atomic_file, summary).
#include "atomic_file.h"
#include "command_line.h"
#include "input_files.h"
#include "point_set_estimation.h"
#include "point_set_input.h"
#include "soup_repair.h"
#include "summary.h"
#include "surface_estimation.h"
#include "surface_input.h"
#include "tetrahedral.h"
#include "tool_error.h"
#include "writers.h"

#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace ce_tool;

namespace {

int run_surface(const Options& o)
{
  const Soup soup = read_input(o.input);
  std::vector<V> file_to_mesh;
  Mesh mesh = build_mesh(soup, file_to_mesh);
  const Surface_estimates rows = estimate(o, mesh, std::move(file_to_mesh));
  if (!o.output.empty()) {
    Atomic_file out(o.output);
    if (lower_extension(o.output) == ".csv")
      write_surface_csv(out, rows);
    else
      write_ply(out, soup, rows, o.color_by);
    out.commit();
    return 0;
  }
  print_surface_summary(o, soup, mesh, rows);
  return 0;
}

int run_point_set(const Options& o, const Point_set_input& input)
{
  const Point_set_estimates estimates = estimate_point_set(o, input);
  if (!o.output.empty()) {
    Atomic_file out(o.output);
    if (lower_extension(o.output) == ".csv")
      write_point_set_csv(out, estimates);
    else
      write_point_set_ply(out, input.points, estimates, o.color_by);
    out.commit();
    return 0;
  }
  print_point_set_summary(o, input, estimates);
  return 0;
}

int run_tetrahedral(const Options& o)
{
  const Tetrahedral_input input = read_tetrahedral_input(o.input, o.scalars);
  const Tetrahedral_estimates estimates = estimate_tetrahedral(o, input);
  if (!o.output.empty()) { // CSV: parse_arguments refuses PLY for tetrahedral input
    Atomic_file out(o.output);
    write_tetrahedral_csv(out, estimates.rows);
    out.commit();
    return 0;
  }
  print_tetrahedral_summary(o, input, estimates);
  return 0;
}

int run(int argc, char** argv)
{
  std::optional<Options> parsed = parse_arguments(argc, argv);
  if (!parsed)
    return 0;
  if (parsed->tetrahedral)
    return run_tetrahedral(*parsed);
  const std::optional<Point_set_input> points = read_point_set_input(parsed->input);
  read_as(*parsed, points.has_value());
  return points ? run_point_set(*parsed, *points) : run_surface(*parsed);
}

} // namespace

int main(int argc, char** argv)
{
  try {
    return run(argc, argv);
  } catch (const Tool_error& e) {
    std::cerr << "curvature: error: " << one_line(e.what()) << '\n';
    return e.code;
  } catch (const std::bad_alloc&) {
    std::cerr << "curvature: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "curvature: error: " << one_line(e.what()) << '\n';
    return 1;
  } catch (...) {
    std::cerr << "curvature: error: unexpected failure\n";
    return 1;
  }
}
