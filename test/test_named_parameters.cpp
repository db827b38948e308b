// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of CGAL/Curvature_estimation/parameters.h: this package's named
// parameters and the CGAL ones its functions read chain in any order, CGAL's
// lookup machinery accepts the resulting packs, and paraboloid_fitting_curvatures
// reads exactly the parameters it is given (outputs written only when their map
// is passed, the point and normal maps honoured, out-of-range values rejected).
#include <CGAL/Curvature_estimation.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>
#if CGAL_VERSION_MAJOR >= 6
#include <CGAL/Polygon_mesh_processing/interpolated_corrected_curvatures.h>
#endif

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include "test_surfaces.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace {

namespace CE = CGAL::Curvature_estimation;
namespace CE_np = CGAL::Curvature_estimation::internal_np;
namespace CGAL_np = CGAL::internal_np;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;

using Kernel = CGAL::Epick;
using Other_kernel = CGAL::Simple_cartesian<double>; // not the kernel deduced from the mesh
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = Mesh::Vertex_index;
using Curvatures = CE::Principal_curvatures_and_directions<Kernel>;
using Status = CE::Estimation_status;
using Method = CE::Vertex_normal_method;

// A vertex point map of its own type: the mesh's points scaled by `factor`.
struct Scaled_point_map
{
  using key_type = vertex_descriptor;
  using value_type = Point;
  using reference = Point;
  using category = boost::readable_property_map_tag;

  const Mesh* mesh = nullptr;
  double factor = 1;

  friend Point get(const Scaled_point_map& map, vertex_descriptor v)
  {
    const Point& p = map.mesh->point(v);
    return Point(map.factor * p.x(), map.factor * p.y(), map.factor * p.z());
  }
};

// True for the pack class of this package (not CGAL's own).
template <typename T>
struct is_package_pack : std::false_type
{};
template <typename T, typename Tag, typename Base>
struct is_package_pack<CE::Named_function_parameters<T, Tag, Base>> : std::true_type
{};

template <typename NP, typename Tag>
constexpr bool has()
{
  return !is_default_parameter<NP, Tag>::value;
}

// Sentinels that the estimator never writes.
constexpr double sentinel_value = -123456.75;
const Status sentinel_status = static_cast<Status>(200);
Curvatures sentinel_curvatures() { return Curvatures(-7.5, 7.25, Vector(7, 7, 7), Vector(-7, -7, -7)); }

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

bool same_bits(const Curvatures& a, const Curvatures& b)
{
  return same_bits(a.min_curvature, b.min_curvature) && same_bits(a.max_curvature, b.max_curvature) &&
         same_bits(a.min_direction.x(), b.min_direction.x()) && same_bits(a.min_direction.y(), b.min_direction.y()) &&
         same_bits(a.min_direction.z(), b.min_direction.z()) && same_bits(a.max_direction.x(), b.max_direction.x()) &&
         same_bits(a.max_direction.y(), b.max_direction.y()) && same_bits(a.max_direction.z(), b.max_direction.z());
}

// The output maps of one run, added to a mesh and filled with sentinels.
struct Outputs
{
  Mesh::Property_map<vertex_descriptor, double> mean, gaussian;
  Mesh::Property_map<vertex_descriptor, Curvatures> principal;
  Mesh::Property_map<vertex_descriptor, Status> status;

  explicit Outputs(Mesh& mesh, const std::string& prefix = "v:test_")
  {
    mean = mesh.add_property_map<vertex_descriptor, double>(prefix + "H", sentinel_value).first;
    gaussian = mesh.add_property_map<vertex_descriptor, double>(prefix + "K", sentinel_value).first;
    principal = mesh.add_property_map<vertex_descriptor, Curvatures>(prefix + "P", sentinel_curvatures()).first;
    status = mesh.add_property_map<vertex_descriptor, Status>(prefix + "S", sentinel_status).first;
    reset(mesh);
  }
  void reset(const Mesh& mesh)
  {
    for (vertex_descriptor v : vertices(mesh)) {
      mean[v] = sentinel_value;
      gaussian[v] = sentinel_value;
      principal[v] = sentinel_curvatures();
      status[v] = sentinel_status;
    }
  }
};

Mesh icosphere(double radius, unsigned subdivisions)
{
  return ce_test::to_mesh<Mesh>(ce_test::sphere_soup(radius, subdivisions));
}

const ce_test::Graph_function& paraboloid_function()
{
  static const std::vector<ce_test::Graph_function> functions = ce_test::hamann_table1_functions();
  for (const ce_test::Graph_function& f : functions)
    if (f.name == "paraboloid")
      return f;
  throw std::logic_error("no paraboloid in Hamann's table");
}

// A small irregular graph mesh with a boundary (so that every ring parameter matters).
Mesh jittered_paraboloid_grid()
{
  return ce_test::to_mesh<Mesh>(ce_test::jittered_grid_graph_soup(paraboloid_function(), 9, -1, 1, 0.2, 7));
}

