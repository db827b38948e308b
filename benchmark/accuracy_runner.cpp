// SPDX-License-Identifier: GPL-3.0-or-later
// Accuracy of every estimator of benchmark/estimators.h against exact curvature,
// written as CSV for benchmark/make_report.py.
//
//   ./build/benchmark/accuracy_runner [--quick] [--out DIR] [--only PART]   (DIR defaults to .)
//   ./build/benchmark/accuracy_runner --list        (prints DIR/estimators.json, below)
//
// Surfaces: five of Hamann's graph functions on [-1,1]^2, a sphere, a torus and an
// ellipsoid, each as a regular mesh (grid, icosphere, parameter grid) and as an
// irregular one (jittered parameter domain, points moved up to 0.2 of the local
// spacing), the graphs also on Delaunay triangulations of random points; each on a
// refinement series of 4 sizes (2 with --quick), so that the report can fit observed orders.
// --only runs one part: accuracy, noise, bunny or scale (the files of each below; every
// part writes cgal_version.txt and estimators.json).
//
// DIR/accuracy.csv, one row per surface x mesh x size x estimator x region x quantity:
//   surface,mesh,level,vertices,h,estimator,region,quantity,rms,max,count,not_estimable
// h is the mean edge length; region is `all` or `interior` (graphs: the vertices with
// |x|, |y| <= 0.8, away from the one-sided stencils of the boundary, a fixed part of
// the domain as h -> 0; closed surfaces: all vertices); quantity is k_max, k_min, H or
// K (only those the estimator gives: CGAL's discrete operators give H or K alone);
// rms and max are over the `count` vertices of the region that have an estimate;
// `not_estimable` counts the region's vertices without one (left out of the errors).
// The estimator `paraboloid_given_normals` is given the EXACT normals here: it shows
// what the fit does when the normals are not the limiting factor.
//
// DIR/noise_radius.csv, the report's noise section: the noisy ellipsoid of
// test/common/noisy_meshes.h (10,242 vertices; 2,562 with --quick), seeds 1, 2 and 3, and
// every estimator of ball_estimators() at radii of 1, 2, 3, 4, 6 and 8 mean edge lengths
// h (of the noisy mesh); one row per estimator x seed x radius:
//   estimator,seed,vertices,h,sigma,radius_edges,ball_vertices,H_rms,H_max,K_rms,widened,ns_per_vertex
// sigma is the noise's standard deviation; ball_vertices the mean number of vertices in
// the balls of that radius (the connected part of the mesh in the ball, the center
// included) before any widening, `widened` the number of vertices whose estimate is
// `widened`; ns_per_vertex the time of the call on one thread (Sequential_tag). The
// default paraboloid fit (1-ring) and the Gauss map are there too, for reference, with
// radius_edges and ball_vertices empty.
//
// DIR/scale_selection.csv, the report's scale-selection section: the noisy family of
// test_scale_selection (noisy_meshes.h: ellipsoid, torus and Delaunay mesh, noise of 1, 5
// and 15% of the mean edge length h or varying from 0 to 15%), interior H RMS of the
// paraboloid fit (degree 2), jet fitting (d = 2) and, built against CGAL 6, ICC over balls
// of 1 to 16 h (steps of 2^(1/2)), and of the first two with ball_radius_range(1 h, 16 h);
// one row per mesh x estimator x radius, all threads, the same meshes with --quick:
//   mesh,vertices,h,estimator,radius_edges,H_rms,median_radius_edges,median_noise_ratio
// radius_edges is empty on the rows of the selection, which give the median over the
// interior vertices of the radius chosen (in h) and of the noise estimated over the noise
// added (where some was added); those two are empty on the fixed rows.
// DIR/bunny_scale_radius.csv and DIR/bunny_scale_noise.csv: x,y,z of bunny00 and the radius
// and the noise (in mean edge lengths of the mesh) that the default paraboloid fit with
// ball_radius_range(1 h, 16 h) gives on the scan (`scan`) and on the scan with Gaussian
// noise of 0.1 h added in each coordinate (seed 1, `noisy`); and DIR/bunny_faces.csv (below).
// DIR/bunny_mean_curvature.csv (x,y,z and one column of H per estimator that gives H),
// DIR/bunny_ball_mean_curvature.csv (x,y,z and H of the default paraboloid fit over its
// 1-ring, `paraboloid`, and over balls of 2 and 6 mean edge lengths, `ball_2h` and
// `ball_6h`) and DIR/bunny_faces.csv (three vertex indices per row) for the report's pictures.
// DIR/cgal_version.txt: the CGAL this runner was compiled against (CGAL_VERSION_STR).
// DIR/estimators.json: the estimators in report order, with their labels (and those of the
// noise section), for make_report.py (write_estimators_json in estimators.h).
#include "estimators.h"

