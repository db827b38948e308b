// SPDX-License-Identifier: GPL-3.0-or-later
// The C++ peer of the Python call curvature_estimation.mesh_curvatures(V, F, METHOD,
// threads=THREADS), for benchmark/python_overhead.py: from the same arrays (raw float64
// vertices and int64 faces of COLUMNS indices, as numpy's tofile writes them), the same
// work without Python: the tool's soup of the arrays (python/src/surface_rows.h), its
// mesh (soup_repair.h: the repair check, and the repair where needed), its estimation
// (the registry's run) and the rows into freshly allocated output arrays. The files are
// read before the clock starts. Output, a line per call:
//   seconds S checksum C
// C: the XOR of the bits of k_max, k_min, mean and gaussian, which the script compares
// with the Python call's.
//
//   python_overhead_peer VERTICES FACES COLUMNS METHOD THREADS [CALLS]   (CALLS: 3)
#include "surface_rows.h"

#include "command_line.h"
#include "soup_repair.h"
#include "surface_estimation.h"
#include "tool_error.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace ce_tool;

template <typename T>
std::vector<T> read_raw(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    fail("cannot read " + path);
  const auto bytes = static_cast<std::size_t>(in.tellg());
  std::vector<T> values(bytes / sizeof(T));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(T)));
  return values;
}

std::uint64_t checksum(const std::unique_ptr<double[]>* arrays, std::size_t count, std::size_t n)
{
  std::uint64_t x = 0;
  for (std::size_t a = 0; a < count; ++a)
    for (std::size_t i = 0; i < n; ++i) {
      std::uint64_t bits;
      std::memcpy(&bits, &arrays[a][i], sizeof bits);
      x ^= bits;
    }
  return x;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 6 || argc > 7) {
    std::cerr << "usage: python_overhead_peer VERTICES FACES COLUMNS METHOD THREADS [CALLS]\n";
    return 2;
  }
  try {
    const std::vector<double> xyz = read_raw<double>(argv[1]);
    // int64 indices read as std::size_t: the same bits for the non-negative indices of the files.
    static_assert(sizeof(std::size_t) == sizeof(std::int64_t));
    const std::vector<std::size_t> indices = read_raw<std::size_t>(argv[2]);
    const std::size_t columns = std::stoul(argv[3]);
    const std::size_t n = xyz.size() / 3, m = indices.size() / columns;
    const int calls = argc == 7 ? std::stoi(argv[6]) : 3;
    for (int call = 0; call < calls; ++call) {
      std::unique_ptr<double[]> values[6];
      std::unique_ptr<std::uint8_t[]> status;
      const auto start = std::chrono::steady_clock::now();
      { // the mesh freed on the clock, as at the Python call's return
        Options o;
        o.method = find_method(argv[4]);
        if (!o.method)
          fail(std::string("unknown method ") + argv[4]);
        o.threads = std::stoi(argv[5]);
        check_options(o);
        std::ostringstream notes; // the Python call keeps the repair's notes for its warnings
        std::vector<V> file_to_mesh;
        Mesh mesh = build_mesh(ce_python::soup_of(xyz.data(), n, indices.data(), m, columns), file_to_mesh, notes);
        for (std::size_t a = 0; a < 6; ++a)
          values[a].reset(new double[a < 4 ? n : 3 * n]);
        status.reset(new std::uint8_t[n]);
        ce_python::write_rows(estimate(o, mesh, std::move(file_to_mesh)),
                              {values[0].get(), values[1].get(), values[2].get(), values[3].get(), values[4].get(),
                               values[5].get(), status.get()});
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("seconds %.6f checksum %llu\n", seconds, static_cast<unsigned long long>(checksum(values, 4, n)));
    }
  } catch (const std::exception& e) {
    std::cerr << "python_overhead_peer: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
