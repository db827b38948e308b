# SPDX-License-Identifier: GPL-3.0-or-later
"""Inputs: the conversions accepted (float32, int32, non-contiguous, lists) give the same values;
bad input raises ValueError with a message naming what is wrong, never a crash."""

import numpy as np
import pytest

import curvature_estimation as ce
from conftest import assert_bit_identical, grid_graph
from test_bit_identity import tetrahedral_grid


def values(r):
    return np.column_stack([np.asarray(field, dtype=np.float64).reshape(len(r.status), -1)
                            for field in r if field is not r.status])


@pytest.fixture(scope="module")
def mesh():
    return grid_graph(n=9, jitter=0.3)


@pytest.fixture(scope="module")
def expected(mesh):
    return ce.mesh_curvatures(*mesh)


def test_conversions(mesh, expected):
    vertices, faces = mesh
    strided = np.zeros((len(vertices), 6))
    strided[:, ::2] = vertices
    for v, f in [(vertices[:, :].copy(order="F"), faces),  # Fortran order
                 (strided[:, ::2], faces[::1, :]),  # non-contiguous rows
                 (vertices, faces.astype(np.int32)),
                 (vertices, faces.astype(np.uint32)),
                 (vertices.tolist(), faces.tolist())]:
        r = ce.mesh_curvatures(v, f)
        assert_bit_identical(values(r), values(expected))
        np.testing.assert_array_equal(r.status, expected.status)


def test_float32_is_its_float64_value(mesh):
    vertices, faces = mesh
    single = vertices.astype(np.float32)
    assert_bit_identical(values(ce.mesh_curvatures(single, faces)),
                         values(ce.mesh_curvatures(single.astype(np.float64), faces)))


def test_output_types(mesh, expected):
    n = len(mesh[0])
    for name in ("k_max", "k_min", "mean", "gaussian"):
        assert getattr(expected, name).dtype == np.float64 and getattr(expected, name).shape == (n,)
    assert expected.d_max.shape == expected.d_min.shape == (n, 3)
    assert expected.status.shape == (n,) and expected.status.dtype == np.uint8
    assert set(expected.status) <= {int(s) for s in ce.Status}
    assert [s.name for s in ce.Status] == ["ok", "widened", "failed", "fallback"]


def refuses(match, function, *args, **kwargs):
    with pytest.raises(ValueError, match=match):
        function(*args, **kwargs)


def test_bad_mesh_arrays(mesh):
    vertices, faces = mesh
    nan = vertices.copy()
    nan[5, 1] = np.nan
    inf = vertices.copy()
    inf[6, 2] = -np.inf
    negative = faces.copy()
    negative[3, 1] = -1
    beyond = faces.copy()
    beyond[4, 2] = len(vertices)
    cases = [
        ("vertices must have the shape \\(n, 3\\), got \\(81, 2\\)", vertices[:, :2], faces),
        ("vertices must have the shape", vertices.ravel(), faces),
        ("vertices must be float64 or float32, got int64", vertices.astype(np.int64), faces),
        ("vertices must be float64 or float32, got float16", vertices.astype(np.float16), faces),
        ("vertices must be float64 or float32, got complex128", vertices.astype(complex), faces),
        ("vertices must have the shape \\(n, 3\\), got \\(\\)", object(), faces),
        ("vertices is empty", np.zeros((0, 3)), faces),
        ("vertices row 5 holds a non-finite value", nan, faces),
        ("vertices row 6 holds a non-finite value", inf, faces),
        ("faces must be an integer array", vertices, faces.astype(np.float64)),
        ("faces must be an integer array", vertices, faces.astype(bool)),
        ("faces must have the shape \\(m, k >= 3\\), got \\(128, 2\\)", vertices, faces[:, :2]),
        ("faces must have the shape", vertices, faces.ravel()),
        ("faces is empty", vertices, np.zeros((0, 3), dtype=np.int64)),
        ("faces row 3 holds the negative index -1", vertices, negative),
        ("faces row 4 refers to vertex 81 but there are 81 vertices", vertices, beyond),
        ("faces row 4 refers to vertex 81", vertices, beyond.astype(np.uint64)),
    ]
    for match, v, f in cases:
        refuses(match, ce.mesh_curvatures, v, f)