#include "estimator_runs.h"
#include "noisy_meshes.h"
#include "test_surfaces.h"

#include <CGAL/Curvature_estimation/internal/rings.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using namespace ce_bench;
// Results do not depend on the threads (the estimators guarantee it); all cores are just faster.
constexpr int all_threads = 0;

// Runs `e` with every output requested: its estimates in vertex order.
ce_test::Estimates<Kernel> estimates(const Estimator& e, const Mesh& mesh, Normal_map given_normals, double h,
                                     int threads)
{
  return ce_test::run_with_all_outputs<Kernel>(
    mesh, [&](const Mesh& m, const auto& np) { run(e, m, given_normals, h, outputs_of(m, np), threads); },
    CE::parameters::default_values());
}

struct Case
{
  std::string surface, mesh; // mesh: regular, jittered or delaunay
  int level;                 // 0 = coarsest of the series
  ce_test::Soup soup;
  std::vector<ce_test::Exact_curvature> exact;
  std::vector<bool> interior;
};

// A refinement series: makes the case of level `level` (0 .. levels-1).
struct Series
{
  std::string surface, mesh;
  std::function<Case(int level)> make;
};

constexpr double jitter = 0.2;

Case make_case(const std::string& surface, const std::string& mesh, int level, ce_test::Soup soup,
               std::vector<ce_test::Exact_curvature> exact, std::function<bool(const Eigen::Vector2d&)> is_interior)
{
  Case c{surface, mesh, level, std::move(soup), std::move(exact), {}};
  for (const Eigen::Vector2d& p : c.soup.params)
    c.interior.push_back(is_interior(p));
  return c;
}