// ---------------------------------------------------------------------------
// Compile-time and run-time lookup in packs built in different orders
// ---------------------------------------------------------------------------

struct Full_pack_fixture
{
  Mesh mesh = icosphere(1.0, 1);
  Outputs out{mesh};
  Mesh::Property_map<vertex_descriptor, Vector> normals =
    mesh.add_property_map<vertex_descriptor, Vector>("v:test_N", Vector(0, 0, 0)).first;
  Scaled_point_map points{&mesh, 2.0};
  vertex_descriptor v = *vertices(mesh).begin();
};

// Checks that every parameter of a full pack is found, with its value.
template <typename NP>
void check_full_pack(const NP& np, Full_pack_fixture& f, Method method)
{
  static_assert(is_package_pack<NP>::value, "chaining must stay in the package's pack class");
  // Present: this package's tags ...
  static_assert(has<NP, CE_np::vertex_mean_curvature_map_t>(), "");
  static_assert(has<NP, CE_np::vertex_Gaussian_curvature_map_t>(), "");
  static_assert(has<NP, CE_np::vertex_principal_curvatures_and_directions_map_t>(), "");
  static_assert(has<NP, CE_np::vertex_estimation_status_map_t>(), "");
  static_assert(has<NP, CE_np::vertex_normal_method_t>(), "");
  static_assert(has<NP, CE_np::neighborhood_rings_t>(), "");
  static_assert(has<NP, CE_np::boundary_neighborhood_rings_t>(), "");
  static_assert(has<NP, CE_np::max_neighborhood_rings_t>(), "");
  static_assert(has<NP, CE_np::max_condition_number_t>(), "");
  // ... and CGAL's.
  static_assert(has<NP, CGAL_np::vertex_point_t>(), "");
  static_assert(has<NP, CGAL_np::vertex_normal_map_t>(), "");
  static_assert(has<NP, CGAL_np::geom_traits_t>(), "");
  // Absent ones are default.
  static_assert(is_default_parameter<NP, CGAL_np::vertex_index_t>::value, "");
  static_assert(is_default_parameter<NP, CGAL_np::face_index_t>::value, "");
  static_assert(is_default_parameter<NP, CGAL_np::number_of_iterations_t>::value, "");
  // CGAL's own traits deduction sees the pack's traits and point map.
  static_assert(std::is_same<typename CGAL::GetGeomTraits<Mesh, NP>::type, Other_kernel>::value, "");
  static_assert(std::is_same<typename CGAL::GetVertexPointMap<Mesh, NP>::type, Scaled_point_map>::value, "");
  static_assert(std::is_same<typename CGAL::GetVertexPointMap<Mesh, NP>::const_type, Scaled_point_map>::value, "");
  // The values have the types they were given.
  static_assert(std::is_same<decltype(get_parameter(np, CE_np::neighborhood_rings)), int>::value, "");
  static_assert(std::is_same<decltype(get_parameter(np, CE_np::max_condition_number)), double>::value, "");
  static_assert(std::is_same<decltype(get_parameter(np, CE_np::vertex_normal_method)), Method>::value, "");
  static_assert(std::is_same<decltype(get_parameter(np, CGAL_np::geom_traits)), Other_kernel>::value, "");

  // Run time: the scalar values ...
  EXPECT_EQ(get_parameter(np, CE_np::neighborhood_rings), 1);
  EXPECT_EQ(get_parameter(np, CE_np::boundary_neighborhood_rings), 2);
  EXPECT_EQ(get_parameter(np, CE_np::max_neighborhood_rings), 3);
  EXPECT_EQ(get_parameter(np, CE_np::max_condition_number), 1e3);
  EXPECT_EQ(get_parameter(np, CE_np::vertex_normal_method), method);
  EXPECT_EQ(choose_parameter(get_parameter(np, CGAL_np::vertex_index), 42), 42);
  EXPECT_EQ(choose_parameter(get_parameter(np, CE_np::max_neighborhood_rings), 42), 3);
  // ... the point map (its own copy, with its factor) ...
  const Scaled_point_map points = get_parameter(np, CGAL_np::vertex_point);
  EXPECT_EQ(points.mesh, &f.mesh);
  EXPECT_EQ(points.factor, 2.0);
  EXPECT_EQ(get(points, f.v), Point(2 * f.mesh.point(f.v).x(), 2 * f.mesh.point(f.v).y(), 2 * f.mesh.point(f.v).z()));
  // ... and the maps: each retrieved map writes into its own property.
  f.out.reset(f.mesh);
  put(get_parameter(np, CE_np::vertex_mean_curvature_map), f.v, 1.5);
  put(get_parameter(np, CE_np::vertex_Gaussian_curvature_map), f.v, 2.5);
  put(get_parameter(np, CE_np::vertex_principal_curvatures_and_directions_map), f.v,
      Curvatures(-1, 3, Vector(1, 0, 0), Vector(0, 1, 0)));
  put(get_parameter(np, CE_np::vertex_estimation_status_map), f.v, Status::widened);
  put(get_parameter(np, CGAL_np::vertex_normal_map), f.v, Vector(0, 0, 4));
  EXPECT_EQ(f.out.mean[f.v], 1.5);
  EXPECT_EQ(f.out.gaussian[f.v], 2.5);
  EXPECT_EQ(f.out.principal[f.v].min_curvature, -1);
  EXPECT_EQ(f.out.principal[f.v].max_curvature, 3);
  EXPECT_EQ(f.out.status[f.v], Status::widened);
  EXPECT_EQ(f.normals[f.v], Vector(0, 0, 4));
}

