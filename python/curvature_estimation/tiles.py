# SPDX-License-Identifier: GPL-3.0-or-later
"""Tiles with halos: a surface mesh cut into tiles on a grid in x and y, each tile run
on its own (serially or on Dask, one task per tile), the results stitched by global
index into what mesh_curvatures gives on the whole mesh, bit for bit.

A tile holds the vertices it owns (those in its cell of the grid), a halo around them
(the vertices within `Halo.distance` in x and y of its cell, then `Halo.rings` rings of
faces more) and the faces touching all but its last ring: its vertices keep their global
relative order and its faces theirs, so that the mesh built from a tile walks around a
vertex whose faces are all in the tile as the whole mesh's does (see the manual). After
a run each owned vertex is checked against the tile's incomplete vertices (those missing
some of their faces): where its neighborhood could have reached one (by the rings its
method reads with its settings, and by how far the balls it read reached), the tile is
cut again with a wider halo and run again.
"""

import math
import os
import shutil
import sys
import time
from typing import NamedTuple

import numpy as np

from . import MeshCurvatures, Status, _mesh_curvatures, mesh_reach

__all__ = ["Halo", "Tile", "TiledRun", "cut_tiles", "halo_of", "mean_edge_length", "reach_of", "recut", "run_tile",
           "run_tiles"]

class Halo(NamedTuple):
    """How far a tile reaches beyond the vertices it owns: `distance` in x and y (for
    balls), then `rings` rings of faces (at least 1: the owned vertices' own faces)."""

    rings: int
    distance: float = 0.0

    @classmethod
    def around(cls, reach):
        """The halo that holds a reach (a MeshReach) around each owned vertex."""
        return cls(reach.rings, reach.distance)

    def wider(self, needed, reached=0.0):
        """The halo a tile that failed its check is cut again with: one ring more and
        distances 1.25 times this one's (a ball's growth), at least those of the reach `needed`
        and the farthest `reached` by the balls of its flagged vertices."""
        return Halo(max(self.rings + 1, needed.rings), max(self.distance * 1.25, needed.distance, reached * 1.001))


def reach_of(method="paraboloid", **settings):
    """How far a method with the settings of mesh_curvatures reads at a vertex, with its
    normals and its fallbacks, as a MeshReach (mesh_reach: the library's neighborhood_reach);
    the radius absolute, in mesh units. Ring reaches bound every status; balls, as they grew,
    are checked at run time by the library's per-vertex reach (see check_tile)."""
    if isinstance(settings.get("radius"), str):
        raise ValueError("reach_of takes an absolute radius: convert 'Nx' with mean_edge_length first")
    return mesh_reach(method, **settings)


def halo_of(method="paraboloid", **settings):
    """The halo a tile needs for the method with the settings (reach_of)."""
    return Halo.around(reach_of(method, **settings))


def first_edges(faces, n):
    """The edges of `faces` (m, k) over n vertices where the faces first meet them: their
    positions in faces.ravel() (ascending), sources and targets."""
    source = faces.ravel()
    target = np.roll(faces, -1, axis=1).ravel()
    key = np.minimum(source, target).astype(np.int64) * np.int64(n) + np.maximum(source, target)
    _, first = np.unique(key, return_index=True)
    first.sort()
    return first, source[first], target[first]


def edge_lengths(d):
    """|d| of each row of d (edges, 3) as Eigen's norm of a Vector3d sums it at -O3:
    (x^2 + y^2) + z^2 (checked on 1e6 random vectors; x^2 + (y^2 + z^2) differs in 12% of them)."""
    return np.sqrt((d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1]) + d[:, 2] * d[:, 2])


def relative_radius(radius):
    """N of a radius "Nx" (N mean edge lengths), None for an absolute one."""
    if not isinstance(radius, str):
        return None
    if not radius.endswith("x"):
        raise ValueError(f"radius must be a length or a string 'Nx', got {radius!r}")
    return float(radius[:-1])


def mean_edge_length(vertices, faces):
    """The mean edge length of the mesh of (vertices, faces) as the library computes it
    for radius "Nx" (mean_edge_length.h), bit for bit: the edges in the order the faces
    first meet them, each |source - target| as Eigen's norm sums it, summed in that order."""
    vertices = np.asarray(vertices, dtype=np.float64)
    _, source, target = first_edges(np.asarray(faces), len(vertices))
    length = edge_lengths(vertices[source] - vertices[target])
    length = length[np.isfinite(length)]
    return float(np.cumsum(length)[-1] / len(length)) if len(length) else 0.0  # cumsum: in order