std::vector<Series> all_series()
{
  std::vector<Series> series;
  const auto everywhere = [](const Eigen::Vector2d&) { return true; };
  const auto inside_graph = [](const Eigen::Vector2d& p) { return std::abs(p.x()) <= 0.8 && std::abs(p.y()) <= 0.8; };

  // Hamann's Table 4.1 numbers (1-based): sphere cap, hyperboloid, monkey saddle, exponential, trigonometric.
  const std::vector<ce_test::Graph_function> functions = ce_test::hamann_table1_functions();
  for (int index : {3, 5, 6, 8, 9}) {
    const ce_test::Graph_function g = functions[static_cast<std::size_t>(index - 1)];
    const std::string name = "graph_" + g.name;
    // n = 17, 33, 65, 129 grid points per side: h halves at each level.
    const auto n_of = [](int level) { return static_cast<std::size_t>(16 << level) + 1; };
    series.push_back({name, "regular", [=](int l) {
                        ce_test::Soup s = ce_test::grid_graph_soup(g, n_of(l));
                        auto exact = ce_test::graph_curvatures(g, s);
                        return make_case(name, "regular", l, std::move(s), std::move(exact), inside_graph);
                      }});
    series.push_back({name, "jittered", [=](int l) {
                        ce_test::Soup s = ce_test::jittered_grid_graph_soup(g, n_of(l), -1.0, 1.0, jitter, 7);
                        auto exact = ce_test::graph_curvatures(g, s);
                        return make_case(name, "jittered", l, std::move(s), std::move(exact), inside_graph);
                      }});
    series.push_back({name, "delaunay", [=](int l) {
                        const std::size_t n = n_of(l);
                        ce_test::Soup s = ce_test::delaunay_graph_soup(g, n * n, -1.0, 1.0, 7);
                        auto exact = ce_test::graph_curvatures(g, s);
                        return make_case(name, "delaunay", l, std::move(s), std::move(exact), inside_graph);
                      }});
  }

  // Closed surfaces have no boundary: every vertex is interior.
  // Sphere and ellipsoid: icosphere subdivisions 2..5 (162 .. 10242 vertices).
  const double a = 1.5, b = 1.0, c = 0.6;
  for (const bool irregular : {false, true}) {
    const std::string mesh = irregular ? "jittered" : "regular";
    const double j = irregular ? jitter : 0.0;
    series.push_back({"sphere", mesh, [=](int l) {
                        ce_test::Soup s = ce_test::ellipsoid_soup(1.0, 1.0, 1.0, unsigned(l + 2), j, 7);
                        auto exact = ce_test::sphere_curvatures(1.0, s);
                        return make_case("sphere", mesh, l, std::move(s), std::move(exact), everywhere);
                      }});
    series.push_back({"ellipsoid", mesh, [=](int l) {
                        ce_test::Soup s = ce_test::ellipsoid_soup(a, b, c, unsigned(l + 2), j, 7);
                        auto exact = ce_test::ellipsoid_curvatures(a, b, c, s);
                        return make_case("ellipsoid", mesh, l, std::move(s), std::move(exact), everywhere);
                      }});
    // Torus R = 3, r = 1 on 2k x k parameter grids, k = 12, 24, 48, 96.
    series.push_back({"torus", mesh, [=](int l) {
                        const std::size_t k = std::size_t(12) << l;
                        ce_test::Soup s = ce_test::torus_soup(3.0, 1.0, 2 * k, k, j, 7);
                        auto exact = ce_test::torus_curvatures(3.0, 1.0, s);
                        return make_case("torus", mesh, l, std::move(s), std::move(exact), everywhere);
                      }});
  }
  return series;
}

void write_rows(std::ostream& out, const Case& c, double h, const Estimator& estimator,
                const ce_test::Estimates<Kernel>& e)
{
  for (const bool interior_only : {false, true}) {
    std::size_t not_estimable = 0; // counted by `include`, which curvature_errors calls once per vertex
    const auto include = [&](std::size_t i) {
      if (interior_only && !c.interior[i])
        return false;
      if (e.status[i] == CE::Estimation_status::not_estimable) {
        ++not_estimable;
        return false;
      }
      return true;
    };
    const ce_test::Curvature_errors errors = ce_test::curvature_errors(e, c.exact, include);
    const std::tuple<const char*, unsigned, const ce_test::Error_accumulator*> quantities[] = {
      {"k_max", ce_tool::gives_principal, &errors.k_max},
      {"k_min", ce_tool::gives_principal, &errors.k_min},
      {"H", ce_tool::gives_H, &errors.mean},
      {"K", ce_tool::gives_K, &errors.gaussian}};
    for (const auto& [quantity, given_by, accumulator] : quantities) {
      if (!(estimator.quantities() & given_by))
        continue;
      const ce_test::Error_stats s = accumulator->stats();
      out << c.surface << ',' << c.mesh << ',' << c.level << ',' << c.soup.points.size() << ',' << h << ','
          << estimator.name << ',' << (interior_only ? "interior" : "all") << ',' << quantity << ',' << s.rms << ','
          << s.max << ',' << s.count << ',' << not_estimable << '\n';
    }
  }
}

// Opens `path` for CSV rows (numbers to 9 significant digits) and writes its header line.
std::ofstream csv_file(const std::string& path, const std::string& header)
{
  std::ofstream out(path);
  if (!(out << std::setprecision(9) << header << '\n'))
    throw std::runtime_error("cannot write " + path);
  return out;
}