TEST(NamedParameters, FullPacksChainInAnyOrder)
{
  Full_pack_fixture f;
  const Other_kernel traits;

  // 1. Starting with a package parameter, CGAL's in the middle.
  const auto np1 = CE::parameters::vertex_mean_curvature_map(f.out.mean)
                     .vertex_Gaussian_curvature_map(f.out.gaussian)
                     .vertex_point_map(f.points)
                     .vertex_principal_curvatures_and_directions_map(f.out.principal)
                     .geom_traits(traits)
                     .vertex_estimation_status_map(f.out.status)
                     .vertex_normal_map(f.normals)
                     .vertex_normal_method(Method::angle_weighted)
                     .neighborhood_rings(1)
                     .boundary_neighborhood_rings(2)
                     .max_neighborhood_rings(3)
                     .max_condition_number(1e3);
  check_full_pack(np1, f, Method::angle_weighted);

  // 2. Starting with a CGAL parameter, alternating.
  const auto np2 = CE::parameters::vertex_point_map(f.points)
                     .max_condition_number(1e3)
                     .geom_traits(traits)
                     .vertex_estimation_status_map(f.out.status)
                     .vertex_normal_map(f.normals)
                     .neighborhood_rings(1)
                     .vertex_Gaussian_curvature_map(f.out.gaussian)
                     .max_neighborhood_rings(3)
                     .vertex_principal_curvatures_and_directions_map(f.out.principal)
                     .boundary_neighborhood_rings(2)
                     .vertex_normal_method(Method::centroid_weighted)
                     .vertex_mean_curvature_map(f.out.mean);
  check_full_pack(np2, f, Method::centroid_weighted);

  // 3. Starting with geom_traits, CGAL's parameters last.
  const auto np3 = CE::parameters::geom_traits(traits)
                     .boundary_neighborhood_rings(2)
                     .vertex_principal_curvatures_and_directions_map(f.out.principal)
                     .max_neighborhood_rings(3)
                     .vertex_mean_curvature_map(f.out.mean)
                     .vertex_normal_method(Method::area_weighted)
                     .max_condition_number(1e3)
                     .vertex_estimation_status_map(f.out.status)
                     .neighborhood_rings(1)
                     .vertex_Gaussian_curvature_map(f.out.gaussian)
                     .vertex_normal_map(f.normals)
                     .vertex_point_map(f.points);
  check_full_pack(np3, f, Method::area_weighted);

  // 4. From default_values().
  const auto np4 = CE::parameters::default_values()
                     .vertex_normal_map(f.normals)
                     .neighborhood_rings(1)
                     .vertex_mean_curvature_map(f.out.mean)
                     .geom_traits(traits)
                     .vertex_estimation_status_map(f.out.status)
                     .max_neighborhood_rings(3)
                     .vertex_point_map(f.points)
                     .vertex_Gaussian_curvature_map(f.out.gaussian)
                     .max_condition_number(1e3)
                     .vertex_principal_curvatures_and_directions_map(f.out.principal)
                     .boundary_neighborhood_rings(2)
                     .vertex_normal_method(Method::quadric_fit);
  check_full_pack(np4, f, Method::quadric_fit);

  // The pack types differ (the order is part of the type) but hold the same parameters.
  static_assert(!std::is_same<decltype(np1), decltype(np2)>::value, "");
}

