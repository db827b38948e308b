# SPDX-License-Identifier: GPL-3.0-or-later
"""Tiles with halos (curvature_estimation.tiles): the tiled run equals one process bit for
bit, statuses included, for every method with rings and with a radius (absolute and in
mean edge lengths) on 3x3 and 4x4 tiles of a jittered 50k-vertex grid; a halo one ring too
narrow makes differences that the check flags, every one, and the re-cut repairs, as do
balls grown past any halo known before the run; the same tiles on a LocalCluster of 2
worker processes give the serial driver's result."""

import os
import signal

import numpy as np
import pytest

import curvature_estimation as ce
from conftest import assert_bit_identical
from curvature_estimation import tiles as T

# (method, keyword arguments of mesh_curvatures)
CASES = [
    ("paraboloid", {}),
    ("paraboloid", {"fit_degree": 3}),
    ("paraboloid", {"fit_degree": 4}),
    ("paraboloid", {"rings": 2}),
    ("paraboloid", {"radius": "3x"}),
    ("paraboloid", {"radius": 0.03}),
    ("curve-network", {}),
    ("gauss-map", {}),
    ("gauss-map", {"radius": "2.5x"}),
    ("taubin", {}),
    ("taubin", {"rings": 2}),
    ("chen-schmitt", {}),
    ("jet", {}),
    ("jet", {"radius": "3x"}),
]
TILINGS = [(3, 3), (4, 4)]


def case_id(case):
    method, kwargs = case
    return method + "".join(f"-{k}={v}" for k, v in kwargs.items())


@pytest.fixture(scope="module")
def mesh(tiles_mesh):
    return tiles_mesh  # the mesh `whole` caches the results of


_whole = {}


def whole(mesh, method, kwargs):
    """One process on the whole mesh, once per case."""
    key = case_id((method, kwargs))
    if key not in _whole:
        _whole[key] = ce.mesh_curvatures(*mesh, method, threads=1, **kwargs)
    return _whole[key]


def values(result):
    """The float columns of a result (all but status)."""
    return [a for f, a in zip(result._fields, result) if f != "status"]


def assert_same(actual, expected):
    assert actual._fields == expected._fields
    for a, e in zip(values(actual), values(expected)):
        assert_bit_identical(a, e)
    np.testing.assert_array_equal(actual.status, expected.status)


def differing(actual, expected):
    """The vertices where `actual` and `expected` differ in any bit or status."""
    same = actual.status == expected.status
    for a, e in zip(values(actual), values(expected)):
        a, e = a.reshape(len(same), -1), e.reshape(len(same), -1)
        same &= ((a.view(np.uint64) == e.view(np.uint64)) | (np.isnan(a) & np.isnan(e))).all(axis=1)
    return np.flatnonzero(~same)


def test_every_method_is_tested():
    assert {case[0] for case in CASES} == set(ce.METHODS)
    assert {"rings", "radius"} <= {k for _, kwargs in CASES for k in kwargs}


def test_the_reach_reads_the_settings_as_the_estimators_do():
    """mesh_reach and point_set_reach (the library's neighborhood_reach) refuse what the estimators
    refuse, and widen with the settings that widen the fits: at degree 4 the normals' fits read 4 rings."""
    assert ce.mesh_reach("paraboloid", fit_degree=4).rings == ce.mesh_reach("paraboloid").rings + 1
    ball = ce.mesh_reach("gauss-map", radius=0.02)
    assert (ball.rings, ball.distance, ball.grown_distance) == (1, 0.04, 0.08)  # its normals' balls: twice r
    for method, bad in [("taubin", {"radius": 0.1}), ("paraboloid", {"radius": "3x"}),
                        ("paraboloid", {"order": 2}), ("no-such-method", {})]:
        with pytest.raises(ValueError):
            ce.mesh_reach(method, **bad)
    k = ce.point_set_reach(fit_degree=3)
    assert (k.neighbors, k.widened_neighbors, k.distance) == (32, 128, 0.0)  # the documented default k, then 4k
    with pytest.raises(ValueError):
        ce.point_set_reach(number_of_neighbors=16, neighbor_radius=0.1)


