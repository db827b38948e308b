// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of CGAL/Curvature_estimation/vertex_normals.h
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <gtest/gtest.h>

#include "test_surfaces.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace {

namespace CE = CGAL::Curvature_estimation;
using K = CGAL::Epick;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = Mesh::Vertex_index;
using Method = CE::Vertex_normal_method;
using Status = CE::Estimation_status;
using Vec3 = Eigen::Vector3d;

const Method face_methods[] = {Method::area_weighted, Method::angle_weighted, Method::centroid_weighted};
constexpr double pi = 3.14159265358979323846;

Vec3 to_eigen(const Vector& v) { return Vec3(v.x(), v.y(), v.z()); }
Vec3 to_eigen(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

// Angle between two vectors, robust near 0.
double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

// A small portable pseudo-random generator (same numbers on every platform).
struct Lcg
{
  std::uint64_t state;
  explicit Lcg(std::uint64_t seed)
      : state(seed)
  {}
  double uniform() // in [-1, 1)
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53) * 2. - 1.;
  }
};

struct Soup
{
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
};

Mesh to_mesh(const Soup& soup)
{
  Mesh m;
  std::vector<vertex_descriptor> vs;
  for (const Vec3& p : soup.points)
    vs.push_back(m.add_vertex(Point(p.x(), p.y(), p.z())));
  for (const auto& f : soup.faces) {
    std::vector<vertex_descriptor> fv;
    for (int i : f)
      fv.push_back(vs[i]);
    const auto fd = m.add_face(fv);
    EXPECT_NE(fd, Mesh::null_face()) << "test mesh construction failed";
  }
  return m;
}

// Icosphere of radius 1 with `levels` midpoint subdivisions; every vertex moved along the
// sphere by a random tangent displacement of up to `jitter` times the edge length.
Soup icosphere(int levels, double jitter)
{
  const ce_test::Soup sphere = ce_test::sphere_soup(1.0, static_cast<unsigned>(levels));
  Soup s;
  s.points = sphere.points;
  for (const auto& f : sphere.faces)
    s.faces.push_back({int(f[0]), int(f[1]), int(f[2])});
  const double h = 1.0515 / double(1 << levels); // edge length of the icosahedron / 2^levels
  Lcg rng(12345 + levels);
  for (Vec3& p : s.points) {
    const Vec3 d(rng.uniform(), rng.uniform(), rng.uniform());
    const Vec3 tangent = d - d.dot(p) * p;
    p = (p + jitter * h * tangent).normalized();
  }
  return s;
}

// n x n grid on [0,1]^2 with interior vertices jittered, triangulated with alternating
// diagonals; counter-clockwise seen from +z.
Soup jittered_grid(int n, double jitter)
{
  Soup s;
  Lcg rng(777);
  const double h = 1. / (n - 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Vec3 p(i * h, j * h, 0.);
      if (i > 0 && i < n - 1 && j > 0 && j < n - 1) {
        p.x() += jitter * h * rng.uniform();
        p.y() += jitter * h * rng.uniform();
      }
      s.points.push_back(p);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      if ((i + j) % 2 == 0) {
        s.faces.push_back({a, b, c});
        s.faces.push_back({a, c, d});
      } else {
        s.faces.push_back({a, b, d});
        s.faces.push_back({b, c, d});
      }
    }
  return s;
}

std::vector<Vec3> normals_of(Mesh& m, Method method)
{
  auto nmap = m.add_property_map<vertex_descriptor, Vector>("v:test_normal").first;
  CE::estimate_vertex_normals(m, nmap, CE::parameters::vertex_normal_method(method));
  std::vector<Vec3> out;
  for (vertex_descriptor v : vertices(m))
    out.push_back(to_eigen(get(nmap, v)));
  m.remove_property_map(nmap);
  return out;
}