TEST(NamedParameters, PartialPacksAndDefaults)
{
  Mesh mesh = icosphere(1.0, 0);
  Outputs out(mesh);

  // default_values(): nothing is set, CGAL's deductions give the defaults.
  using Default = decltype(CE::parameters::default_values());
  static_assert(is_package_pack<Default>::value, "");
  static_assert(std::is_same<Default, CE::parameters::Default_named_parameters>::value, "");
  static_assert(is_default_parameter<Default, CE_np::vertex_mean_curvature_map_t>::value, "");
  static_assert(is_default_parameter<Default, CE_np::max_condition_number_t>::value, "");
  static_assert(is_default_parameter<Default, CGAL_np::vertex_point_t>::value, "");
  static_assert(is_default_parameter<Default, CGAL_np::geom_traits_t>::value, "");
  static_assert(std::is_same<CGAL::GetGeomTraits<Mesh, Default>::type, Kernel>::value, "");
  static_assert(std::is_same<CGAL::GetVertexPointMap<Mesh, Default>::const_type,
                             boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value,
                "");
  EXPECT_EQ(choose_parameter(get_parameter(CE::parameters::default_values(), CE_np::neighborhood_rings), 7), 7);

  // One package parameter, then one CGAL parameter: the rest stays default.
  const auto np = CE::parameters::max_neighborhood_rings(5).geom_traits(Other_kernel());
  using NP = std::decay_t<decltype(np)>;
  static_assert(is_package_pack<NP>::value, "");
  static_assert(has<NP, CE_np::max_neighborhood_rings_t>(), "");
  static_assert(has<NP, CGAL_np::geom_traits_t>(), "");
  static_assert(is_default_parameter<NP, CE_np::neighborhood_rings_t>::value, "");
  static_assert(is_default_parameter<NP, CE_np::boundary_neighborhood_rings_t>::value, "");
  static_assert(is_default_parameter<NP, CE_np::vertex_mean_curvature_map_t>::value, "");
  static_assert(is_default_parameter<NP, CE_np::vertex_Gaussian_curvature_map_t>::value, "");
  static_assert(is_default_parameter<NP, CE_np::vertex_principal_curvatures_and_directions_map_t>::value, "");
  static_assert(is_default_parameter<NP, CE_np::vertex_estimation_status_map_t>::value, "");
  static_assert(is_default_parameter<NP, CE_np::vertex_normal_method_t>::value, "");
  static_assert(is_default_parameter<NP, CE_np::max_condition_number_t>::value, "");
  static_assert(is_default_parameter<NP, CGAL_np::vertex_point_t>::value, "");
  static_assert(is_default_parameter<NP, CGAL_np::vertex_normal_map_t>::value, "");
  static_assert(std::is_same<CGAL::GetGeomTraits<Mesh, NP>::type, Other_kernel>::value, "");
  static_assert(!CE::internal::has_parameter<NP, CE_np::vertex_mean_curvature_map_t>(), "");
  static_assert(CE::internal::has_parameter<NP, CE_np::max_neighborhood_rings_t>(), "");
  EXPECT_EQ(get_parameter(np, CE_np::max_neighborhood_rings), 5);
  EXPECT_EQ(choose_parameter(get_parameter(np, CE_np::neighborhood_rings), 1), 1);

  // A CGAL parameter first, from this package's namespace: still this package's pack.
  const auto vpm = get(CGAL::vertex_point, mesh);
  const auto np_vpm = CE::parameters::vertex_point_map(vpm);
  static_assert(is_package_pack<std::decay_t<decltype(np_vpm)>>::value, "");
  static_assert(is_package_pack<std::decay_t<decltype(np_vpm.vertex_mean_curvature_map(out.mean))>>::value, "");
  static_assert(is_package_pack<std::decay_t<decltype(CE::parameters::vertex_index_map(0).face_index_map(0))>>::value,
                "");
  static_assert(std::is_same<CGAL::GetVertexPointMap<Mesh, std::decay_t<decltype(np_vpm)>>::type,
                             std::decay_t<decltype(vpm)>>::value,
                "");

  // Chaining after default_values() runs: a pack with only a status map.
  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::default_values().vertex_estimation_status_map(out.status));
  for (vertex_descriptor v : vertices(mesh))
    EXPECT_EQ(out.status[v], Status::ok);
}

// ---------------------------------------------------------------------------
// Behaviour of paraboloid_fitting_curvatures
// ---------------------------------------------------------------------------

enum class Only
{
  mean,
  gaussian,
  principal,
  status
};

