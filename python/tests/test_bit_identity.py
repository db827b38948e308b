# SPDX-License-Identifier: GPL-3.0-or-later
"""The module's values are the tool's, bit for bit: every method, with its options, on meshes
made here (regular, jittered, closed, quads, needing repair) and on the bunny; tetrahedral input."""

import numpy as np
import pytest

import curvature_estimation as ce
from conftest import (assert_bit_identical, grid_graph, run_tool, text, torus, write_medit, write_off)

SURFACE_HEADER = "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status".split(",")

# (method, keyword arguments of mesh_curvatures, the tool's options)
CASES = [
    ("paraboloid", {}, []),
    ("paraboloid", {"fit_degree": 3}, ["--fit-degree", 3]),
    ("paraboloid", {"fit_degree": 4}, ["--fit-degree", 4]),
    ("paraboloid", {"rings": 2}, ["--rings", 2]),
    ("paraboloid", {"radius": "3x"}, ["--radius", "3x"]),
    ("paraboloid", {"radius": 0.05, "fit_degree": 3}, ["--radius", "0.05", "--fit-degree", 3]),
    ("curve-network", {}, []),
    ("curve-network", {"order": 2}, ["--order", 2]),
    ("gauss-map", {}, []),
    ("gauss-map", {"radius": "2.5x"}, ["--radius", "2.5x"]),
    ("taubin", {}, []),
    ("taubin", {"rings": 2}, ["--rings", 2]),
    ("chen-schmitt", {}, []),
    ("jet", {}, []),
    ("jet", {"degree": 3, "monge_degree": 3}, ["--degree", 3, "--monge-degree", 3]),
    ("jet", {"radius": "3x"}, ["--radius", "3x"]),
]


def case_id(case):
    method, kwargs, _ = case
    return method + "".join(f"-{k}={v}" for k, v in kwargs.items())


def test_every_method_is_tested():
    assert {case[0] for case in CASES} == set(ce.METHODS)


def compare(tmp_path, vertices, faces, method, kwargs, options, threads=0):
    path = tmp_path / "mesh.off"
    write_off(path, vertices, faces)
    header, values, status, _ = run_tool(tmp_path, path, "-m", method, "--threads", threads, *options)
    assert header == SURFACE_HEADER
    r = ce.mesh_curvatures(vertices, faces, method, threads=threads, **kwargs)
    assert r._fields == ("k_max", "k_min", "mean", "gaussian", "d_max", "d_min", "status")
    actual = np.column_stack([r.k_max, r.k_min, r.mean, r.gaussian, r.d_max, r.d_min])
    assert_bit_identical(actual, values)
    np.testing.assert_array_equal(r.status, status)
    return r


@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_jittered_grid(tmp_path, case):
    vertices, faces = grid_graph(n=13, jitter=0.4)
    r = compare(tmp_path, vertices, faces, *case)
    # Not a vacuous comparison: the most of the vertices are estimated.
    assert np.count_nonzero(r.status != ce.Status.failed) > 0.9 * len(vertices)


@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_bunny(tmp_path, bunny, case):
    compare(tmp_path, *bunny, *case)


@pytest.mark.parametrize("method", ce.METHODS)
def test_closed_torus_sequential(tmp_path, method):
    compare(tmp_path, *torus(), method, {}, [], threads=1)


@pytest.mark.parametrize("method", ["paraboloid", "gauss-map", "taubin"])
def test_quad_faces(tmp_path, method):
    vertices, faces = torus(quads=True)
    assert faces.shape[1] == 4
    compare(tmp_path, vertices, faces, method, {}, [])


def test_mesh_needing_repair(tmp_path):
    """A duplicated point, a flipped face and a vertex in no face: repaired, with the tool's note as a warning."""
    vertices, faces = grid_graph(n=9)
    vertices = np.vstack([vertices, vertices[40], [5.0, 5.0, 5.0]])  # 81: a copy of 40; 82: in no face
    faces = faces.copy()
    faces[faces == 40] = np.where(np.arange(faces.size).reshape(faces.shape)[faces == 40] % 2 == 0, 40, 81)
    faces[7] = faces[7][::-1]
    path = tmp_path / "mesh.off"
    write_off(path, vertices, faces)
    _, values, status, stderr = run_tool(tmp_path, path)
    with pytest.warns(ce.RepairWarning) as caught:
        r = ce.mesh_curvatures(vertices, faces)
    notes = [str(w.message) for w in caught]
    assert notes == [line.removeprefix("curvature: note: ") for line in stderr.splitlines()]
    assert any("merged 1 duplicate points" in n for n in notes) and any("re-oriented" in n for n in notes)
    assert_bit_identical(np.column_stack([r.k_max, r.k_min, r.mean, r.gaussian, r.d_max, r.d_min]), values)
    np.testing.assert_array_equal(r.status, status)
    assert r.status[82] == ce.Status.failed and np.isnan(r.mean[82])


def tetrahedral_grid(n=6, seed=2):
    """The cubes of an n^3 grid of [-1, 1]^3, 6 tetrahedra each (Kuhn), f = |p|^2 / 2 with noise."""
    axis = np.linspace(-1, 1, n)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    vertices = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    index = np.arange(n ** 3).reshape(n, n, n)
    tetrahedra = []
    paths = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for i in range(n - 1):
        for j in range(n - 1):
            for k in range(n - 1):
                for path in paths:
                    corner = [i, j, k]
                    tet = [index[tuple(corner)]]
                    for axis_step in path:
                        corner[axis_step] += 1
                        tet.append(index[tuple(corner)])
                    tetrahedra.append(tet)
    rng = np.random.default_rng(seed)
    scalars = 0.5 * (vertices ** 2).sum(axis=1) + 0.005 * rng.uniform(-1, 1, len(vertices))
    return vertices, np.array(tetrahedra, dtype=np.int64), scalars