void run_accuracy(bool quick, const std::string& path)
{
  std::ofstream out =
    csv_file(path, "surface,mesh,level,vertices,h,estimator,region,quantity,rms,max,count,not_estimable");
  const int levels = quick ? 2 : 4;
  for (const Series& series : all_series())
    for (int level = 0; level < levels; ++level) {
      const auto start = std::chrono::steady_clock::now();
      Case c = series.make(level);
      Mesh mesh = ce_test::to_mesh<Mesh>(c.soup);
      const double h = ce_test::mean_edge_length(c.soup);
      Normal_map exact_normals = ce_test::exact_normal_map<Kernel>(mesh, c.exact);
      for (const Estimator& e : estimators())
        write_rows(out, c, h, e, estimates(e, mesh, exact_normals, h, all_threads));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "accuracy: %-22s %-9s level %d: %7zu vertices, %6.2f s\n", c.surface.c_str(), c.mesh.c_str(),
                   level, c.soup.points.size(), seconds);
    }
}

// Runs `e` on one thread with every output requested: its estimates, and the wall time
// of the call in ns per vertex.
std::pair<ce_test::Estimates<Kernel>, double> timed_run(const Estimator& e, const Mesh& mesh, double h)
{
  double seconds = 0;
  ce_test::Estimates<Kernel> estimates = ce_test::run_with_all_outputs<Kernel>(
    mesh,
    [&](const Mesh& m, const auto& np) {
      const auto start = std::chrono::steady_clock::now();
      run(e, m, Normal_map(), h, outputs_of(m, np), 1); // no given normals read
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    },
    CE::parameters::default_values());
  return {std::move(estimates), 1e9 * seconds / double(mesh.number_of_vertices())};
}

// The mean number of vertices in the balls of radius `radius` of the vertices of `mesh`,
// gathered as the fits over a ball gather them, before they widen any.
double mean_ball_size(const Mesh& mesh, double radius)
{
  CE::internal::Ring_collector<Mesh> collector;
  std::size_t sum = 0;
  for (vertex_descriptor v : vertices(mesh)) {
    const Kernel::Point_3& center = mesh.point(v);
    collector.start(v, mesh);
    collector.grow_ball(mesh, radius * radius,
                        [&](vertex_descriptor w) { return CGAL::squared_distance(mesh.point(w), center); });
    sum += collector.ball_size();
  }
  return double(sum) / double(mesh.number_of_vertices());
}

// The error against the radius on the noisy ellipsoid: DIR/noise_radius.csv (see the top).
void run_noise(bool quick, const std::string& path)
{
  std::ofstream out = csv_file(
    path, "estimator,seed,vertices,h,sigma,radius_edges,ball_vertices,H_rms,H_max,K_rms,widened,ns_per_vertex");
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const auto start = std::chrono::steady_clock::now();
    const ce_test::Noisy_ellipsoid_soup noisy = ce_test::noisy_ellipsoid_soup(quick ? 4 : 5, seed);
    const Mesh mesh = ce_test::to_mesh<Mesh>(noisy.soup);
    const double h = CE::mean_edge_length(mesh);
    // radius_edges and ball_vertices as written: empty for the references.
    const auto write = [&](const char* name, const std::string& radius_edges, const std::string& ball_vertices,
                           const std::pair<ce_test::Estimates<Kernel>, double>& timed) {
      const ce_test::Curvature_errors errors = ce_test::curvature_errors(timed.first, noisy.exact);
      const ce_test::Error_stats H = errors.mean.stats();
      const auto widened =
        std::count(timed.first.status.begin(), timed.first.status.end(), CE::Estimation_status::widened);
      out << name << ',' << seed << ',' << mesh.number_of_vertices() << ',' << h << ',' << noisy.sigma << ','
          << radius_edges << ',' << ball_vertices << ',' << H.rms << ',' << H.max << ',' << errors.gaussian.stats().rms
          << ',' << widened << ',' << timed.second << '\n';
    };
    for (const char* reference : {"paraboloid", "gauss_map"})
      write(reference, "", "", timed_run(estimator(reference), mesh, h));
    for (const int edges : {1, 2, 3, 4, 6, 8}) {
      const std::string ball_vertices = std::to_string(mean_ball_size(mesh, edges * h));
      for (const Ball_estimator& b : ball_estimators())
        write(b.estimator.name.c_str(), std::to_string(edges), ball_vertices,
              timed_run(in_ball(b.estimator, edges), mesh, h));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "noise: ellipsoid, seed %u: %7zu vertices, %6.2f s\n", unsigned(seed),
                 std::size_t(mesh.number_of_vertices()), seconds);
  }
}