TEST(NamedParameters, OnlyTheOutputsPassedAreWritten)
{
  const double radius = 1.5;
  Mesh mesh = icosphere(radius, 2); // 162 vertices, valence 5 and 6: every 1-ring is fine
  for (Only only : {Only::status, Only::mean, Only::gaussian, Only::principal}) {
    Outputs out(mesh);
    switch (only) {
      case Only::status:
        CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_estimation_status_map(out.status));
        break;
      case Only::mean:
        CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(out.mean));
        break;
      case Only::gaussian:
        CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_Gaussian_curvature_map(out.gaussian));
        break;
      case Only::principal:
        CE::paraboloid_fitting_curvatures(
          mesh, CE::parameters::vertex_principal_curvatures_and_directions_map(out.principal));
        break;
    }
    const Curvatures sentinel = sentinel_curvatures();
    for (vertex_descriptor v : vertices(mesh)) {
      // The output asked for is written ...
      switch (only) {
        case Only::status:
          EXPECT_EQ(out.status[v], Status::ok);
          break;
        case Only::mean: // a sphere: H = 1/r with outward normals (loose: this is not an accuracy test)
          EXPECT_NEAR(out.mean[v], 1 / radius, 0.05 / radius);
          break;
        case Only::gaussian:
          EXPECT_NEAR(out.gaussian[v], 1 / (radius * radius), 0.1 / (radius * radius));
          break;
        case Only::principal:
          EXPECT_NEAR(out.principal[v].max_curvature, 1 / radius, 0.1 / radius);
          EXPECT_NEAR(out.principal[v].min_curvature, 1 / radius, 0.1 / radius);
          EXPECT_NEAR(std::sqrt(out.principal[v].max_direction.squared_length()), 1.0, 1e-12);
          break;
      }
      // ... and nothing else.
      if (only != Only::status) {
        EXPECT_EQ(out.status[v], sentinel_status);
      }
      if (only != Only::mean) {
        EXPECT_TRUE(same_bits(out.mean[v], sentinel_value));
      }
      if (only != Only::gaussian) {
        EXPECT_TRUE(same_bits(out.gaussian[v], sentinel_value));
      }
      if (only != Only::principal) {
        EXPECT_TRUE(same_bits(out.principal[v], sentinel));
      }
    }
    mesh.remove_property_map(out.mean);
    mesh.remove_property_map(out.gaussian);
    mesh.remove_property_map(out.principal);
    mesh.remove_property_map(out.status);
  }
}

TEST(NamedParameters, ResultsDoNotDependOnTheOrderOfTheParameters)
{
  Mesh mesh = jittered_paraboloid_grid(); // a boundary, so boundary_neighborhood_rings is read
  Outputs a(mesh, "v:a_"), b(mesh, "v:b_"), c(mesh, "v:c_"), reference(mesh, "v:r_");
  const auto vpm = get(CGAL::vertex_point, mesh);

  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(a.mean)
                                            .vertex_Gaussian_curvature_map(a.gaussian)
                                            .vertex_point_map(vpm)
                                            .vertex_principal_curvatures_and_directions_map(a.principal)
                                            .geom_traits(Kernel())
                                            .vertex_estimation_status_map(a.status)
                                            .vertex_normal_method(Method::angle_weighted)
                                            .neighborhood_rings(1)
                                            .boundary_neighborhood_rings(2)
                                            .max_neighborhood_rings(3)
                                            .max_condition_number(1e3));
  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_point_map(vpm)
                                            .max_condition_number(1e3)
                                            .boundary_neighborhood_rings(2)
                                            .vertex_estimation_status_map(b.status)
                                            .geom_traits(Kernel())
                                            .vertex_principal_curvatures_and_directions_map(b.principal)
                                            .max_neighborhood_rings(3)
                                            .vertex_normal_method(Method::angle_weighted)
                                            .vertex_Gaussian_curvature_map(b.gaussian)
                                            .neighborhood_rings(1)
                                            .vertex_mean_curvature_map(b.mean));
  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_normal_method(Method::angle_weighted)
                                            .vertex_principal_curvatures_and_directions_map(c.principal)
                                            .max_neighborhood_rings(3)
                                            .vertex_mean_curvature_map(c.mean)
                                            .boundary_neighborhood_rings(2)
                                            .geom_traits(Kernel())
                                            .vertex_Gaussian_curvature_map(c.gaussian)
                                            .neighborhood_rings(1)
                                            .vertex_estimation_status_map(c.status)
                                            .max_condition_number(1e3)
                                            .vertex_point_map(vpm));
  // Reference with the defaults (quadric_fit normal, 1 boundary ring): the
  // parameters above must have been read, so some results differ from it.
  CE::paraboloid_fitting_curvatures(
    mesh, CE::parameters::vertex_mean_curvature_map(reference.mean).vertex_estimation_status_map(reference.status));

  int differing_from_defaults = 0, widened = 0;
  for (vertex_descriptor v : vertices(mesh)) {
    for (const Outputs* o : {&b, &c}) {
      EXPECT_TRUE(same_bits(o->mean[v], a.mean[v])) << v;
      EXPECT_TRUE(same_bits(o->gaussian[v], a.gaussian[v])) << v;
      EXPECT_TRUE(same_bits(o->principal[v], a.principal[v])) << v;
      EXPECT_EQ(o->status[v], a.status[v]) << v;
    }
    EXPECT_NE(a.status[v], sentinel_status);
    EXPECT_TRUE(std::isfinite(a.mean[v])) << v;
    if (!same_bits(a.mean[v], reference.mean[v]))
      ++differing_from_defaults;
    // boundary_neighborhood_rings(2): every boundary vertex starts from 2 rings.
    if (CGAL::is_border(v, mesh)) {
      EXPECT_EQ(a.status[v], Status::widened) << v;
      ++widened;
    }
  }
  EXPECT_GT(widened, 0);
  EXPECT_GT(differing_from_defaults, 0);
}