class Tile(NamedTuple):
    """One tile: `vertices` the global indices of its vertices (ascending), `faces` its
    faces in local indices (in global order), `owned` and `complete` per local vertex
    (complete: every face of the vertex is in the tile); `cell` its (i, j) in the grid,
    `box` the cell's (x0, x1, y0, y1), `halo` the halo it was cut with."""

    cell: tuple
    box: tuple
    halo: Halo
    vertices: np.ndarray
    faces: np.ndarray
    owned: np.ndarray
    complete: np.ndarray


def grid_of(lo, hi):
    """The origin and size of the grid over the bounds lo, hi in x and y."""
    lo, hi = np.asarray(lo, dtype=np.float64), np.asarray(hi, dtype=np.float64)
    return lo, np.where(hi > lo, hi - lo, 1.0)


def cell_of(xy, tiles, lo, size):
    """The (i, j) of the cell of each point of xy (n, 2) on the grid."""
    cell = np.floor((xy - lo) / size * np.array(tiles)).astype(np.int64)
    return np.clip(cell, 0, np.array(tiles) - 1)


def _cells(xy, tiles):
    lo, size = grid_of(xy.min(axis=0), xy.max(axis=0))
    return cell_of(xy, tiles, lo, size), lo, size


def box_of(cell, tiles, lo, size):
    (i, j), (nx, ny) = cell, tiles
    # Outer sides at infinity: no vertex lies beyond them.
    x0 = lo[0] + size[0] * i / nx if i > 0 else -math.inf
    x1 = lo[0] + size[0] * (i + 1) / nx if i < nx - 1 else math.inf
    y0 = lo[1] + size[1] * j / ny if j > 0 else -math.inf
    y1 = lo[1] + size[1] * (j + 1) / ny if j < ny - 1 else math.inf
    return (x0, x1, y0, y1)


def _cut(vertices, faces, degree, cell, box, owned_global, halo):
    core = owned_global.copy()
    if halo.distance > 0:
        x0, x1, y0, y1 = box
        x, y, d = vertices[:, 0], vertices[:, 1], halo.distance
        core |= (x >= x0 - d) & (x <= x1 + d) & (y >= y0 - d) & (y <= y1 + d)
    inside = core
    for _ in range(halo.rings):
        touching = inside[faces].any(axis=1)
        inside = inside.copy()
        inside[faces[touching]] = True
    global_index = np.flatnonzero(inside)
    local = np.full(len(vertices), -1, dtype=np.int64)
    local[global_index] = np.arange(len(global_index))
    tile_faces = local[faces[touching]]
    complete = np.bincount(tile_faces.ravel(), minlength=len(global_index)) == degree[global_index]
    return Tile(cell, box, halo, global_index, tile_faces, owned_global[global_index], complete)


def cut_tiles(vertices, faces, tiles=(3, 3), halo=Halo(1)):
    """The tiles of the mesh (vertices (n, 3), faces (m, k)) on a grid of tiles[0] by
    tiles[1] cells over the bounding box in x and y, each with `halo`; empty cells give
    no tile."""
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    if halo.rings < 1:
        raise ValueError("a halo has at least 1 ring (the owned vertices' faces)")
    cell, lo, size = _cells(vertices[:, :2], tiles)
    degree = np.bincount(faces.ravel(), minlength=len(vertices))
    result = []
    for i in range(tiles[0]):
        for j in range(tiles[1]):
            owned = (cell[:, 0] == i) & (cell[:, 1] == j)
            if owned.any():
                result.append(_cut(vertices, faces, degree, (i, j), box_of((i, j), tiles, lo, size), owned, halo))
    return result


def recut(vertices, faces, tile, halo):
    """`tile` cut again from the mesh with `halo`."""
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    owned = np.zeros(len(vertices), dtype=bool)
    owned[tile.vertices[tile.owned]] = True
    degree = np.bincount(faces.ravel(), minlength=len(vertices))
    return _cut(vertices, faces, degree, tile.cell, tile.box, owned, halo)


def _ring_distance(faces, start, limit):
    """Per vertex, the rings of faces from the `start` vertices to it, up to `limit` (else limit)."""
    distance = np.full(len(start), limit, dtype=np.int64)
    reached = start.copy()
    distance[reached] = 0
    for step in range(1, limit):
        touching = reached[faces].any(axis=1)
        grown = reached.copy()
        grown[faces[touching]] = True
        distance[grown & ~reached] = step
        reached = grown
    return distance