// The points (in vertex order) and triangles of `mesh`. A mesh read from a file has no
// removed elements: vertex indices are 0 .. n-1 in iteration order, the row numbers of
// the per-vertex CSV files.
ce_test::Soup soup_of(const Mesh& mesh)
{
  ce_test::Soup soup;
  for (vertex_descriptor v : vertices(mesh)) {
    const Kernel::Point_3& p = mesh.point(v);
    soup.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (Mesh::Face_index f : faces(mesh)) {
    std::array<std::size_t, 3> face{};
    std::size_t k = 0;
    for (vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) {
      if (k == 3)
        throw std::runtime_error("ce_bench::soup_of: a face that is not a triangle");
      face[k++] = std::size_t(v);
    }
    soup.faces.push_back(face);
  }
  return soup;
}

// Writes x,y,z and the columns named `names` (one value per vertex, in vertex order) of
// `mesh` to `path` as CSV.
void write_vertex_columns(const std::string& path, const Mesh& mesh, const std::vector<std::string>& names,
                          const std::vector<std::vector<double>>& columns)
{
  std::string header = "x,y,z";
  for (const std::string& name : names)
    header += ',' + name;
  std::ofstream out = csv_file(path, header);
  std::size_t i = 0;
  for (vertex_descriptor v : vertices(mesh)) {
    const Kernel::Point_3& p = mesh.point(v);
    out << p.x() << ',' << p.y() << ',' << p.z();
    for (const std::vector<double>& column : columns)
      out << ',' << column[i];
    out << '\n';
    ++i;
  }
  if (!out)
    throw std::runtime_error("cannot write " + path);
}

// The triangles of `mesh` (three vertex indices per row) to `path` as CSV, for the pictures.
void write_faces(const std::string& path, const Mesh& mesh)
{
  std::ofstream out = csv_file(path, "a,b,c");
  for (const auto& [a, b, c] : soup_of(mesh).faces)
    out << a << ',' << b << ',' << c << '\n';
  if (!out)
    throw std::runtime_error("cannot write " + path);
}

// Mean curvature of every estimator on the bunny, and of the default paraboloid fit over
// balls, for the report's pictures.
void run_bunny(const std::string& dir)
{
  Mesh mesh = read_real_mesh("bunny00");
  Normal_map normals = mesh.add_property_map<vertex_descriptor, Kernel::Vector_3>("v:given_normal").first;
  CE::estimate_vertex_normals(mesh, normals); // no exact normals on a scanned mesh: the default estimate
  const double h = CE::mean_edge_length(mesh);
  std::vector<std::string> names, ball_names;
  std::vector<std::vector<double>> columns, ball_columns;
  for (const Estimator& e : estimators())
    if (e.quantities() & ce_tool::gives_H) {
      names.push_back(e.name);
      columns.push_back(estimates(e, mesh, normals, h, all_threads).mean);
      if (e.name == "paraboloid") { // the default fit over its 1-ring, then over balls
        ball_names.push_back(names.back());
        ball_columns.push_back(columns.back());
      }
    }
  write_vertex_columns(dir + "/bunny_mean_curvature.csv", mesh, names, columns);

  for (const int edges : {2, 6}) {
    ball_names.push_back("ball_" + std::to_string(edges) + "h");
    ball_columns.push_back(estimates(in_ball(estimator("paraboloid"), edges), mesh, normals, h, all_threads).mean);
  }
  write_vertex_columns(dir + "/bunny_ball_mean_curvature.csv", mesh, ball_names, ball_columns);

  write_faces(dir + "/bunny_faces.csv", mesh);
}

// The radius range of the scale selection, in mean edge lengths: that of the tests.
constexpr double selection_max_edges = 16;

// H, and the radius and the noise in mean edge lengths h, of `e` (a method that reads
// ball_radius_range) with ball_radius_range(1 h, 16 h) on `mesh`, all threads.
struct Selection
{
  std::vector<double> mean, radius, noise;
};

Selection run_selection(const Estimator& e, Mesh& mesh, double h)
{
  auto radius = mesh.add_property_map<vertex_descriptor, double>("v:selected_radius").first;
  auto noise = mesh.add_property_map<vertex_descriptor, double>("v:selected_noise").first;
  ce_tool::Settings settings = e.settings;
  settings.radius_selection = ce_tool::Settings::Radius_selection{{h, selection_max_edges * h}, radius, noise};
  Selection s;
  s.mean =
    ce_test::run_with_all_outputs<Kernel>(
      mesh,
      [&](const Mesh& m, const auto& np) { ce_tool::run(*e.method, m, settings, outputs_of(m, np), all_threads); },
      CE::parameters::default_values())
      .mean;
  for (vertex_descriptor v : vertices(mesh)) {
    s.radius.push_back(radius[v] / h);
    s.noise.push_back(noise[v] / h);
  }
  mesh.remove_property_map(radius);
  mesh.remove_property_map(noise);
  return s;
}

// The median of `values` where `keep` holds.
double median_where(const std::vector<double>& values, const std::function<bool(std::size_t)>& keep)
{
  std::vector<double> kept;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (keep(i))
      kept.push_back(values[i]);
  if (kept.empty())
    return std::nan("");
  std::nth_element(kept.begin(), kept.begin() + kept.size() / 2, kept.end());
  return kept[kept.size() / 2];
}

// The scale selection against fixed balls on the noisy family: DIR/scale_selection.csv (see the top).
void run_scale_selection(const std::string& path)
{
  std::ofstream out =
    csv_file(path, "mesh,vertices,h,estimator,radius_edges,H_rms,median_radius_edges,median_noise_ratio");
  std::vector<const Ball_estimator*> compared; // ours (degree 2), jet fitting and ICC
  for (const Ball_estimator& b : ball_estimators())
    if (b.estimator.name == "paraboloid_ball" || b.estimator.name == "jet_d2_ball" || b.estimator.name == "icc_ball")
      compared.push_back(&b);
  for (const ce_test::Noisy_shape shape :
       {ce_test::Noisy_shape::ellipsoid, ce_test::Noisy_shape::torus, ce_test::Noisy_shape::delaunay})
    for (const double fraction : ce_test::noisy_family_fractions()) {
      const auto start = std::chrono::steady_clock::now();
      const ce_test::Noisy_family_soup family = ce_test::noisy_family_soup(shape, fraction);
      Mesh mesh = ce_test::to_mesh<Mesh>(family.soup);
      const double h = CE::mean_edge_length(mesh);
      const auto write = [&](const Ball_estimator& b, const std::string& radius_edges, const std::vector<double>& mean,
                             const std::string& medians) {
        out << family.name << ',' << mesh.number_of_vertices() << ',' << h << ',' << b.estimator.name << ','
            << radius_edges << ',' << ce_test::interior_rms(family, mean) << ',' << medians << '\n';
      };
      for (const Ball_estimator* b : compared) {
        for (const double edges : ce_test::noisy_family_radii_in_edges())
          write(*b, std::to_string(edges),
                estimates(in_ball(b->estimator, edges), mesh, Normal_map(), h, all_threads).mean, ",");
        if (!(b->estimator.method && b->estimator.method->reads_setting(ce_tool::Setting::ball_radius_range)))
          continue;
        const Selection s = run_selection(b->estimator, mesh, h);
        std::vector<double> noise_ratio;
        for (std::size_t i = 0; i < s.noise.size(); ++i)
          noise_ratio.push_back(s.noise[i] * h / family.sigma[i]);
        const double radius = median_where(s.radius, [&](std::size_t i) { return bool(family.interior[i]); });
        const double noise =
          median_where(noise_ratio, [&](std::size_t i) { return family.interior[i] && family.sigma[i] > 0; });
        write(*b, "", s.mean, std::to_string(radius) + ',' + std::to_string(noise));
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "scale selection: %-18s %7zu vertices, %6.2f s\n", family.name.c_str(),
                   std::size_t(mesh.number_of_vertices()), seconds);
    }
}

// The radius and the noise the scale selection gives on the bunny as scanned and with
// noise of 0.1 h added: DIR/bunny_scale_radius.csv and DIR/bunny_scale_noise.csv.
void run_bunny_scale_selection(const std::string& dir)
{
  Mesh scan = read_real_mesh("bunny00");
  Mesh noisy = scan;
  ce_test::Soup soup = soup_of(scan);
  ce_test::add_gaussian_noise(soup, 0.1, 1);
  std::size_t i = 0;
  for (vertex_descriptor v : vertices(noisy)) {
    noisy.point(v) = Kernel::Point_3(soup.points[i].x(), soup.points[i].y(), soup.points[i].z());
    ++i;
  }
  const Estimator& paraboloid = estimator("paraboloid");
  const Selection on_scan = run_selection(paraboloid, scan, CE::mean_edge_length(scan));
  const Selection on_noisy = run_selection(paraboloid, noisy, CE::mean_edge_length(noisy));
  write_vertex_columns(dir + "/bunny_scale_radius.csv", scan, {"scan", "noisy"}, {on_scan.radius, on_noisy.radius});
  write_vertex_columns(dir + "/bunny_scale_noise.csv", scan, {"scan", "noisy"}, {on_scan.noise, on_noisy.noise});
  write_faces(dir + "/bunny_faces.csv", scan);
}

} // namespace