TEST(NamedParameters, VertexPointMapIsHonoured)
{
  // The same mesh through a separate point map scaled by 2: every curvature halves
  // (and K quarters), the directions stay. Scaling by 2 is exact in binary floating point.
  Mesh mesh = jittered_paraboloid_grid();
  auto doubled = mesh.add_property_map<vertex_descriptor, Point>("v:doubled").first;
  for (vertex_descriptor v : vertices(mesh))
    doubled[v] = Point(2 * mesh.point(v).x(), 2 * mesh.point(v).y(), 2 * mesh.point(v).z());
  Outputs own(mesh, "v:own_"), scaled(mesh, "v:scaled_");

  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(own.mean)
                                            .vertex_Gaussian_curvature_map(own.gaussian)
                                            .vertex_principal_curvatures_and_directions_map(own.principal));
  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(scaled.mean)
                                            .vertex_point_map(doubled)
                                            .vertex_Gaussian_curvature_map(scaled.gaussian)
                                            .vertex_principal_curvatures_and_directions_map(scaled.principal));
  // (A point map of another type, such as Scaled_point_map, is not run here: with
  // GCC 12 -O1 it makes platelet_fit.h's uninitialised Platelet_fitter::center_
  // raise -Wmaybe-uninitialized when the estimator copies its worker.)

  for (vertex_descriptor v : vertices(mesh)) {
    ASSERT_TRUE(std::isfinite(own.mean[v]));
    const double tolerance = 1e-12 * (std::abs(own.mean[v]) + 1e-3);
    EXPECT_NEAR(scaled.mean[v], 0.5 * own.mean[v], tolerance) << v;
    EXPECT_NEAR(scaled.gaussian[v], 0.25 * own.gaussian[v], 1e-12 * (std::abs(own.gaussian[v]) + 1e-3)) << v;
    EXPECT_NEAR(scaled.principal[v].max_curvature, 0.5 * own.principal[v].max_curvature, tolerance) << v;
    EXPECT_NEAR(scaled.principal[v].min_curvature, 0.5 * own.principal[v].min_curvature, tolerance) << v;
    EXPECT_LE(std::sqrt((scaled.principal[v].max_direction - own.principal[v].max_direction).squared_length()), 1e-9)
      << v;
  }
  // Sanity of the comparison: near the centre of the grid (point (4, 4), jittered
  // around (0, 0)) H is close to the exact value of the paraboloid z = 0.4 (x^2 + y^2),
  // about -0.8 (the upward normal: the surface bends towards it, hence negative).
  const vertex_descriptor centre = ce_test::soup_order_vertices(mesh)[40];
  const Point& p = mesh.point(centre);
  const double exact = ce_test::graph_curvature(paraboloid_function(), p.x(), p.y()).H;
  EXPECT_NEAR(exact, -0.8, 0.05);
  EXPECT_NEAR(own.mean[centre], exact, 0.05 * std::abs(exact));
}

TEST(NamedParameters, VertexNormalMapIsHonouredAndSetsTheSign)
{
  // Exact normals on an icosphere of radius r: H = 1/r up to the fit's truncation
  // error, about (h/r)^2 / 4 relative, below 3e-4 for 5 subdivisions (h ~ 0.033 r).
  const double radius = 2.5;
  Mesh mesh = icosphere(radius, 5);
  auto outward = mesh.add_property_map<vertex_descriptor, Vector>("v:outward").first;
  auto inward = mesh.add_property_map<vertex_descriptor, Vector>("v:inward").first;
  auto long_outward = mesh.add_property_map<vertex_descriptor, Vector>("v:long_outward").first;
  for (vertex_descriptor v : vertices(mesh)) {
    const Vector n = (mesh.point(v) - CGAL::ORIGIN) / std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length());
    outward[v] = n;
    inward[v] = -n;
    long_outward[v] = 3 * n; // "trusted as given, need not be unit"
  }
  Outputs out(mesh, "v:out_"), in(mesh, "v:in_"), longer(mesh, "v:long_");
  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_normal_map(outward)
                                            .vertex_mean_curvature_map(out.mean)
                                            .vertex_principal_curvatures_and_directions_map(out.principal));
  CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(in.mean)
                                            .vertex_principal_curvatures_and_directions_map(in.principal)
                                            .vertex_normal_map(inward));
  CE::paraboloid_fitting_curvatures(
    mesh, CE::parameters::vertex_mean_curvature_map(longer.mean).vertex_normal_map(long_outward));
  double worst = 0;
  for (vertex_descriptor v : vertices(mesh)) {
    EXPECT_NEAR(out.mean[v], 1 / radius, 1e-3 / radius) << v;
    EXPECT_NEAR(in.mean[v], -1 / radius, 1e-3 / radius) << v;
    // Reversing the normal reverses every curvature (and swaps max and min).
    EXPECT_NEAR(in.mean[v], -out.mean[v], 1e-12) << v;
    EXPECT_NEAR(in.principal[v].max_curvature, -out.principal[v].min_curvature, 1e-12) << v;
    EXPECT_NEAR(in.principal[v].min_curvature, -out.principal[v].max_curvature, 1e-12) << v;
    EXPECT_NEAR(longer.mean[v], out.mean[v], 1e-12) << v;
    worst = (std::max)(worst, std::abs(out.mean[v] * radius - 1));
  }
  std::cout << "icosphere (5 subdivisions), exact normals: max |H r - 1| = " << worst << "\n";
}