def box_gap(points, box, halo):
    """Per point, its distance in x and y to the edge of the tile's complete region (the
    cell widened by halo.distance): no incomplete vertex is nearer, in 3D."""
    x0, x1, y0, y1 = box
    d = halo.distance
    x, y = points[:, 0], points[:, 1]
    return np.minimum(np.minimum(x - (x0 - d), (x1 + d) - x), np.minimum(y - (y0 - d), (y1 + d) - y))


def check_tile(tile, points, reach, needed):
    """The owned vertices (local indices) whose estimate could have read an incomplete
    vertex of the tile: those fewer than needed.rings rings from one (the rings they read,
    a bound for every status), and those with one within their `reach` (per local vertex,
    the library's vertex_reach_map: how far the balls each estimate read reached, as they
    grew)."""
    owned = np.flatnonzero(tile.owned)
    rings = _ring_distance(tile.faces, ~tile.complete, needed.rings)
    suspect = rings[owned] < needed.rings
    # The margin covers the rounding of the distances the balls were measured with. Only the
    # vertices nearer the edge of the complete region (the cell widened by the halo's distance)
    # than their reach can have an incomplete vertex within it.
    reach = reach[owned] * (1 + 1e-9)
    near = np.flatnonzero(box_gap(points[owned], tile.box, tile.halo) < reach)
    incomplete = points[~tile.complete]
    if len(near) and len(incomplete):
        from scipy.spatial import cKDTree
        distance, _ = cKDTree(incomplete).query(points[owned[near]], distance_upper_bound=reach[near].max())
        suspect[near] |= distance <= reach[near]
    return owned[suspect]


def run_tile(points, tile, method, settings, needed, threads=1):
    """A task: mesh_curvatures on the tile (points: its vertices' coordinates) and the
    check. Returns the owned vertices' global indices, their values as MeshCurvatures,
    the global indices of those the check flags, the farthest their balls reached (0 for
    none), and the seconds the task took."""
    start = time.monotonic()
    r, reach = _mesh_curvatures(points, tile.faces, method, threads=threads, **settings)
    flagged = check_tile(tile, points, reach, needed)
    owned = tile.owned
    return (tile.vertices[owned], MeshCurvatures(*(a[owned] for a in r)), tile.vertices[flagged],
            float(reach[flagged].max(initial=0.0)), time.monotonic() - start)


class TiledRun(NamedTuple):
    """What run_tiles did: the tiles, the re-cuts (tiles run again with a wider halo),
    the halo overhead (the vertices of the tiles kept summed over the input's, minus
    one), the wall time, the sum of the tasks' times (re-cut ones too), and the halo
    each tile ended with, by cell."""

    tiles: int
    recuts: int
    overhead: float
    seconds: float
    task_seconds: float
    halos: dict

    def summary(self):
        return (f"{self.tiles} tiles, {self.recuts} re-cut, halo overhead {100 * self.overhead:.1f}%, "
                f"{self.seconds:.2f} s wall, {self.task_seconds:.2f} s in tasks")


class _Done:
    """A task the serial driver ran at its submission."""

    def __init__(self, value):
        self.value = value


class _Serial:
    """The driver without Dask: tasks run at submission, in order."""

    @staticmethod
    def submit(function, *args, **kwargs):
        return _Done(function(*args, **kwargs))

    @staticmethod
    def completed(futures):
        return iter(futures)

    @staticmethod
    def result(future):
        return future.value


class _Dask:
    """One task per tile on a Dask distributed client."""

    def __init__(self, client):
        self.client = client

    def submit(self, function, *args, **kwargs):
        return self.client.submit(function, *args, pure=False, **kwargs)

    @staticmethod
    def completed(futures):
        from distributed import as_completed
        return as_completed(futures)

    @staticmethod
    def result(future):
        return future.result()


def _progress_printer(stream):
    start = time.monotonic()

    def show(done, total, vertices):
        elapsed = time.monotonic() - start
        rate = vertices / elapsed if elapsed > 0 else 0.0
        left = elapsed * (total - done) / done
        stream.write(f"\rtiles {done}/{total}, {rate:,.0f} vertices/s, {left:.0f} s left ")
        if done == total:
            stream.write("\n")
        stream.flush()

    return show