def test_bad_parameters(mesh):
    """The tool's option checks, their messages naming the keywords (rings), not the tool's flags (--rings)."""
    v, f = mesh
    refuses("unknown method 'hamann' \\(expected one of paraboloid, curve-network", ce.mesh_curvatures, v, f, "hamann")
    refuses("^rings applies to", ce.mesh_curvatures, v, f, "curve-network", rings=2)
    refuses("^radius applies to the .* methods only, not to 'taubin'$", ce.mesh_curvatures, v, f, "taubin", radius=0.5)
    refuses("^radius and rings exclude each other", ce.mesh_curvatures, v, f, radius=0.5, rings=2)
    refuses("^fit_degree applies to the paraboloid method only \\(degree is the jet's\\)$", ce.mesh_curvatures, v, f,
            "jet", fit_degree=3)
    refuses("fit_degree must be an integer from 2 to 4, got 5", ce.mesh_curvatures, v, f, fit_degree=5)
    refuses("rings must be an integer from 1 to 100, got 0", ce.mesh_curvatures, v, f, rings=0)
    refuses("^monge_degree 3 exceeds the jet degree 2 \\(see degree\\)$", ce.mesh_curvatures, v, f, "jet",
            monge_degree=3)
    refuses("radius expects a positive length", ce.mesh_curvatures, v, f, radius="four")
    refuses("radius expects a positive length", ce.mesh_curvatures, v, f, radius="-2x")
    refuses("radius must be a positive finite length, got -1.0", ce.mesh_curvatures, v, f, radius=-1.0)
    refuses("radius must be a positive finite length, got nan", ce.mesh_curvatures, v, f, radius=float("nan"))
    refuses("radius must be a number or a string", ce.mesh_curvatures, v, f, radius=True)
    refuses("radius expects a length, auto, or auto:A:B", ce.mesh_curvatures, v, f, radius="auto:2x")
    refuses("radius auto:0x:2x expects a positive length", ce.mesh_curvatures, v, f, radius="auto:0x:2x")
    refuses("radius auto:A:B needs A <= B", ce.mesh_curvatures, v, f, radius="auto:4x:2x")
    refuses("^radius auto applies to the .* methods only, not to 'taubin'$", ce.mesh_curvatures, v, f, "taubin",
            radius="auto")
    refuses("^radius and rings exclude each other", ce.mesh_curvatures, v, f, radius="auto", rings=2)
    refuses("threads must be 0", ce.mesh_curvatures, v, f, threads=-1)
    with pytest.raises(TypeError):
        ce.mesh_curvatures(v, f, rings=1.5)


def test_normals(mesh):
    vertices, faces = mesh
    up = np.tile([0.0, 0.0, 1.0], (len(vertices), 1))
    with_up = ce.mesh_curvatures(vertices, faces, normals=up)
    default = ce.mesh_curvatures(vertices, faces)
    # the given normals are read: the values change, and are finite where estimated
    assert not np.array_equal(with_up.mean, default.mean)
    assert np.isfinite(with_up.mean[with_up.status != ce.Status.failed]).all()
    refuses("normals must have a row per vertex \\(81\\), got 80", ce.mesh_curvatures, vertices, faces,
            normals=up[:-1])
    refuses("normals must have the shape", ce.mesh_curvatures, vertices, faces, normals=up[:, :2])
    nan = up.copy()
    nan[0, 0] = np.nan
    refuses("normals row 0 holds a non-finite value", ce.mesh_curvatures, vertices, faces, normals=nan)
    refuses("does not read vertex_normal_map", ce.mesh_curvatures, vertices, faces, "jet", normals=up)
    flipped = faces.copy()
    flipped[0] = flipped[0][::-1]
    refuses("normals are taken only for a mesh that needs no repair, and this one does: repaired the input: "
            "re-oriented [0-9]+ faces", ce.mesh_curvatures, vertices, flipped, normals=up)


def test_non_manifold_is_repaired_with_a_warning():
    """Two tetrahedra's surfaces sharing one vertex (a pinch): the tool duplicates the vertex."""
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1.0]])
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3],
                      [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]])
    with pytest.warns(ce.RepairWarning, match="duplicated 1 non-manifold vertices"):
        r = ce.mesh_curvatures(vertices, faces)
    assert r.status.shape == (7,)