TEST(NamedParameters, OutOfRangeParametersThrow)
{
  Mesh mesh = jittered_paraboloid_grid();
  Outputs out(mesh);
  const auto H = out.mean;
  EXPECT_THROW(
    CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(H).neighborhood_rings(0)),
    std::invalid_argument);
  EXPECT_THROW(
    CE::paraboloid_fitting_curvatures(mesh, CE::parameters::neighborhood_rings(-1).vertex_mean_curvature_map(H)),
    std::invalid_argument);
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(
                 mesh, CE::parameters::vertex_mean_curvature_map(H).boundary_neighborhood_rings(0)),
               std::invalid_argument);
  EXPECT_THROW(
    CE::paraboloid_fitting_curvatures(
      mesh, CE::parameters::max_neighborhood_rings(1).boundary_neighborhood_rings(2).vertex_mean_curvature_map(H)),
    std::invalid_argument);
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(
                 mesh, CE::parameters::vertex_mean_curvature_map(H).neighborhood_rings(3).max_neighborhood_rings(2)),
               std::invalid_argument);
  EXPECT_THROW(
    CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(H).max_condition_number(0.5)),
    std::invalid_argument);
  EXPECT_THROW(
    CE::paraboloid_fitting_curvatures(mesh, CE::parameters::max_condition_number(1.0).vertex_mean_curvature_map(H)),
    std::invalid_argument);
  EXPECT_THROW(
    CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(H).max_condition_number(
                                              std::numeric_limits<double>::quiet_NaN())),
    std::invalid_argument);
  // Also without any output map (the arguments are checked first).
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(mesh, CE::parameters::neighborhood_rings(0)), std::invalid_argument);
  // Nothing was written by the rejected calls.
  for (vertex_descriptor v : vertices(mesh))
    EXPECT_TRUE(same_bits(out.mean[v], sentinel_value));
  // The limits themselves are accepted.
  EXPECT_NO_THROW(CE::paraboloid_fitting_curvatures(mesh, CE::parameters::vertex_mean_curvature_map(H)
                                                            .neighborhood_rings(1)
                                                            .boundary_neighborhood_rings(3)
                                                            .max_neighborhood_rings(3)
                                                            .max_condition_number(1.5)));
}