// ---------------------------------------------------------------------------
// (a) closed convex mesh: outward, close to the radial normal, first-order convergence
// ---------------------------------------------------------------------------
TEST(VertexNormals, SphereOutwardAndConvergesAtLeastFirstOrder)
{
  // Jittered icospheres (irregular stars, so that symmetric cancellations do not hide the
  // order): edge length h ~ 0.26, 0.13, 0.066. Measured: RMS errors drop by a factor ~0.45-0.5
  // per halving of h for all three methods (first order).
  const int levels[] = {2, 3, 4};
  for (Method method : face_methods) {
    std::vector<double> max_errors, rms_errors;
    for (int level : levels) {
      Mesh m = to_mesh(icosphere(level, 0.2));
      const std::vector<Vec3> n = normals_of(m, method);
      double max_error = 0., sum_squares = 0.;
      std::size_t i = 0;
      for (vertex_descriptor v : vertices(m)) {
        const Vec3 radial = to_eigen(m.point(v)).normalized();
        ASSERT_TRUE(n[i].allFinite());
        EXPECT_NEAR(n[i].norm(), 1., 1e-14);
        EXPECT_GT(n[i].dot(radial), 0.9) << "normal not outward at level " << level;
        const double e = angle_between(n[i], radial);
        max_error = std::max(max_error, e);
        sum_squares += e * e;
        ++i;
      }
      max_errors.push_back(max_error);
      rms_errors.push_back(std::sqrt(sum_squares / double(i)));
    }
    SCOPED_TRACE(testing::Message() << "method " << int(method) << ", max angle errors " << max_errors[0] << " "
                                    << max_errors[1] << " " << max_errors[2] << ", RMS " << rms_errors[0] << " "
                                    << rms_errors[1] << " " << rms_errors[2]);
    EXPECT_LT(max_errors[0], 0.15);
    // Halving the edge length must about halve the error (first order): 0.6 leaves room for noise.
    EXPECT_LT(rms_errors[1], 0.6 * rms_errors[0]);
    EXPECT_LT(rms_errors[2], 0.6 * rms_errors[1]);
    // The worst vertex improves too (its shape varies with the jitter, so a looser bound).
    EXPECT_LT(max_errors[2], 0.6 * max_errors[0]);
  }
}

// ---------------------------------------------------------------------------
// (b) tilted plane: exact for every method, also at border vertices; reads the given
// vertex_point_map (the mesh's own points are flat) and geom_traits
// ---------------------------------------------------------------------------
TEST(VertexNormals, TiltedPlaneIsExactForEveryMethod)
{
  const Soup grid = jittered_grid(9, 0.3);
  Mesh m = to_mesh(grid); // z = 0
  auto tilted = m.add_property_map<vertex_descriptor, Point>("v:tilted").first;
  const double a = 0.7, b = -1.3, c = 0.25;
  for (vertex_descriptor v : vertices(m)) {
    const Point& p = m.point(v);
    put(tilted, v, Point(p.x(), p.y(), a * p.x() + b * p.y() + c));
  }
  const Vec3 exact = Vec3(-a, -b, 1.).normalized();

  for (Method method : face_methods) {
    auto nmap = m.add_property_map<vertex_descriptor, Vector>("v:n").first;
    auto smap = m.add_property_map<vertex_descriptor, Status>("v:s", Status::widened).first;
    // our parameters and CGAL's chained in mixed order
    CE::estimate_vertex_normals(m, nmap,
                                CE::parameters::vertex_point_map(tilted)
                                  .vertex_normal_method(method)
                                  .geom_traits(K())
                                  .vertex_estimation_status_map(smap));
    for (vertex_descriptor v : vertices(m)) {
      EXPECT_EQ(get(smap, v), Status::ok);
      EXPECT_LT((to_eigen(get(nmap, v)) - exact).cwiseAbs().maxCoeff(), 1e-12)
        << "method " << int(method) << " vertex " << v;
    }
    m.remove_property_map(nmap);
    m.remove_property_map(smap);
  }
}

// ---------------------------------------------------------------------------
// (c) irregular star: each method equals its own weighted sum computed here from the
// geometry, and the three methods differ
// ---------------------------------------------------------------------------
struct Star
{
  Vec3 center{0.1, -0.2, 0.3};
  // ring around the centre, counter-clockwise seen from +z, unequal angles, radii, heights
  std::vector<Vec3> ring{{1.0, 0.1, 0.2}, {0.4, 0.9, -0.1}, {-0.7, 1.6, 0.5}, {-1.1, -0.2, 0.0}, {0.3, -0.5, 0.4}};
  Mesh mesh;
  vertex_descriptor c;

  Star()
  {
    c = mesh.add_vertex(Point(center.x(), center.y(), center.z()));
    std::vector<vertex_descriptor> r;
    for (const Vec3& p : ring)
      r.push_back(mesh.add_vertex(Point(p.x(), p.y(), p.z())));
    for (std::size_t i = 0; i < r.size(); ++i)
      mesh.add_face(c, r[i], r[(i + 1) % r.size()]);
  }

