// SPDX-License-Identifier: GPL-3.0-or-later
// The geometry every part of the tool shares: points read from files and given
// to the estimators are points of this kernel, surfaces are meshes of this type.
#ifndef CE_TOOLS_KERNEL_H
#define CE_TOOLS_KERNEL_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

// Declared so that the alias below needs no estimator header.
namespace CGAL::Curvature_estimation {}

namespace ce_tool {

namespace CE = CGAL::Curvature_estimation;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using V = Mesh::Vertex_index;

} // namespace ce_tool

#endif // CE_TOOLS_KERNEL_H
