# SPDX-License-Identifier: GPL-3.0-or-later
"""Curvature of surface meshes, point sets and tetrahedral graphs in R^4, with numpy.

The C++ package CGAL::Curvature_estimation through the parts of its command-line tool
``curvature``: every function gives the tool's values bit for bit, one row per input
vertex in input order, as float64 arrays, with a ``status`` per vertex (see Status).
The estimation runs without the GIL; ``threads`` is as the tool's --threads (0: all
cores, 1: sequential, N: at most N threads).
"""

import collections
import enum
import re
import warnings
from typing import NamedTuple

import numpy as np

from . import _core

__all__ = [
    "METHODS",
    "MeshCurvatures",
    "MeshCurvaturesWithRadius",
    "MeshReach",
    "PointSetCurvatures",
    "PointSetCurvaturesWithRadius",
    "PointSetReach",
    "RepairWarning",
    "Status",
    "TetrahedralCurvatures",
    "mesh_curvatures",
    "mesh_reach",
    "point_set_curvatures",
    "point_set_reach",
    "read_off",
    "tetrahedral_curvatures",
]

#: The status of a vertex, as the tool's CSV names it (values as in its PLY output).
Status = enum.IntEnum("Status", sorted(_core.STATUS.items(), key=lambda item: item[1]), module=__name__)
Status.__doc__ = """ok: estimated from the neighborhood asked for; widened: from a wider one;
failed: no estimate (NaN values); fallback: by the method's documented fallback."""

#: The methods of mesh_curvatures (the tool's -m), the default first.
METHODS = tuple(_core.METHODS)


class RepairWarning(UserWarning):
    """The faces had to be repaired (as the tool repairs a file) before they made a mesh."""


class MeshCurvatures(NamedTuple):
    """The tool's CSV columns: arrays of n values, d_max and d_min of shape (n, 3)."""

    k_max: np.ndarray
    k_min: np.ndarray
    mean: np.ndarray
    gaussian: np.ndarray
    d_max: np.ndarray
    d_min: np.ndarray
    status: np.ndarray


PointSetCurvatures = collections.namedtuple("PointSetCurvatures", MeshCurvatures._fields + ("normal",))
PointSetCurvatures.__doc__ = "As MeshCurvatures, and the unit normal of each point's fit (n, 3), oriented as the result."

_SELECTION_FIELDS = ("radius", "noise")
MeshCurvaturesWithRadius = collections.namedtuple("MeshCurvaturesWithRadius",
                                                  MeshCurvatures._fields + _SELECTION_FIELDS)
MeshCurvaturesWithRadius.__doc__ = """As MeshCurvatures, with radius="auto": the radius chosen per vertex and the noise
(the standard deviation of the heights' noise), in mesh units, as the tool's CSV columns radius and noise."""
PointSetCurvaturesWithRadius = collections.namedtuple("PointSetCurvaturesWithRadius",
                                                      PointSetCurvatures._fields + _SELECTION_FIELDS)
PointSetCurvaturesWithRadius.__doc__ = """As PointSetCurvatures, with radius="auto": the radius chosen per point and the
noise, in the points' units, as the tool's CSV columns radius and noise."""


class TetrahedralCurvatures(NamedTuple):
    """The tool's CSV columns of tetrahedral input: k_1 >= k_2 >= k_3, their mean and product."""

    k_1: np.ndarray
    k_2: np.ndarray
    k_3: np.ndarray
    mean: np.ndarray
    gaussian: np.ndarray
    status: np.ndarray


def mesh_curvatures(vertices, faces, method="paraboloid", *, rings=None, radius=None, order=None,
                    fit_degree=None, degree=None, monge_degree=None, normals=None, threads=0):
    """Curvature at the vertices of a surface mesh, as ``curvature -m METHOD -o out.csv``.

    vertices: (n, 3) float64 or float32; faces: (m, k) integers (k >= 3: triangles,
    quads, ...), indices from 0. method: one of METHODS. rings (--rings), radius
    (--radius: a length, or a string "Nx" for N mean edge lengths; "auto" or "auto:A:B"
    chooses it per vertex, as --radius auto, and gives a MeshCurvaturesWithRadius), order (--order),
    fit_degree (--fit-degree), degree and monge_degree (jet: --degree, --monge-degree):
    None is the tool's default. normals: (n, 3) vertex normals for the methods that
    read them (not jet), for a mesh that needs no repair. Faces that do not make a mesh
    as they are (duplicate points, degenerate faces, inconsistent orientation,
    non-manifold vertices) are repaired as the tool repairs them, with a RepairWarning
    saying what changed; a vertex in no face is failed. Bad input raises ValueError.
    """
    return _mesh_curvatures(vertices, faces, method, rings=rings, radius=radius, order=order, fit_degree=fit_degree,
                            degree=degree, monge_degree=monge_degree, normals=normals, threads=threads)[0]


def _mesh_curvatures(vertices, faces, method, *, rings=None, radius=None, order=None, fit_degree=None, degree=None,
                     monge_degree=None, normals=None, threads=0):
    """mesh_curvatures' result and, per vertex, the library's vertex_reach_map (how far the balls its
    estimate read reach; 0 over rings only, and at a vertex in no face)."""
    *values, repairs, selection, reach = _core.mesh_curvatures(vertices, faces, method, rings, radius, order,
                                                               fit_degree, degree, monge_degree, normals, threads)
    for repair in repairs:
        warnings.warn(repair, RepairWarning, stacklevel=3)
    if selection is not None:
        return MeshCurvaturesWithRadius(*values, *selection), reach
    return MeshCurvatures(*values), reach