def test_tiles_partition_the_vertices_and_keep_their_order(mesh):
    vertices, faces = mesh
    tiles = T.cut_tiles(vertices, faces, (3, 3), T.Halo(2))
    assert len(tiles) == 9
    owned = np.concatenate([t.vertices[t.owned] for t in tiles])
    np.testing.assert_array_equal(np.sort(owned), np.arange(len(vertices)))
    degree = np.bincount(faces.ravel(), minlength=len(vertices))
    face_rows = {tuple(f) for f in faces.tolist()}
    for t in tiles:
        assert np.all(np.diff(t.vertices) > 0)  # ascending global indices: the global relative order
        assert t.complete[t.owned].all()
        global_faces = t.vertices[t.faces]
        assert {tuple(f) for f in global_faces.tolist()} <= face_rows
        # complete: every face of the vertex is in the tile, no more, no less
        counts = np.bincount(t.faces.ravel(), minlength=len(t.vertices))
        np.testing.assert_array_equal(t.complete, counts == degree[t.vertices])
        assert not t.complete.all()  # a halo has an edge


@pytest.mark.parametrize("tiling", TILINGS, ids=lambda t: f"{t[0]}x{t[1]}")
@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_tiled_equals_one_process(mesh, case, tiling):
    method, kwargs = case
    expected = whole(mesh, method, kwargs)
    actual, run = T.run_tiles(*mesh, method, tiles=tiling, **kwargs)
    assert_same(actual, expected)
    assert run.tiles == tiling[0] * tiling[1] and run.overhead > 0
    # Not a vacuous comparison: most vertices are estimated.
    assert np.count_nonzero(expected.status != ce.Status.failed) > 0.9 * len(expected.status)


@pytest.mark.parametrize("case", [("gauss-map", {}), ("taubin", {"rings": 2}), ("gauss-map", {"radius": "2.5x"})],
                         ids=case_id)
def test_a_narrow_halo_is_flagged_and_repaired(mesh, case):
    method, kwargs = case
    vertices, faces = mesh
    expected = whole(mesh, method, kwargs)
    settings = dict(kwargs)
    if "radius" in settings:
        settings["radius"] = 2.5 * T.mean_edge_length(vertices, faces)
    needed = T.reach_of(method, **settings)
    narrow = T.Halo(needed.rings, needed.distance / 2) if needed.distance else T.Halo(needed.rings - 1)
    actual = ce.MeshCurvatures(*(np.empty_like(a) for a in expected))
    flagged = []
    for tile in T.cut_tiles(vertices, faces, (3, 3), narrow):
        owned, values, flags, _, _ = T.run_tile(vertices[tile.vertices], tile, method, settings, needed)
        for column, value in zip(actual, values):
            column[owned] = value
        flagged.append(flags)
    flagged = np.concatenate(flagged)
    wrong = differing(actual, expected)
    assert len(wrong) > 0  # the halo is too narrow: the control can fail
    assert np.isin(wrong, flagged).all()
    repaired, run = T.run_tiles(vertices, faces, method, tiles=(3, 3), halo=narrow, **kwargs)
    assert run.recuts > 0
    assert_same(repaired, expected)


@pytest.fixture(scope="module")
def sparse_band():
    """A Delaunay mesh of random points over the unit square, 40 times sparser (6 times the spacing)
    in a band across the cut between the first two columns of 3x3 tiles than elsewhere: there, balls
    of 2.5 mean edges grow for lack of vertices past the reach known before the run."""
    from scipy.spatial import Delaunay
    rng = np.random.default_rng(47)
    xy = rng.random((24000, 2))
    band = (xy[:, 0] > 0.2) & (xy[:, 0] < 0.45)
    xy = xy[~band | (rng.random(len(xy)) < 1 / 40)]
    vertices = np.column_stack([xy, 0.2 * np.sin(3 * xy[:, 0]) * np.cos(2 * xy[:, 1])])
    faces = Delaunay(xy).simplices.astype(np.int64)
    a, b, c = (xy[faces[:, k]] for k in range(3))
    clockwise = np.cross(b - a, c - a) < 0
    faces[clockwise] = faces[clockwise][:, ::-1]  # every face counterclockwise: a mesh that needs no repair
    return vertices, faces