  // the expected normal, from the closed-form weights (acos for the angle, explicit centroid)
  Vec3 expected(Method method) const
  {
    Vec3 sum = Vec3::Zero();
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec3 e1 = ring[i] - center, e2 = ring[(i + 1) % ring.size()] - center;
      const Vec3 unit_normal = e1.cross(e2).normalized();
      const double area = 0.5 * e1.cross(e2).norm();
      const double angle = std::acos(e1.dot(e2) / (e1.norm() * e2.norm()));
      const Vec3 centroid = (center + ring[i] + ring[(i + 1) % ring.size()]) / 3.;
      double w = 0.;
      switch (method) {
        case Method::area_weighted:
          w = area;
          break;
        case Method::angle_weighted:
          w = angle;
          break;
        case Method::centroid_weighted:
          w = 1. / (centroid - center).squaredNorm();
          break;
        default:
          ADD_FAILURE();
      }
      sum += w * unit_normal;
    }
    return sum.normalized();
  }
};

TEST(VertexNormals, IrregularStarMatchesHandWeightsAndMethodsDiffer)
{
  Star star;
  std::vector<Vec3> got;
  for (Method method : face_methods) {
    const Vec3 n = normals_of(star.mesh, method)[std::size_t(star.c)];
    const Vec3 e = star.expected(method);
    EXPECT_LT((n - e).norm(), 1e-12) << "method " << int(method);
    // the per-vertex kernel gives the same vector
    const Vec3 k = CE::internal::face_average_normal(star.c, star.mesh, get(CGAL::vertex_point, star.mesh), method);
    EXPECT_LT((k - e).norm(), 1e-12);
    got.push_back(n);
  }
  // the methods really weigh differently on this star
  EXPECT_GT(angle_between(got[0], got[1]), 1e-2);
  EXPECT_GT(angle_between(got[0], got[2]), 1e-2);
  EXPECT_GT(angle_between(got[1], got[2]), 1e-2);

  // the default method is quadric_fit
  auto default_map = star.mesh.add_property_map<vertex_descriptor, Vector>("v:default").first;
  auto fitted_map = star.mesh.add_property_map<vertex_descriptor, Vector>("v:fitted").first;
  CE::estimate_vertex_normals(star.mesh, default_map);
  CE::estimate_vertex_normals(star.mesh, fitted_map, CE::parameters::vertex_normal_method(Method::quadric_fit));
  EXPECT_EQ(to_eigen(get(default_map, star.c)), to_eigen(get(fitted_map, star.c)));
}

TEST(VertexNormals, ScaleInvariantOnTinyAndHugeMeshes)
{
  Star star;
  for (double scale : {1e-150, 1e150, 1e-300, 1e300}) {
    Mesh scaled = star.mesh;
    for (vertex_descriptor v : vertices(scaled)) {
      const Point p = scaled.point(v);
      scaled.point(v) = Point(scale * p.x(), scale * p.y(), scale * p.z());
    }
    for (Method method : face_methods) {
      const Vec3 n = normals_of(scaled, method)[std::size_t(star.c)];
      EXPECT_LT((n - star.expected(method)).norm(), 1e-12) << "scale " << scale << " method " << int(method);
    }
  }
}

// ---------------------------------------------------------------------------
// (d) polygon faces
// ---------------------------------------------------------------------------
TEST(VertexNormals, QuadBoxCornersHaveTheHandComputedNormals)
{
  // box [0,1] x [0,2] x [0,3] made of 6 quads, oriented outward
  const double X = 1., Y = 2., Z = 3.;
  Soup box;
  for (int i = 0; i < 8; ++i)
    box.points.push_back(Vec3((i & 1) ? X : 0., (i & 2) ? Y : 0., (i & 4) ? Z : 0.));
  box.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  Mesh m = to_mesh(box);

  // at the corner (X,Y,Z) the outward face normals are +x, +y, +z, i.e. by symmetry the
  // corner normal is (s_x wx, s_y wy, s_z wz) with weights of the faces x = X, y = Y, z = Z
  const Vec3 area(Y * Z, X * Z, X * Y);                                                  // face areas
  const Vec3 angle(pi / 2, pi / 2, pi / 2);                                              // right angles
  const Vec3 centroid(4. / (Y * Y + Z * Z), 4. / (X * X + Z * Z), 4. / (X * X + Y * Y)); // 1/|G-v|^2
  const Vec3 expected[] = {area.normalized(), angle.normalized(), centroid.normalized()};

  for (int k = 0; k < 3; ++k) {
    const std::vector<Vec3> n = normals_of(m, face_methods[k]);
    std::size_t i = 0;
    for (vertex_descriptor v : vertices(m)) {
      const Point& p = m.point(v);
      const Vec3 sign(p.x() > 0 ? 1. : -1., p.y() > 0 ? 1. : -1., p.z() > 0 ? 1. : -1.);
      EXPECT_LT((n[i] - sign.cwiseProduct(expected[k])).norm(), 1e-14) << "method " << k << " vertex " << v;
      ++i;
    }
  }
}

