// SPDX-License-Identifier: GPL-3.0-or-later
// What a program gets: one estimator of benchmark/estimators.h timed in a process that
// builds one mesh and calls the estimator a few times, as a user's program does, where
// bench_estimators times every estimator in one process that has built every input
// (and whose heap is warm). For each call, on one thread: the wall time and the minor
// page faults (getrusage), per vertex. scripts/make_report.sh runs it once per
// estimator and mesh, each in a fresh process; make_report.py puts it beside the warm
// figure.
//
//   ./build/benchmark/first_calls ESTIMATOR MESH [CALLS]     (CALLS defaults to 3)
//
// MESH as bench_estimators names it (grid_<n>, or a real mesh: bunny00, ...). Output, one
// line of JSON:
//   {"estimator": E, "mesh": M, "vertices": V, "ns_per_vertex": [...], "faults_per_vertex": [...]}
#include "estimators.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

void print_list(const char* key, const std::vector<double>& values)
{
  std::cout << ", \"" << key << "\": [";
  for (std::size_t i = 0; i < values.size(); ++i)
    std::cout << (i ? ", " : "") << values[i];
  std::cout << ']';
}

} // namespace

int main(int argc, char** argv)
{
  using namespace ce_bench;
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: first_calls ESTIMATOR MESH [CALLS]\n";
    return 2;
  }
  try {
    const Estimator& e = estimator(argv[1]);
    const int calls = argc == 4 ? std::stoi(argv[3]) : 3;
    Mesh mesh = speed_input(argv[2]);
    const double h = CE::mean_edge_length(mesh);
    const ce_tool::Outputs outputs = ce_tool::add_outputs(mesh, "v:");
    Normal_map given = mesh.add_property_map<vertex_descriptor, Kernel::Vector_3>("v:normal").first;
    if (e.given_normals)
      CE::estimate_vertex_normals(mesh, given); // not timed, as in bench_estimators

    const double n = double(num_vertices(mesh));
    std::vector<double> ns, faults;
    for (int call = 0; call < calls; ++call) {
      const long faults_before = minor_page_faults();
      const auto start = std::chrono::steady_clock::now();
      run(e, mesh, given, h, outputs, 1);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      faults.push_back(double(minor_page_faults() - faults_before) / n);
      ns.push_back(1e9 * seconds / n);
    }
    std::cout << "{\"estimator\": \"" << e.name << "\", \"mesh\": \"" << argv[2] << "\", \"vertices\": " << n;
    print_list("ns_per_vertex", ns);
    print_list("faults_per_vertex", faults);
    std::cout << "}\n";
  } catch (const std::exception& ex) {
    std::cerr << "first_calls: " << ex.what() << '\n';
    return 1;
  }
  return 0;
}