// CGAL 6's ball_radius (radius neighborhoods) is refused, with or without output maps,
// rather than ignored, by the estimators that do not take it; those that do (the
// paraboloid fits, jet fitting, the Gauss map, the quadric_fit normals: see
// test_ball_radius) refuse a radius that is not positive and finite.
TEST(NamedParameters, BallRadiusIsRefusedWhereNotTaken)
{
  Mesh mesh = jittered_paraboloid_grid();
  Outputs out(mesh);
  const auto np = CE::parameters::vertex_mean_curvature_map(out.mean).ball_radius(0.5);
  EXPECT_THROW(CE::curve_network_curvatures(mesh, np), std::invalid_argument);
  EXPECT_THROW(CE::taubin_curvatures(mesh, np), std::invalid_argument);
  EXPECT_THROW(CE::chen_schmitt_curvatures(mesh, np), std::invalid_argument);
  const auto negative = CE::parameters::vertex_mean_curvature_map(out.mean).ball_radius(-0.5);
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(mesh, negative), std::invalid_argument);
  EXPECT_THROW(CE::jet_fitting_curvatures(mesh, negative), std::invalid_argument);
  EXPECT_THROW(CE::gauss_map_curvatures(mesh, negative), std::invalid_argument);
  auto normals = mesh.add_property_map<vertex_descriptor, Vector>("v:test_normal").first;
  EXPECT_THROW(CE::estimate_vertex_normals(mesh, normals, CE::parameters::ball_radius(0.0)), std::invalid_argument);
  for (vertex_descriptor v : vertices(mesh))
    EXPECT_TRUE(same_bits(out.mean[v], sentinel_value));
  CE::Indexed_tetrahedral_mesh<std::array<double, 4>> cells;
  cells.points = {{0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  cells.cells = {{0, 1, 2, 3}};
  std::vector<double> cell_H(4, sentinel_value);
  EXPECT_THROW(CE::hypersurface_paraboloid_fitting_curvatures(
                 cells, CE::parameters::vertex_mean_curvature_map(CGAL::make_property_map(cell_H)).ball_radius(-0.5)),
               std::invalid_argument);
  for (double h : cell_H)
    EXPECT_TRUE(same_bits(h, sentinel_value));
}

#if CGAL_VERSION_MAJOR >= 6
// On CGAL 6 the output parameters are CGAL's own, and so is the value type of the
// principal curvatures: the chain of named parameters and the maps that a user wrote
// for CGAL's interpolated corrected curvatures serve our estimators unchanged, so
// that swapping CGAL's estimator for ours is a change of the function's name.
// (A chain started in this package is not CGAL's own class, and CGAL functions that
// overload on their first argument cannot take it: the package chain is for this
// package's functions.)
TEST(NamedParameters, OneChainServesCgalInterpolatedCorrectedCurvatures)
{
  static_assert(std::is_same<CE::Principal_curvatures_and_directions<Kernel>,
                             CGAL::Polygon_mesh_processing::Principal_curvatures_and_directions<Kernel>>::value);
  static_assert(std::is_same<CE_np::vertex_mean_curvature_map_t, CGAL_np::vertex_mean_curvature_map_t>::value);
  static_assert(std::is_same<CE_np::vertex_Gaussian_curvature_map_t, CGAL_np::vertex_Gaussian_curvature_map_t>::value);
  static_assert(std::is_same<CE_np::vertex_principal_curvatures_and_directions_map_t,
                             CGAL_np::vertex_principal_curvatures_and_directions_map_t>::value);
  static_assert(std::is_same<CE_np::ball_radius_t, CGAL_np::ball_radius_t>::value);

  const double radius = 2;
  Mesh mesh = ce_test::to_mesh<Mesh>(ce_test::sphere_soup(radius, 4));
  auto H = mesh.add_property_map<vertex_descriptor, double>("v:H", sentinel_value).first;
  auto K = mesh.add_property_map<vertex_descriptor, double>("v:K", sentinel_value).first;
  auto P =
    mesh
      .add_property_map<vertex_descriptor, CGAL::Polygon_mesh_processing::Principal_curvatures_and_directions<Kernel>>(
        "v:P")
      .first;
  // Every vertex of the sphere has H = k_min = k_max = 1/r and K = 1/r^2 (then reset).
  const auto check = [&](const char* who, double tolerance) {
    for (vertex_descriptor v : vertices(mesh)) {
      ASSERT_NEAR(H[v] * radius, 1, tolerance) << who << " H at " << v;
      ASSERT_NEAR(K[v] * radius * radius, 1, 2 * tolerance) << who << " K at " << v;
      ASSERT_NEAR(P[v].min_curvature * radius, 1, tolerance) << who << " k_min at " << v;
      ASSERT_NEAR(P[v].max_curvature * radius, 1, tolerance) << who << " k_max at " << v;
      H[v] = K[v] = sentinel_value;
      P[v].min_curvature = P[v].max_curvature = sentinel_value;
    }
  };

  // One chain of CGAL's own functions, for CGAL's estimator and ours.
  const auto np = CGAL::parameters::vertex_principal_curvatures_and_directions_map(P)
                    .vertex_Gaussian_curvature_map(K)
                    .vertex_mean_curvature_map(H)
                    .vertex_point_map(get(CGAL::vertex_point, mesh))
                    .geom_traits(Kernel());
  CGAL::Polygon_mesh_processing::interpolated_corrected_curvatures(mesh, np);
  check("interpolated_corrected_curvatures", 0.05);
  CE::paraboloid_fitting_curvatures(mesh, np);
  check("paraboloid_fitting_curvatures", 0.01);
  CE::jet_fitting_curvatures(mesh, np);
  check("jet_fitting_curvatures", 0.01);
  CE::gauss_map_curvatures(mesh, np);
  check("gauss_map_curvatures", 0.05);

  // The package's chain holds the same maps under the same (CGAL's) tags.
  const auto ours = CE::parameters::vertex_mean_curvature_map(H)
                      .vertex_Gaussian_curvature_map(K)
                      .vertex_principal_curvatures_and_directions_map(P)
                      .neighborhood_rings(1);
  CE::paraboloid_fitting_curvatures(mesh, ours);
  check("paraboloid_fitting_curvatures, package chain", 0.01);

  // CGAL's ball_radius is read by CGAL's estimator and by ours that take it.
  CGAL::Polygon_mesh_processing::interpolated_corrected_curvatures(mesh, np.ball_radius(0.2));
  check("interpolated_corrected_curvatures, ball_radius", 0.05);
  CE::paraboloid_fitting_curvatures(mesh, np.ball_radius(0.2));
  check("paraboloid_fitting_curvatures, ball_radius", 0.01);
  CE::jet_fitting_curvatures(mesh, np.ball_radius(0.2));
  check("jet_fitting_curvatures, ball_radius", 0.01);
  CE::gauss_map_curvatures(mesh, np.ball_radius(0.2));
  check("gauss_map_curvatures, ball_radius", 0.05);
}
#endif

} // namespace