TEST(VertexNormals, ReflexVertexOfNonConvexPolygonGetsItsLargeAngle)
{
  // an L-shaped hexagon in z = 0 (reflex vertex r = (1,1,0), vertex 3, interior angle 3 pi / 2)
  // and a triangle hanging from its edge (2,1)-(1,1) in the plane y = 1
  Soup s;
  s.points = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2.5, 0}, {1.5, 1, -1}};
  s.faces = {{0, 1, 2, 3, 4, 5}, {3, 2, 6}};
  Mesh m = to_mesh(s);

  const Vec3 n_hexagon(0, 0, 1);
  const Vec3 e1(1, 0, 0), e2(0.5, 0, -1);            // edges of the triangle at r
  const Vec3 n_triangle = e1.cross(e2).normalized(); // (0, 1, 0)
  const double triangle_angle = std::acos(e1.dot(e2) / e2.norm());
  const double triangle_area = 0.5 * e1.cross(e2).norm();
  const double hexagon_area = 3.25; // shoelace: (2 + 1 + 1 + 2.5) / 2

  const Vec3 exp_angle = (1.5 * pi * n_hexagon + triangle_angle * n_triangle).normalized();
  const Vec3 exp_area = (hexagon_area * n_hexagon + triangle_area * n_triangle).normalized();
  const Vec3 g_hex(6. / 6., 6.5 / 6., 0.); // mean of the hexagon's vertices
  const Vec3 g_tri = (Vec3(1, 1, 0) + Vec3(2, 1, 0) + Vec3(1.5, 1, -1)) / 3.;
  const Vec3 rp(1, 1, 0);
  const Vec3 exp_centroid =
    (n_hexagon / (g_hex - rp).squaredNorm() + n_triangle / (g_tri - rp).squaredNorm()).normalized();

  EXPECT_LT((normals_of(m, Method::angle_weighted)[3] - exp_angle).norm(), 1e-14);
  EXPECT_LT((normals_of(m, Method::area_weighted)[3] - exp_area).norm(), 1e-14);
  EXPECT_LT((normals_of(m, Method::centroid_weighted)[3] - exp_centroid).norm(), 1e-14);

  // With (0, 2) instead of (0, 2.5) the hexagon's centroid is r itself: an infinite centroid
  // weight, so the hexagon's normal alone (the limit as the centroid tends to r).
  m.point(vertex_descriptor(5)) = Point(0, 2, 0);
  EXPECT_EQ(normals_of(m, Method::centroid_weighted)[3], n_hexagon);
}

TEST(VertexNormals, TiltedQuadGridIsExact)
{
  // quads of a jittered grid on a plane: Newell's normal is exact for planar polygons
  const int n = 6;
  Soup s;
  Lcg rng(99);
  const Vec3 u(1., 0.2, -0.4), w(-0.3, 1., 0.5), o(0.3, -2., 7.);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      s.points.push_back(o + (i + 0.3 * rng.uniform()) * u + (j + 0.3 * rng.uniform()) * w);
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i)
      s.faces.push_back({j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i});
  Mesh m = to_mesh(s);
  const Vec3 exact = u.cross(w).normalized();
  for (Method method : face_methods)
    for (const Vec3& nv : normals_of(m, method))
      EXPECT_LT((nv - exact).cwiseAbs().maxCoeff(), 1e-12) << "method " << int(method);
}

