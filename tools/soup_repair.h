// SPDX-License-Identifier: GPL-3.0-or-later
// From the file's polygon soup to a mesh the estimators accept: CGAL's soup
// repair and orientation, with one note on stderr of what they changed, and the
// map from the file's vertices to the mesh's, by which the outputs keep the
// file's vertex order.
#ifndef CE_TOOLS_SOUP_REPAIR_H
#define CE_TOOLS_SOUP_REPAIR_H

#include "kernel.h"
#include "surface_input.h"

#include <iostream>
#include <vector>

namespace ce_tool {

// Builds the mesh from a repaired copy of the soup; file_to_mesh[i] is the mesh
// vertex of the file's vertex i (null when the vertex is in no usable face). The notes
// of what the repair changed go to `notes`, a line each ("curvature: note: ...").
Mesh build_mesh(const Soup& soup, std::vector<V>& file_to_mesh, std::ostream& notes = std::cerr);

} // namespace ce_tool

#endif // CE_TOOLS_SOUP_REPAIR_H
