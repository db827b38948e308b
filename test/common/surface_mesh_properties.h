// SPDX-License-Identifier: GPL-3.0-or-later
// Looking up a named property map of a CGAL::Surface_mesh, in one spelling for CGAL 5.x
// (which returns a pair of the map and whether it was found) and CGAL 6 (std::optional).
#ifndef CE_TEST_COMMON_SURFACE_MESH_PROPERTIES_H
#define CE_TEST_COMMON_SURFACE_MESH_PROPERTIES_H

#include <CGAL/version.h>

#include <optional>
#include <string>

namespace ce_test {

// The property map of `mesh` named `name` with key `Key` and value `Value`, if there is one.
template <typename Key, typename Value, typename Mesh>
std::optional<typename Mesh::template Property_map<Key, Value>> find_property_map(const Mesh& mesh,
                                                                                  const std::string& name)
{
#if CGAL_VERSION_MAJOR >= 6
  return mesh.template property_map<Key, Value>(name);
#else
  const auto [map, found] = mesh.template property_map<Key, Value>(name);
  if (!found)
    return std::nullopt;
  return map;
#endif
}

} // namespace ce_test

#endif // CE_TEST_COMMON_SURFACE_MESH_PROPERTIES_H