@pytest.mark.parametrize("kwargs,options", [({}, []), ({"rings": 2}, ["--rings", 2]),
                                            ({"fit_degree": 3}, ["--fit-degree", 3]),
                                            ({"radius": "2x"}, ["--radius", "2x"])], ids=str)
def test_tetrahedral(tmp_path, kwargs, options):
    vertices, tetrahedra, scalars = tetrahedral_grid()
    # a vertex in no tetrahedron: failed, as in the tool
    vertices = np.vstack([vertices, [3.0, 3.0, 3.0]])
    scalars = np.append(scalars, 1.0)
    write_medit(tmp_path / "volume.mesh", tmp_path / "volume.sol", vertices, tetrahedra, scalars)
    header, values, status, _ = run_tool(tmp_path, tmp_path / "volume.mesh", *options)
    assert header == "k_1,k_2,k_3,mean,gaussian,status".split(",")
    r = ce.tetrahedral_curvatures(vertices, tetrahedra, scalars, **kwargs)
    assert_bit_identical(np.column_stack([r.k_1, r.k_2, r.k_3, r.mean, r.gaussian]), values)
    np.testing.assert_array_equal(r.status, status)
    assert r.status[-1] == ce.Status.failed
    # a convex f has negative curvatures (the README's convention), away from the boundary
    inner = np.all(np.abs(vertices) < 0.5, axis=1)
    assert np.all(r.mean[inner] < 0)


def noisy(vertices, fraction, seed=2):
    """The vertices moved by Gaussian noise of `fraction` of their bounding box's diagonal."""
    diagonal = np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))
    return vertices + np.random.default_rng(seed).normal(scale=fraction * diagonal, size=vertices.shape)


@pytest.mark.parametrize("method, kwargs, options", [
    ("paraboloid", {"radius": "auto"}, ["--radius", "auto"]),
    ("paraboloid", {"radius": "auto:2x:8x", "fit_degree": 3}, ["--radius", "auto:2x:8x", "--fit-degree", 3]),
    ("jet", {"radius": "auto:0.05:0.6"}, ["--radius", "auto:0.05:0.6"]),
], ids=["auto", "auto-2x-8x-degree-3", "jet-auto-units"])
def test_auto_radius_on_a_noisy_torus(tmp_path, method, kwargs, options):
    """radius="auto": the tool's CSV with its radius and noise columns, bit for bit."""
    vertices, faces = torus(major=48, minor=24)
    vertices = noisy(vertices, 0.002)
    path = tmp_path / "mesh.off"
    write_off(path, vertices, faces)
    header, values, status, _ = run_tool(tmp_path, path, "-m", method, *options)
    assert header == SURFACE_HEADER[:-1] + ["radius", "noise", "status"]
    r = ce.mesh_curvatures(vertices, faces, method, **kwargs)
    assert isinstance(r, ce.MeshCurvaturesWithRadius)
    assert r._fields == ("k_max", "k_min", "mean", "gaussian", "d_max", "d_min", "status", "radius", "noise")
    actual = np.column_stack([r.k_max, r.k_min, r.mean, r.gaussian, r.d_max, r.d_min, r.radius, r.noise])
    assert_bit_identical(actual, values)
    np.testing.assert_array_equal(r.status, status)
    assert np.all(np.isfinite(r.radius)) and np.all(np.isfinite(r.noise))


POINT_SET_HEADER = SURFACE_HEADER[:-1] + ["nx", "ny", "nz", "radius", "noise", "status"]


@pytest.mark.parametrize("kwargs, options", [
    ({"radius": "auto"}, ["--radius", "auto"]),
    ({"radius": "auto:4x:16x", "fit_degree": 3, "number_of_neighbors": 40},
     ["--radius", "auto:4x:16x", "--fit-degree", 3, "--neighbors", 40]),
    ({"radius": "auto:0.05:0.4", "threads": 1}, ["--radius", "auto:0.05:0.4", "--threads", 1]),
], ids=["auto", "auto-4x-16x-degree-3-k40", "auto-units-sequential"])
def test_auto_radius_on_a_noisy_point_set(tmp_path, kwargs, options):
    """point_set_curvatures(radius="auto"): the tool's CSV of the .xyz with its radius and noise columns, bit for bit."""
    vertices, _ = torus(major=64, minor=32)
    points = noisy(vertices, 0.002)
    path = tmp_path / "points.xyz"
    path.write_text("".join(" ".join(text(c) for c in p) + "\n" for p in points))
    header, values, status, _ = run_tool(tmp_path, path, *options)
    assert header == POINT_SET_HEADER
    r = ce.point_set_curvatures(points, **kwargs)
    assert isinstance(r, ce.PointSetCurvaturesWithRadius)
    actual = np.column_stack([r.k_max, r.k_min, r.mean, r.gaussian, r.d_max, r.d_min, r.normal, r.radius, r.noise])
    assert_bit_identical(actual, values)
    np.testing.assert_array_equal(r.status, status)
    assert np.count_nonzero(np.isfinite(r.noise)) > 0.9 * len(points)