def point_set_curvatures(points, *, number_of_neighbors=None, neighbor_radius=None, radius=None, fit_degree=2,
                         normals=None, unsigned=False, threads=0):
    """Curvature at the points of a point set (the library's point_set_curvatures).

    points: (n, 3) float64 or float32. The fit of fit_degree (2 to 4) over the
    number_of_neighbors nearest points (default 16, 32, 64 by degree) or the points
    within neighbor_radius; normals (n, 3), if given, orient the result, else the fitted
    normals are oriented consistently, or each point takes H >= 0 with unsigned=True.
    radius="auto" or "auto:A:B" (the tool's --radius auto: A and B lengths, or "Nx" for N
    mean distances to the nearest neighbor; default 2x:32x) chooses the ball per point
    instead of neighbor_radius and gives a PointSetCurvaturesWithRadius.
    """
    if radius is not None and not (isinstance(radius, str) and radius.startswith("auto")):
        raise ValueError(f"radius must be 'auto' or 'auto:A:B' (a fixed ball is neighbor_radius), got {radius!r}")
    *values, selection = _core.point_set_curvatures(points, number_of_neighbors, neighbor_radius, radius,
                                                    fit_degree, normals, unsigned, threads)
    if selection is not None:
        return PointSetCurvaturesWithRadius(*values, *selection)
    return PointSetCurvatures(*values)


class MeshReach(NamedTuple):
    """How far a method reads around a vertex (the library's neighborhood_reach): every vertex whose
    position can change its values lies within `rings` rings of faces of the vertices within `distance`
    of it, or `grown_distance` where a ball grew to condition its fit (status widened)."""

    rings: int
    distance: float
    grown_distance: float


class PointSetReach(NamedTuple):
    """How far point_set_curvatures reads around a point (the library's neighborhood_reach): its
    `neighbors` nearest points (`widened_neighbors` at a status other than ok), or the points within
    `distance` (`grown_distance` where the ball grew). Without normals the signs follow an orientation
    over the whole set."""

    neighbors: int
    widened_neighbors: int
    distance: float
    grown_distance: float


def mesh_reach(method="paraboloid", *, rings=None, radius=None, order=None, fit_degree=None, degree=None,
               monge_degree=None):
    """How far mesh_curvatures with these settings reads around each vertex, its normals and fallbacks
    included, as a MeshReach; radius: a length (not "Nx" or "auto"). Bad settings raise ValueError."""
    return MeshReach(*_core.neighborhood_reach(method, rings, radius, order, fit_degree, degree, monge_degree))


def point_set_reach(*, number_of_neighbors=None, neighbor_radius=None, fit_degree=2):
    """How far point_set_curvatures with these settings reads around each point, as a PointSetReach."""
    return PointSetReach(*_core.point_set_reach(number_of_neighbors, neighbor_radius, fit_degree))


def tetrahedral_curvatures(vertices, tetrahedra, scalars, *, rings=None, radius=None, fit_degree=None,
                           threads=0):
    """Curvature of the graph (x, y, z, f) in R^4 over a tetrahedral mesh, as the tool on a .mesh and its .sol.

    vertices: (n, 3) float64 or float32; tetrahedra: (m, 4) integers from 0; scalars:
    f, n values. Tetrahedra are oriented so that the normal points towards increasing
    f (a convex f has negative curvatures). rings, radius ("Nx": N mean edge lengths in
    R^4) and fit_degree (2 or 3) as the tool's options. A vertex in no tetrahedron is failed.
    """
    return TetrahedralCurvatures(*_core.tetrahedral_curvatures(vertices, tetrahedra, scalars, rings, radius,
                                                               fit_degree, threads))


def read_off(path):
    """The vertices (n, 3) float64 and faces (m, k) int64 of an ASCII OFF file, for mesh_curvatures.

    OFF as the tool reads it: a header [ST][C][N]OFF, the counts of vertices and faces
    (and edges, unused), a vertex a line (x y z, then values the header announces, not
    read), a face a line (k, k indices from 0, then an optional colour); '#' starts a
    comment. The faces must all have the same number of vertices. Raises ValueError
    where the file is not such an OFF.
    """
    with open(path, encoding="utf-8", errors="replace") as off:
        lines = [words for words in (line.split("#", 1)[0].split() for line in off) if words]
    if not lines or not re.fullmatch(r"(ST)?C?N?OFF", lines[0][0]) or "BINARY" in lines[0]:
        raise ValueError(f"{path}: not an ASCII OFF file (header {' '.join(lines[0]) if lines else 'missing'})")
    if len(lines[0]) > 1:  # the counts on the header's line
        counts, body = lines[0][1:], lines[1:]
    else:
        counts, body = (lines[1] if len(lines) > 1 else []), lines[2:]
    if len(counts) < 2:
        raise ValueError(f"{path}: no counts of vertices and faces after the header")
    n, m = int(counts[0]), int(counts[1])
    if len(body) < n + m:
        raise ValueError(f"{path}: the file ends before its {n} vertices and {m} faces")
    vertex_lines, face_lines = body[:n], body[n:n + m]
    sizes = {int(line[0]) for line in face_lines}
    if len(sizes) > 1:
        raise ValueError(f"{path}: faces of {sorted(sizes)} vertices: mesh_curvatures takes faces of one size")
    k = sizes.pop() if sizes else 3
    if any(len(line) < 3 for line in vertex_lines) or any(len(line) < 1 + k for line in face_lines):
        raise ValueError(f"{path}: a vertex line holds fewer than 3 values or a face line fewer than its indices")
    vertices = np.array([[float(w) for w in line[:3]] for line in vertex_lines], dtype=np.float64).reshape(n, 3)
    faces = np.array([[int(w) for w in line[1:1 + k]] for line in face_lines], dtype=np.int64).reshape(m, k)
    return vertices, faces