def _driver(scheduler):
    """The driver of `scheduler` (see run_tiles) and what to close after the run."""
    if scheduler == "serial":
        return _Serial(), []
    from distributed import Client, LocalCluster
    if scheduler is None:
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None)
        client = Client(cluster)
        return _Dask(client), [client, cluster]
    if isinstance(scheduler, str):
        client = Client(scheduler)
        return _Dask(client), [client]
    return _Dask(scheduler), []


def run_tiles(vertices, faces, method="paraboloid", *, tiles=(3, 3), halo=None, scheduler="serial",
              max_recuts=4, threads=1, progress=None, **settings):
    """mesh_curvatures(vertices, faces, method, **settings) computed tile by tile, bit for bit.

    tiles: the grid (nx, ny) in x and y. halo: by default halo_of(method, **settings);
    where the check flags a tile it is cut again with a wider halo (Halo.wider), at most
    max_recuts times (then RuntimeError). radius "Nx" is made absolute with
    mean_edge_length of the whole mesh first. scheduler: "serial" (no Dask), a
    distributed.Client, a scheduler's address, or None (a LocalCluster of 2 worker
    processes of one thread on localhost, closed at the end). threads: each task's, as
    mesh_curvatures'. progress: None, True (a line on stderr) or a function (tiles done,
    tiles, vertices done). Returns (MeshCurvatures of the whole mesh, TiledRun).
    """
    start = time.monotonic()
    vertices = np.ascontiguousarray(vertices, dtype=np.float64)
    faces = np.ascontiguousarray(faces, dtype=np.int64)
    factor = relative_radius(settings.get("radius"))
    if factor is not None:
        settings["radius"] = factor * mean_edge_length(vertices, faces)
    needed = reach_of(method, **settings)

    n = len(vertices)
    out = MeshCurvatures(*(np.empty(n) for _ in range(4)), np.empty((n, 3)), np.empty((n, 3)),
                         np.empty(n, dtype=np.uint8))
    cut = cut_tiles(vertices, faces, tiles, halo or Halo.around(needed))

    def task(driver, tile):
        return driver.submit(run_tile, vertices[tile.vertices], tile, method, settings, needed, threads)

    def keep(tile, result):
        owned, values = result[:2]
        for column, value in zip(out, values):
            column[owned] = value
        return len(owned)

    def again(tile, reached):
        return recut(vertices, faces, tile, tile.halo.wider(needed, reached))

    kept, recuts, task_seconds = schedule(scheduler, cut, task, again, keep, max_recuts, progress)
    return out, TiledRun(len(cut), recuts, sum(len(t.vertices) for t in kept) / n - 1, time.monotonic() - start,
                         task_seconds, {t.cell: t.halo for t in kept})


def schedule(scheduler, tiles, task, again, keep, max_recuts=4, progress=None):
    """Runs every tile as task(driver, tile) (a future of the driver of `scheduler`, see
    run_tiles) whose result ends with the global indices the check flags, the farthest
    their balls reached and the task's seconds; a flagged tile is replaced by
    again(tile, reached) and run again, at most max_recuts
    times per cell (then RuntimeError), the others go to keep(tile, result), which returns
    the vertices it stitched. Returns (the tiles kept, the re-cuts, the tasks' seconds)."""
    if progress is True:
        progress = _progress_printer(sys.stderr)
    driver, to_close = _driver(scheduler)
    futures, recuts, kept = {}, {}, []
    stitched = 0
    task_seconds = 0.0

    def submit(tile):
        future = task(driver, tile)
        futures[future] = tile
        return future

    try:
        pending = [submit(tile) for tile in tiles]
        while pending:
            again_pending = []
            for future in driver.completed(pending):
                tile = futures.pop(future)
                result = driver.result(future)
                flagged, reached, seconds = result[-3:]
                task_seconds += seconds
                if len(flagged):
                    recuts[tile.cell] = recuts.get(tile.cell, 0) + 1
                    if recuts[tile.cell] > max_recuts:
                        raise RuntimeError(f"tile {tile.cell}: {len(flagged)} vertices still flagged with the halo "
                                           f"{tile.halo}, after {max_recuts} re-cuts")
                    again_pending.append(submit(again(tile, reached)))
                    continue
                stitched += keep(tile, result)
                kept.append(tile)
                if progress:
                    progress(len(kept), len(tiles), stitched)
            pending = again_pending
    finally:
        for resource in to_close:
            resource.close()
    return kept, sum(recuts.values()), task_seconds


