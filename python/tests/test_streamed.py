# SPDX-License-Identifier: GPL-3.0-or-later
"""Tiles of a file (curvature_estimation.streamed): a 50k-vertex jittered grid written as a
binary PLY (and an OFF, and quads), read in chunks smaller than the input, cut into 3x3 and
4x4 tiles in a work directory and run: the stitched columns equal one process on the whole
mesh bit for bit, statuses included, for every method with rings and with a radius
(absolute and in mean edge lengths); point sets with given normals over k neighbors and over a radius too;
the same on a LocalCluster of 2 workers, one of them killed mid-run; bad files give one
error and no work directory."""

import os

import numpy as np
import pytest

import curvature_estimation as ce
from conftest import grid_graph, torus, write_off
from curvature_estimation import streamed as S
from curvature_estimation import tiles as T
from test_tiles import assert_same, case_id, whole, with_a_worker_killed

CASES = [
    ("paraboloid", {}),
    ("paraboloid", {"radius": "3x"}),
    ("paraboloid", {"radius": 0.03}),
    ("curve-network", {}),
    ("gauss-map", {}),
    ("gauss-map", {"radius": "2.5x"}),
    ("taubin", {"rings": 2}),
    ("chen-schmitt", {}),
    ("jet", {}),
    ("jet", {"radius": "3x"}),
]


def write_ply(path, vertices, faces=None, normals=None, coordinate="<f8", index="<i4"):
    """A binary little-endian PLY: x y z (and nx ny nz) of `coordinate`, faces as lists of uchar and `index`."""
    names = ["x", "y", "z"] + ([] if normals is None else ["nx", "ny", "nz"])
    ply_type = {"<f8": "double", "<f4": "float", "<i4": "int", "<u4": "uint"}
    header = ["ply", "format binary_little_endian 1.0", f"element vertex {len(vertices)}"]
    header += [f"property {ply_type[coordinate]} {name}" for name in names]
    if faces is not None:
        header += [f"element face {len(faces)}", f"property list uchar {ply_type[index]} vertex_indices"]
    columns = vertices if normals is None else np.column_stack([vertices, normals])
    with open(path, "wb") as out:
        out.write(("\n".join(header + ["end_header"]) + "\n").encode("ascii"))
        out.write(np.ascontiguousarray(columns, dtype=coordinate).tobytes())
        if faces is not None:
            rows = np.empty(len(faces), dtype=[("count", "u1"), ("index", index, (faces.shape[1],))])
            rows["count"], rows["index"] = faces.shape[1], faces
            out.write(rows.tobytes())


@pytest.fixture(scope="module")
def mesh(tiles_mesh):
    return tiles_mesh  # the mesh `whole` caches the results of


@pytest.fixture(scope="module")
def ply(mesh, tmp_path_factory):
    path = tmp_path_factory.mktemp("input") / "grid.ply"
    write_ply(path, *mesh)
    return str(path)


@pytest.fixture(autouse=True)
def small_chunks(monkeypatch):
    """Chunks far smaller than the inputs: every pass runs over many chunks."""
    monkeypatch.setattr(S, "CHUNK", 4096)


def tiled(path, directory, tiles, method="paraboloid", scheduler="serial", halo=None, **kwargs):
    manifest = S.write_tiles(path, str(directory), tiles, method, halo, **kwargs)
    done = S.run_directory(str(directory), scheduler)
    return S.read_columns(done.columns), done.run, manifest


@pytest.mark.parametrize("tiling", [(3, 3), (4, 4)], ids=lambda t: f"{t[0]}x{t[1]}")
@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_streamed_tiles_equal_one_process(mesh, ply, tmp_path, case, tiling):
    method, kwargs = case
    actual, run, manifest = tiled(ply, tmp_path / "work", tiling, method, **kwargs)
    expected = whole(mesh, method, kwargs)
    assert_same(actual, expected)
    assert run.tiles == tiling[0] * tiling[1] and run.overhead > 0
    assert np.count_nonzero(expected.status != ce.Status.failed) > 0.9 * len(expected.status)
    if isinstance(kwargs.get("radius"), str):  # the global mean edge length, summed from the tiles' edges
        assert manifest["mean_edge_length"] == T.mean_edge_length(*mesh)
        assert manifest["settings"]["radius"] == float(kwargs["radius"][:-1]) * T.mean_edge_length(*mesh)


