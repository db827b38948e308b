// SPDX-License-Identifier: GPL-3.0-or-later
// Umbrella header of the curvature estimation package.
#ifndef CGAL_CURVATURE_ESTIMATION_H
#define CGAL_CURVATURE_ESTIMATION_H

#include <CGAL/Curvature_estimation/Estimator.h>
#include <CGAL/Curvature_estimation/Neighbor_weighting.h>
#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/chen_schmitt.h>
#include <CGAL/Curvature_estimation/curve_network.h>
#include <CGAL/Curvature_estimation/gauss_map.h>
#include <CGAL/Curvature_estimation/hypersurface_paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/jet_fitting.h>
#include <CGAL/Curvature_estimation/mean_edge_length.h>
#include <CGAL/Curvature_estimation/neighborhood_reach.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>
#include <CGAL/Curvature_estimation/taubin.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#endif // CGAL_CURVATURE_ESTIMATION_H