def main(argv=None):
    import argparse
    import tempfile

    from . import streamed
    parser = argparse.ArgumentParser(
        prog="python3 -m curvature_estimation.tiles",
        description="Curvature of a surface mesh or a point set in tiles with halos, serially or on Dask: the "
                    "values of mesh_curvatures (and of the tool) on the whole input, bit for bit. A file is read "
                    "in chunks and cut into tiles in a work directory (curvature_estimation.streamed).")
    parser.add_argument("input", help="a binary little-endian .ply (a mesh, or a point set without faces), an ASCII "
                                      ".off, an .xyz point set, or an .npz of arrays vertices (n, 3) and faces (m, k)")
    parser.add_argument("-o", "--output", help="a .ply, or a directory of .npy columns (k_max, k_min, mean, gaussian, "
                                               "d_max, d_min, status); for an .npz input, an .npz; without it, the "
                                               "summary only")
    parser.add_argument("-m", "--method", default="paraboloid")
    parser.add_argument("--tiles", default="3x3", help="the grid in x and y, e.g. 4x4, or a number of vertices a tile")
    parser.add_argument("--work-dir", help="where a file's tiles and results go (a new directory; default: a "
                                           "temporary one, removed at the end)")
    parser.add_argument("--scheduler", default="local",
                        help="a Dask scheduler's address, 'local' (a LocalCluster of 2 processes) or 'serial'")
    parser.add_argument("--halo-rings", type=int,
                        help="cut with this many rings first (default: the method's halo; a narrower one is widened)")
    parser.add_argument("--threads", type=int, default=1, help="each task's threads")
    for option in ("rings", "order", "fit-degree", "degree", "monge-degree", "neighbors"):
        parser.add_argument("--" + option, type=int)
    parser.add_argument("--radius", help="a length, or Nx for N mean edge lengths of the whole mesh")
    parser.add_argument("--unsigned", action="store_true", help="a point set without normals: H >= 0 at each point")
    a = parser.parse_args(argv)
    halo = None
    if a.halo_rings is not None:
        if a.radius is not None:
            parser.error("--halo-rings is for ring neighborhoods, not with --radius")
        halo = Halo(a.halo_rings)
    scheduler = {"local": None, "serial": "serial"}.get(a.scheduler, a.scheduler)
    tiles = tuple(int(t) for t in a.tiles.split("x")) if "x" in a.tiles else int(a.tiles)
    radius = a.radius if a.radius is None or a.radius.endswith("x") else float(a.radius)
    progress = sys.stderr.isatty() or None
    if a.input.endswith(".npz"):
        with np.load(a.input) as arrays:
            vertices, faces = arrays["vertices"], arrays["faces"]
        settings = _mesh_options(a, radius)
        result, run = run_tiles(vertices, faces, a.method, tiles=tiles, halo=halo, scheduler=scheduler,
                                threads=a.threads, progress=progress, **settings)
        if a.output:
            np.savez(a.output, **result._asdict())
        counts = np.bincount(result.status, minlength=len(Status))
    else:
        work = a.work_dir or tempfile.mkdtemp(prefix="curvature-tiles-")
        if not a.work_dir:
            os.rmdir(work)  # write_tiles makes it
        try:
            if streamed.input_kind(a.input) == "mesh":
                settings = _mesh_options(a, radius)
            else:
                settings = {k: v for k, v in (("number_of_neighbors", a.neighbors), ("neighbor_radius", radius),
                                              ("fit_degree", a.fit_degree)) if v is not None}
                settings["unsigned"] = a.unsigned
            streamed.write_tiles(a.input, work, tiles, a.method, halo, **settings)
            done = streamed.run_directory(work, scheduler, a.output, threads=a.threads, progress=progress)
            run = done.run
            counts = np.bincount(np.load(os.path.join(done.columns, "status.npy"), mmap_mode="r"),
                                 minlength=len(Status))
        except streamed.InputError as error:
            raise SystemExit(f"error: {error}") from None
        finally:
            if not a.work_dir:
                shutil.rmtree(work, ignore_errors=True)
    print(f"{counts.sum()} vertices: {run.summary()}; " + ", ".join(f"{s.name} {counts[s]}" for s in Status))


def _mesh_options(a, radius):
    settings = {k: v for k, v in (("rings", a.rings), ("order", a.order), ("fit_degree", a.fit_degree),
                                  ("degree", a.degree), ("monge_degree", a.monge_degree)) if v is not None}
    if radius is not None:
        settings["radius"] = radius
    return settings


if __name__ == "__main__":
    # Through the package's module: Dask pickles tiles by reference to their class's module.
    from curvature_estimation.tiles import main as package_main

    package_main()