def test_bad_tetrahedral_input():
    vertices, tetrahedra, scalars = tetrahedral_grid(n=3)
    f = ce.tetrahedral_curvatures
    flat = np.vstack([tetrahedra, [[0, 1, 2, 0]]])
    coplanar = np.vstack([tetrahedra, [[0, 1, 2, 3]]])  # 0, 1, 2 on a line of the grid
    twice = np.vstack([tetrahedra, tetrahedra[3][::-1]])
    refuses(f"tetrahedra row {len(tetrahedra)} has zero volume", f, vertices, flat, scalars)
    refuses(f"tetrahedra row {len(tetrahedra)} has zero volume", f, vertices, coplanar, scalars)
    refuses(f"tetrahedra rows 3 and {len(tetrahedra)} have the same four vertices", f, vertices, twice, scalars)
    refuses("tetrahedra must have the shape \\(n, 4\\)", f, vertices, tetrahedra[:, :3], scalars)
    refuses("tetrahedra row 0 holds the negative index", f, vertices, tetrahedra - 1, scalars)
    refuses("scalars must have a value per vertex \\(27\\), got 26", f, vertices, tetrahedra, scalars[:-1])
    refuses("scalars must have the shape \\(n,\\), got \\(27, 1\\)", f, vertices, tetrahedra, scalars[:, None])
    nan = scalars.copy()
    nan[2] = np.nan
    refuses("scalars row 2 holds a non-finite value", f, vertices, tetrahedra, nan)
    refuses("^fit_degree 4 is for surfaces", f, vertices, tetrahedra, scalars, fit_degree=4)
    refuses("^radius and rings exclude", f, vertices, tetrahedra, scalars, radius="2x", rings=2)


def test_bad_point_sets():
    points = np.random.default_rng(3).normal(size=(50, 3))
    f = ce.point_set_curvatures
    refuses("give number_of_neighbors or neighbor_radius, not both", f, points, number_of_neighbors=8,
            neighbor_radius=1.0)
    refuses("number_of_neighbors must be at least 3", f, points, number_of_neighbors=2)
    refuses("number_of_neighbors must be at least 3", f, points, number_of_neighbors=-4)
    refuses("neighbor_radius must be positive and finite", f, points, neighbor_radius=-1.0)
    refuses("fit_degree", f, points, fit_degree=7)
    refuses("points is empty", f, np.zeros((0, 3)))
    refuses("normals must have a row per point \\(50\\), got 3", f, points, normals=points[:3])
    refuses("radius must be 'auto' or 'auto:A:B'", f, points, radius=0.5)
    refuses("radius must be 'auto' or 'auto:A:B'", f, points, radius="2x")
    refuses("radius expects a length, auto, or auto:A:B", f, points, radius="auto:")
    refuses("radius auto:A:B needs A <= B: here A is .* in the points' units$", f, points, radius="auto:8x:2x")
    refuses("give neighbor_radius or radius, not both", f, points, neighbor_radius=1.0, radius="auto")


def test_read_off(tmp_path):
    """read_off: comments, counts on the header's line, colours after a face; faces of two sizes refused."""
    path = tmp_path / "mesh.off"
    path.write_text("OFF 4 2 0 # counts here\n0 0 0\n1 0 0\n# a comment\n0 1 0\n1 1 0.5\n3 0 1 2 255 0 0\n3 1 3 2\n")
    vertices, faces = ce.read_off(path)
    np.testing.assert_array_equal(vertices, [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.5]])
    np.testing.assert_array_equal(faces, [[0, 1, 2], [1, 3, 2]])
    assert vertices.dtype == np.float64 and faces.dtype == np.int64
    path.write_text("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n4 0 1 3 2\n")
    refuses("faces of \\[3, 4\\] vertices: mesh_curvatures takes faces of one size", ce.read_off, path)
    path.write_text("PLY\n")
    refuses("not an ASCII OFF file", ce.read_off, path)
    path.write_text("OFF\n4 2 0\n0 0 0\n")
    refuses("the file ends before its 4 vertices and 2 faces", ce.read_off, path)