def test_the_tiles_carry_global_index_owned_and_complete(mesh, ply, tmp_path):
    vertices, faces = mesh
    manifest = S.write_tiles(ply, str(tmp_path / "work"), (3, 3), "taubin", rings=2)
    expected = T.cut_tiles(vertices, faces, (3, 3), T.Halo(*manifest["halo"]))
    assert len(manifest["tile_files"]) == len(expected) == 9
    for entry, tile in zip(manifest["tile_files"], expected):
        with np.load(tmp_path / "work" / entry["path"]) as a:
            np.testing.assert_array_equal(a["vertices"], tile.vertices)
            np.testing.assert_array_equal(a["faces"], tile.faces)
            np.testing.assert_array_equal(a["owned"], tile.owned)
            np.testing.assert_array_equal(a["complete"], tile.complete)
            np.testing.assert_array_equal(a["points"], vertices[tile.vertices])


def test_off_float_coordinates_and_quads(mesh, tmp_path):
    vertices, faces = mesh
    off = tmp_path / "grid.off"
    write_off(off, vertices, faces)
    actual, _, _ = tiled(str(off), tmp_path / "off", (3, 3), "gauss-map", radius="2.5x")
    assert_same(actual, whole(mesh, "gauss-map", {"radius": "2.5x"}))

    single = vertices.astype(np.float32)
    write_ply(tmp_path / "float.ply", single, faces, coordinate="<f4", index="<u4")
    actual, _, _ = tiled(str(tmp_path / "float.ply"), tmp_path / "float", (4, 4), "jet")
    assert_same(actual, ce.mesh_curvatures(single.astype(np.float64), faces, "jet", threads=1))

    quads = torus(major=120, minor=60, quads=True)
    write_ply(tmp_path / "quads.ply", *quads)
    actual, _, _ = tiled(str(tmp_path / "quads.ply"), tmp_path / "quads", (3, 3), "paraboloid", radius="2x")
    assert_same(actual, ce.mesh_curvatures(*quads, "paraboloid", radius="2x", threads=1))


def test_a_narrow_halo_is_repaired_from_the_file(mesh, ply, tmp_path):
    actual, run, _ = tiled(ply, tmp_path / "work", (3, 3), "taubin", halo=T.Halo(2), rings=2)
    assert run.recuts > 0
    assert_same(actual, whole(mesh, "taubin", {"rings": 2}))


@pytest.fixture(scope="module")
def point_set(mesh, tmp_path_factory):
    """The grid's vertices with noise, and the normals of the graph they lie near."""
    vertices, _ = mesh
    points = vertices + np.random.default_rng(3).normal(0, 0.001, vertices.shape)
    x, y = vertices[:, 0], vertices[:, 1]
    normals = np.column_stack([-0.3 * np.cos(x) * np.cos(1.5 * y), 0.45 * np.sin(x) * np.sin(1.5 * y), np.ones(len(x))])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    path = tmp_path_factory.mktemp("points") / "points.ply"
    write_ply(path, points, normals=normals)
    return str(path), points, normals


@pytest.mark.parametrize("kwargs", [{}, {"fit_degree": 3}], ids=["k16", "degree3"])
def test_point_set_tiles_over_neighbors_equal_one_process(point_set, tmp_path, kwargs):
    path, points, normals = point_set
    actual, run, _ = tiled(path, tmp_path / "work", (3, 3), **kwargs)
    expected = ce.point_set_curvatures(points, normals=normals, threads=1, **kwargs)
    assert_same(actual, expected)
    assert np.count_nonzero(expected.status == ce.Status.ok) > 0.9 * len(points)


@pytest.mark.parametrize("radius", [0.03, 0.05])
def test_point_set_tiles_over_a_radius_equal_one_process(point_set, tmp_path, radius):
    """The points within a radius come in an order that the points outside the tile do not change
    (by distance, then by position), so the fits sum them as one process does."""
    path, points, normals = point_set
    actual, _, _ = tiled(path, tmp_path / "work", (3, 3), neighbor_radius=radius)
    expected = ce.point_set_curvatures(points, normals=normals, neighbor_radius=radius, threads=1)
    assert_same(actual, expected)
    assert np.count_nonzero(expected.status == ce.Status.ok) > 0.9 * len(points)


def test_a_point_set_without_normals_is_refused_unless_unsigned(point_set, tmp_path):
    _, points, _ = point_set
    write_ply(tmp_path / "bare.ply", points)
    with pytest.raises(S.InputError, match="orientation"):
        S.write_tiles(str(tmp_path / "bare.ply"), str(tmp_path / "work"), (3, 3))
    assert not os.path.exists(tmp_path / "work")
    actual, _, _ = tiled(str(tmp_path / "bare.ply"), tmp_path / "work", (3, 3), unsigned=True)
    assert_same(actual, ce.point_set_curvatures(points, unsigned=True, threads=1))