// ---------------------------------------------------------------------------
// (e) isolated vertex and zero-area face
// ---------------------------------------------------------------------------
TEST(VertexNormals, IsolatedVertexIsNotEstimableAndZeroAreaFaceIsIgnored)
{
  Mesh m;
  const vertex_descriptor a = m.add_vertex(Point(0, 0, 0));
  const vertex_descriptor mid = m.add_vertex(Point(1, 0, 0));
  const vertex_descriptor b = m.add_vertex(Point(2, 0, 0));
  const vertex_descriptor t = m.add_vertex(Point(1, 1, 0));
  ASSERT_NE(m.add_face(a, mid, t), Mesh::null_face());
  ASSERT_NE(m.add_face(mid, b, t), Mesh::null_face());
  ASSERT_NE(m.add_face(b, mid, a), Mesh::null_face()); // zero area: a, mid, b are collinear
  const vertex_descriptor isolated = m.add_vertex(Point(5, 5, 5));

  for (Method method : face_methods) {
    auto nmap = m.add_property_map<vertex_descriptor, Vector>("v:n").first;
    auto smap = m.add_property_map<vertex_descriptor, Status>("v:s", Status::widened).first;
    CE::estimate_vertex_normals(m, nmap,
                                CE::parameters::vertex_estimation_status_map(smap).vertex_normal_method(method));

    EXPECT_EQ(get(smap, isolated), Status::not_estimable);
    const Vector ni = get(nmap, isolated);
    EXPECT_TRUE(std::isnan(ni.x()) && std::isnan(ni.y()) && std::isnan(ni.z()));
    EXPECT_EQ(CE::internal::face_average_normal(isolated, m, get(CGAL::vertex_point, m), method), Vec3::Zero());

    for (vertex_descriptor v : {a, mid, b, t}) {
      EXPECT_EQ(get(smap, v), Status::ok) << "method " << int(method) << " vertex " << v;
      const Vec3 n = to_eigen(get(nmap, v));
      ASSERT_TRUE(n.allFinite());
      EXPECT_LT((n - Vec3(0, 0, 1)).norm(), 1e-15) << "method " << int(method) << " vertex " << v;
    }
    m.remove_property_map(nmap);
    m.remove_property_map(smap);
  }
}

TEST(VertexNormals, NonFiniteCoordinatesGiveNotEstimableWithoutCrash)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Mesh m;
  // a good triangle, and a triangle with a NaN vertex and one with an infinite vertex
  const vertex_descriptor g0 = m.add_vertex(Point(0, 0, 0)), g1 = m.add_vertex(Point(1, 0, 0)),
                          g2 = m.add_vertex(Point(0, 1, 0));
  m.add_face(g0, g1, g2);
  const vertex_descriptor n0 = m.add_vertex(Point(nan, 0, 0)), n1 = m.add_vertex(Point(11, 0, 0)),
                          n2 = m.add_vertex(Point(10, 1, 0));
  m.add_face(n0, n1, n2);
  const vertex_descriptor i0 = m.add_vertex(Point(inf, 0, 0)), i1 = m.add_vertex(Point(21, 0, 0)),
                          i2 = m.add_vertex(Point(20, 1, 0));
  m.add_face(i0, i1, i2);
  // a huge but finite triangle: every vertex has a neighbor whose coordinate difference overflows
  const double big = std::numeric_limits<double>::max();
  const vertex_descriptor h0 = m.add_vertex(Point(-big, 0, 0)), h1 = m.add_vertex(Point(big, 0, 0)),
                          h2 = m.add_vertex(Point(-big, big, 0));
  m.add_face(h0, h1, h2);

  for (Method method : face_methods) {
    auto nmap = m.add_property_map<vertex_descriptor, Vector>("v:n").first;
    auto smap = m.add_property_map<vertex_descriptor, Status>("v:s").first;
    CE::estimate_vertex_normals(m, nmap,
                                CE::parameters::vertex_normal_method(method).vertex_estimation_status_map(smap));
    for (vertex_descriptor v : {g0, g1, g2}) {
      EXPECT_EQ(get(smap, v), Status::ok);
      EXPECT_EQ(to_eigen(get(nmap, v)), Vec3(0, 0, 1));
    }
    for (vertex_descriptor v : {n0, n1, n2, i0, i1, i2, h0, h1, h2}) {
      EXPECT_EQ(get(smap, v), Status::not_estimable) << "vertex " << v;
      EXPECT_TRUE(std::isnan(get(nmap, v).x()));
    }
    m.remove_property_map(nmap);
    m.remove_property_map(smap);
  }
}

