// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the input path of the `curvature` tool: the bytes are an
// input file, the first byte picks its format (.off .ply .obj .stl .mesh .xyz .pwn).
// For .mesh, the bytes up to the first NUL are the .mesh and the bytes after it the
// .sol beside it (no NUL: no .sol). The tool's reader, validation, soup repair and
// the paraboloid fit (surface or hypersurface) run on it, or, where the file is a
// point set (.xyz, .pwn, a PLY or OFF without faces), its point-set reader and the
// point-set fit. A Tool_error is the
// expected outcome for bad input; anything else (crash, sanitizer report, other
// exception, hang) is a finding.
//   cmake -DCMAKE_CXX_COMPILER=clang++ -DCE_BUILD_FUZZERS=ON ... && ./fuzz_tool_input -runs=N
// scripts/run_fuzz.sh runs it briefly over tools/fuzz_seeds/ (one seed per format).
#include "point_set_estimation.h"
#include "point_set_input.h"
#include "soup_repair.h"
#include "surface_estimation.h"
#include "surface_input.h"
#include "tetrahedral.h"
#include "tool_error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace ce_tool;

namespace {

void write_bytes(const std::string& path, const std::uint8_t* data, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

// Rows: one per vertex of the file; not estimable rows are NaN.
template <typename Rows>
void check_rows(const Rows& rows, std::size_t vertices)
{
  if (rows.size() != vertices)
    __builtin_trap();
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].status == CE::Estimation_status::not_estimable && !std::isnan(rows[i].mean))
      __builtin_trap();
}

void run_surface_input(const std::string& path)
{
  Options o;
  o.threads = 1;
  if (const std::optional<Point_set_input> points = read_point_set_input(path)) {
    check_rows(estimate_point_set(o, *points), points->points.size());
    return;
  }
  const Soup soup = read_input(path);
  std::vector<V> file_to_mesh;
  Silence_cerr silence; // repair notes
  Mesh mesh = build_mesh(soup, file_to_mesh);
  check_rows(estimate(o, mesh, std::move(file_to_mesh)), soup.points.size());
}

void run_tetrahedral_input(const std::string& path)
{
  Options o;
  o.threads = 1;
  const Tetrahedral_input input = read_tetrahedral_input(path, "");
  check_rows(estimate_tetrahedral(o, input).rows, input.mesh.points.size());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1 || size > 1 << 16)
    return 0;
  static const char* const extensions[] = {".off", ".ply", ".obj", ".stl", ".mesh", ".xyz", ".pwn"};
  const bool tetrahedral = data[0] % 7 == 4;
  const std::string base = "/tmp/ce_fuzz_tool_input_" + std::to_string(::getpid());
  const std::string path = base + extensions[data[0] % 7];
  const std::uint8_t* const first = data + 1;
  const std::uint8_t* const last = data + size;
  const std::uint8_t* const nul = tetrahedral ? std::find(first, last, std::uint8_t(0)) : last;
  write_bytes(path, first, std::size_t(nul - first));
  if (nul != last)
    write_bytes(base + ".sol", nul + 1, std::size_t(last - nul - 1));
  try {
    if (tetrahedral)
      run_tetrahedral_input(path);
    else
      run_surface_input(path);
  } catch (const Tool_error&) {
  }
  std::remove(path.c_str());
  std::remove((base + ".sol").c_str());
  return 0;
}