@pytest.mark.parametrize("damage, message", [
    (lambda b: b[:len(b) - 100], "truncated"),
    (lambda b: b.replace(b"binary_little_endian", b"binary_big_endian"), "binary_big_endian"),
    (lambda b: b.replace(b"end_header", b"end_heaven"), "not a PLY"),
    (lambda b: b.replace(b"property double y", b"property doubel y"), "unknown PLY type"),
    (lambda b: b + b"\0" * 10, "bytes"),
    (lambda b: b[:b.index(b"end_header\n") + 11] + np.float64(np.nan).tobytes() + b[b.index(b"end_header\n") + 19:],
     "not finite"),
])
def test_a_bad_file_gives_one_error_and_no_output(ply, tmp_path, damage, message):
    bad = tmp_path / "bad.ply"
    bad.write_bytes(damage(open(ply, "rb").read()))
    with pytest.raises(S.InputError, match=message):
        S.write_tiles(str(bad), str(tmp_path / "work"), (3, 3))
    assert sorted(os.listdir(tmp_path)) == ["bad.ply"]


def test_a_bad_off_gives_one_error_and_no_output(tmp_path):
    vertices, faces = grid_graph(n=20)
    write_off(tmp_path / "bad.off", vertices, faces)
    text = (tmp_path / "bad.off").read_text().splitlines()
    (tmp_path / "bad.off").write_text("\n".join(text[:-5]) + "\n")
    with pytest.raises(S.InputError, match="ends before"):
        S.write_tiles(str(tmp_path / "bad.off"), str(tmp_path / "work"), (2, 2))
    faces[7, 1] = len(vertices)
    write_off(tmp_path / "bad.off", vertices, faces)
    with pytest.raises(S.InputError, match="outside"):
        S.write_tiles(str(tmp_path / "bad.off"), str(tmp_path / "work"), (2, 2))
    assert sorted(os.listdir(tmp_path)) == ["bad.off"]


def test_the_command_writes_a_ply(mesh, ply, tmp_path, capsys):
    output = tmp_path / "out.ply"
    T.main([ply, "-m", "jet", "--tiles", "3x3", "--scheduler", "serial", "-o", str(output)])
    assert "9 tiles" in capsys.readouterr().out
    data = output.read_bytes()
    body = data[data.index(b"end_header\n") + len(b"end_header\n"):]
    fields = [(f"{f}_{c}", "<f8") for f in ("d_max", "d_min") for c in "xyz"]
    row = np.dtype([(f, "<f8") for f in ("k_max", "k_min", "mean", "gaussian")] + fields + [("status", "u1")])
    rows = np.frombuffer(body, dtype=row)
    expected = whole(mesh, "jet", {})
    assert_same(ce.MeshCurvatures(rows["k_max"], rows["k_min"], rows["mean"], rows["gaussian"],
                                  np.column_stack([rows["d_max_" + c] for c in "xyz"]),
                                  np.column_stack([rows["d_min_" + c] for c in "xyz"]), rows["status"]), expected)


def test_dask_with_a_worker_killed_mid_run(mesh, ply, tmp_path):
    """The streamed tiles on a LocalCluster of 2 worker processes, one killed once the first
    tile is in: its tasks run again elsewhere (a result file is written whole or not at all)."""
    S.write_tiles(ply, str(tmp_path / "work"), (4, 4), "paraboloid")
    done = with_a_worker_killed(lambda client, progress: S.run_directory(str(tmp_path / "work"), client,
                                                                         progress=progress))
    assert done.run.tiles == 16
    assert_same(S.read_columns(done.columns), whole(mesh, "paraboloid", {}))


def test_the_command_on_an_xyz_writes_npy_columns(point_set, tmp_path, capsys):
    _, points, normals = point_set
    rows = np.column_stack([points, normals])
    (tmp_path / "points.xyz").write_text("\n".join(" ".join(repr(float(x)) for x in row) for row in rows) + "\n")
    output = tmp_path / "columns"
    T.main([str(tmp_path / "points.xyz"), "--tiles", "6000", "--scheduler", "serial", "-o", str(output)])
    assert f"{len(points)} vertices" in capsys.readouterr().out
    assert_same(S.read_columns(str(output)), ce.point_set_curvatures(points, normals=normals, threads=1))
    with pytest.raises(FileExistsError):  # columns are never written over an existing directory
        T.main([str(tmp_path / "points.xyz"), "--scheduler", "serial", "-o", str(output)])