// ---------------------------------------------------------------------------
// (f) Polyhedron_3 and Surface_mesh give the same numbers
// ---------------------------------------------------------------------------
TEST(VertexNormals, PolyhedronAndSurfaceMeshAgree)
{
  using Polyhedron = CGAL::Polyhedron_3<K>;
  using P_vertex = boost::graph_traits<Polyhedron>::vertex_descriptor;

  Mesh sm = to_mesh(icosphere(2, 0.3));
  Polyhedron poly;
  std::vector<std::pair<vertex_descriptor, P_vertex>> v2v;
  CGAL::copy_face_graph(sm, poly, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
  ASSERT_EQ(v2v.size(), num_vertices(sm));

  for (Method method : face_methods) {
    auto sm_normals = get(CGAL::dynamic_vertex_property_t<Vector>(), sm);
    auto p_normals = get(CGAL::dynamic_vertex_property_t<Vector>(), poly);
    auto p_status = get(CGAL::dynamic_vertex_property_t<Status>(), poly);
    CE::estimate_vertex_normals(sm, sm_normals, CE::parameters::vertex_normal_method(method));
    CE::estimate_vertex_normals(poly, p_normals,
                                CE::parameters::vertex_normal_method(method)
                                  .vertex_point_map(get(CGAL::vertex_point, poly))
                                  .vertex_estimation_status_map(p_status));
    for (const auto& vv : v2v) {
      EXPECT_EQ(get(p_status, vv.second), Status::ok);
      // same formula, possibly another summation order around the vertex
      EXPECT_LT((to_eigen(get(sm_normals, vv.first)) - to_eigen(get(p_normals, vv.second))).norm(), 1e-15);
    }
  }
}

// ---------------------------------------------------------------------------
// (g) quadric_fit: second order at every vertex, boundary included
// ---------------------------------------------------------------------------
TEST(VertexNormals, QuadricFitIsSecondOrderAlsoAtTheBoundaryWhereFaceAveragesAreFirstOrder)
{
  // Jittered grids of the graph .1(cos pi x + cos pi y) at spacing h and h/2; the
  // worst angle error over ALL vertices (boundary included) against the exact
  // normal. A face average tilts by O(h) at a one-sided boundary star.
  const ce_test::Graph_function f = ce_test::hamann_table1_functions()[8];
  double previous_fitted = 0, previous_area = 0;
  for (std::size_t n : {21, 41}) {
    const ce_test::Soup soup = ce_test::jittered_grid_graph_soup(f, n, -1, 1, 0.2, 5);
    Mesh m = ce_test::to_mesh<Mesh>(soup);
    const auto exact = ce_test::graph_curvatures(f, soup);
    double worst_fitted = 0, worst_area = 0;
    for (Method method : {Method::quadric_fit, Method::area_weighted}) {
      auto nmap = m.add_property_map<vertex_descriptor, Vector>("v:n").first;
      CE::estimate_vertex_normals(m, nmap, CE::parameters::vertex_normal_method(method));
      std::size_t i = 0;
      for (vertex_descriptor v : vertices(m)) {
        const double angle = angle_between(to_eigen(get(nmap, v)), exact[i++].normal);
        (method == Method::quadric_fit ? worst_fitted : worst_area) =
          std::max(method == Method::quadric_fit ? worst_fitted : worst_area, angle);
      }
      m.remove_property_map(nmap);
    }
    std::printf("n = %zu: worst normal angle error, quadric_fit %.2e rad, area_weighted %.2e rad\n", n, worst_fitted,
                worst_area);
    EXPECT_LT(worst_fitted, worst_area);
    if (previous_fitted > 0) {
      const double h_ratio = 40.0 / 20.0;
      EXPECT_GT(std::log(previous_fitted / worst_fitted) / std::log(h_ratio), 1.8); // second order
      EXPECT_LT(std::log(previous_area / worst_area) / std::log(h_ratio), 1.5);     // first order
    }
    previous_fitted = worst_fitted;
    previous_area = worst_area;
  }
}

TEST(VertexNormals, FaceAverageKernelRefusesQuadricFit)
{
  Star star;
  EXPECT_THROW(
    CE::internal::face_average_normal(star.c, star.mesh, get(CGAL::vertex_point, star.mesh), Method::quadric_fit),
    std::invalid_argument);
}

} // namespace