int main(int argc, char** argv)
{
  bool quick = false;
  std::string dir = ".";
  const std::string parts[] = {"accuracy", "noise", "bunny", "scale"};
  std::string only; // empty: every part
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc)
      dir = argv[++i];
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc &&
             std::find(std::begin(parts), std::end(parts), std::string(argv[i + 1])) != std::end(parts))
      only = argv[++i];
    else if (std::strcmp(argv[i], "--list") == 0) {
      write_estimators_json(std::cout);
      return 0;
    } else {
      std::cerr << "usage: accuracy_runner [--quick] [--out DIR] [--only accuracy|noise|bunny|scale] | --list\n";
      return 2;
    }
  }
  try {
    std::ofstream version(dir + "/cgal_version.txt");
    if (!(version << CGAL_VERSION_STR << '\n'))
      throw std::runtime_error("cannot write " + dir + "/cgal_version.txt");
    std::ofstream list(dir + "/estimators.json");
    write_estimators_json(list);
    if (!list)
      throw std::runtime_error("cannot write " + dir + "/estimators.json");
    if (only.empty() || only == "accuracy")
      run_accuracy(quick, dir + "/accuracy.csv");
    if (only.empty() || only == "noise")
      run_noise(quick, dir + "/noise_radius.csv");
    if (only.empty() || only == "bunny")
      run_bunny(dir);
    if (only.empty() || only == "scale") {
      run_scale_selection(dir + "/scale_selection.csv");
      run_bunny_scale_selection(dir);
    }
  } catch (const std::exception& e) {
    std::cerr << "accuracy_runner: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