def test_balls_grown_past_the_reach_are_flagged_and_repaired(sparse_band):
    """With the halo of the reach known before the run, the owned vertices whose balls (the Gauss
    map's and its normals') grew past it differ from one process; the check flags every one of them
    (by the library's per-vertex reach), and the re-cut repairs the run. (The paraboloid fit's and jet
    fitting's halos also hold the rings of their fallbacks, which on this mesh hold their grown balls.)"""
    method = "gauss-map"
    vertices, faces = sparse_band
    radius = 2.5 * T.mean_edge_length(vertices, faces)
    expected, reach = ce._mesh_curvatures(vertices, faces, method, radius=radius, threads=1)
    needed = T.reach_of(method, radius=radius)
    assert reach.max() > needed.grown_distance  # no halo known before the run holds every ball
    actual = ce.MeshCurvatures(*(np.empty_like(a) for a in expected))
    flagged = []
    for tile in T.cut_tiles(vertices, faces, (3, 3), T.Halo.around(needed)):
        owned, values, flags, _, _ = T.run_tile(vertices[tile.vertices], tile, method, {"radius": radius}, needed)
        for column, value in zip(actual, values):
            column[owned] = value
        flagged.append(flags)
    flagged = np.concatenate(flagged)
    wrong = differing(actual, expected)
    assert len(wrong) > 0  # the control can fail
    assert np.isin(wrong, flagged).all()
    repaired, run = T.run_tiles(vertices, faces, method, tiles=(3, 3), radius=radius)
    assert run.recuts > 0
    assert_same(repaired, expected)


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as c:
        yield c


@pytest.mark.parametrize("case", [("paraboloid", {}), ("gauss-map", {"radius": "2.5x"}), ("jet", {})], ids=case_id)
def test_dask_equals_the_serial_driver(mesh, client, case):
    method, kwargs = case
    serial, _ = T.run_tiles(*mesh, method, tiles=(4, 4), **kwargs)
    on_dask, run = T.run_tiles(*mesh, method, tiles=(4, 4), scheduler=client, **kwargs)
    assert_same(on_dask, serial)
    assert_same(on_dask, whole(mesh, method, kwargs))
    assert run.tiles == 16


def test_dask_repairs_a_narrow_halo(mesh, client):
    expected = whole(mesh, "taubin", {"rings": 2})
    actual, run = T.run_tiles(*mesh, "taubin", rings=2, tiles=(3, 3), halo=T.Halo(2), scheduler=client)
    assert run.recuts > 0
    assert_same(actual, expected)


def with_a_worker_killed(run):
    """run(client, progress) on a LocalCluster of 2 worker processes, one of them killed by
    `progress` once the first tile is in: Dask's nanny starts another and the lost tasks
    run again. Checks that they did; returns run's result."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as c:
        victim = next(iter(c.run(os.getpid).values()))
        killed_after = []

        def kill_once(done, total, vertices):
            if not killed_after:
                os.kill(victim, signal.SIGKILL)
                killed_after.append(done)

        result = run(c, kill_once)
        assert killed_after == [1]
        # Not vacuous: tasks the killed worker was running went back to the scheduler.
        log = c.run_on_scheduler(lambda dask_scheduler: [t[1:3] for t in dask_scheduler.transition_log])
        assert ("processing", "released") in log
        c.wait_for_workers(2)
        assert victim not in c.run(os.getpid).values()
    return result


def test_a_worker_killed_mid_run_changes_nothing(mesh):
    actual, run = with_a_worker_killed(
        lambda client, progress: T.run_tiles(*mesh, "jet", tiles=(4, 4), scheduler=client, progress=progress))
    assert run.tiles == 16
    assert_same(actual, whole(mesh, "jet", {}))
