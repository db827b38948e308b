#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tiles of a file on this machine (issue 47): a height-field grid of N x N vertices,
z = 0.1 sin(3x) cos(2y) + 0.05 x y over [0, 1]^2 with uniform noise of 0.3 grid steps in x
and y, written as a binary PLY streaming (row by row, never whole) to SCRATCH, then:

- the run: curvature_estimation.streamed.write_tiles (cut in TILES) and run_directory on a
  LocalCluster of 2 worker processes of 1 thread each: the tiling's and the run's wall
  times, the sum of the tasks' times, the peak resident memory of each worker process and
  of the driver (ru_maxrss), the halo overhead (tile vertices summed over the input's, minus one);
- the halo overhead against tile size and halo width, measured by cutting the mesh of
  the smaller N_SWEEP grid in 2x2 to 8x8 tiles with halos of 1 to 5 rings;
- the same run for a point set: the grid's vertices (noise 0.001 in z too) with the
  normals of the height field, 16 neighbors, in TILES.

Writes OUT (default benchmark/TILES_STREAMED.md). Run under the machine's lock with an
interpreter that imports curvature_estimation:
  flock /work/build.lock build/python-venv/bin/python benchmark/tiles_streamed.py \\
      --n 7100 --tiles 4x4 --scratch /work/scratch-tiles
"""
import argparse
import datetime
import os
import platform
import shutil
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def height_field(x, y):
    return 0.1 * np.sin(3 * x) * np.cos(2 * y) + 0.05 * x * y


def row(n, j, rng, noise_z=0.0):
    """Row j of the grid: n vertices (x, y, z) and their normals."""
    h = 1.0 / (n - 1)
    x = np.arange(n) * h
    y = np.full(n, j * h)
    inner_x = (0 < np.arange(n)) & (np.arange(n) < n - 1)
    x = x + 0.3 * h * rng.uniform(-1, 1, n) * inner_x
    if 0 < j < n - 1:
        y = y + 0.3 * h * rng.uniform(-1, 1, n)
    z = height_field(x, y) + noise_z * rng.normal(size=n)
    normal = np.column_stack([-(0.3 * np.cos(3 * x) * np.cos(2 * y) + 0.05 * y),
                              -(-0.2 * np.sin(3 * x) * np.sin(2 * y) + 0.05 * x), np.ones(n)])
    return np.column_stack([x, y, z]), normal / np.linalg.norm(normal, axis=1)[:, None]


def write_grid(path, n, points=False):
    """The grid as a binary PLY, a row at a time: a mesh (triangles) or a point set with normals."""
    rng = np.random.default_rng(1)
    names = ["x", "y", "z"] + (["nx", "ny", "nz"] if points else [])
    header = ["ply", "format binary_little_endian 1.0", f"element vertex {n * n}"]
    header += [f"property double {name}" for name in names]
    if not points:
        header += [f"element face {2 * (n - 1) ** 2}", "property list uchar int vertex_indices"]
    with open(path, "wb") as out:
        out.write(("\n".join(header + ["end_header"]) + "\n").encode("ascii"))
        for j in range(n):
            xyz, normal = row(n, j, rng, 0.001 if points else 0.0)
            out.write(np.ascontiguousarray(np.column_stack([xyz, normal]) if points else xyz, "<f8").tobytes())
        if points:
            return
        face = np.empty(2 * (n - 1), dtype=[("count", "u1"), ("index", "<i4", (3,))])
        face["count"] = 3
        for j in range(n - 1):
            a = j * n + np.arange(n - 1)
            b, c, d = a + 1, a + n, a + n + 1
            face["index"][0::2] = np.column_stack([a, b, d])
            face["index"][1::2] = np.column_stack([a, d, c])
            out.write(face.tobytes())


def peak_mib():
    """The process's peak resident set, VmHWM: ru_maxrss would count the RSS of the parent a
    worker was forked from (Linux keeps it across execve)."""
    with open("/proc/self/status", encoding="ascii") as status:
        return next(int(line.split()[1]) for line in status if line.startswith("VmHWM:")) / 1024


def run(path, work, tiles, **settings):
    """write_tiles and run_directory on a LocalCluster of 2 workers; the measures."""
    import distributed

    from curvature_estimation import streamed as S
    shutil.rmtree(work, ignore_errors=True)
    start = time.monotonic()
    manifest = S.write_tiles(str(path), str(work), tiles, **settings)
    cut = time.monotonic() - start
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None, memory_limit="4GiB") as cluster, \
            distributed.Client(cluster) as client:
        done = S.run_directory(str(work), client)
        workers = client.run(peak_mib)
    shutil.rmtree(work, ignore_errors=True)
    tile_vertices = [t["vertices"] for t in manifest["tile_files"]]
    return dict(vertices=manifest["vertices"], tiles=len(tile_vertices), cut=cut, run=done.run.seconds,
                tasks=done.run.task_seconds, recuts=done.run.recuts, overhead=done.run.overhead,
                largest=max(tile_vertices), workers=sorted(workers.values()), halo=manifest["halo"])


def sweep(path, work, grids, halos):
    """The halo overhead of cutting `path` with each grid and halo (rings)."""
    from curvature_estimation import streamed as S
    from curvature_estimation import tiles as T
    rows = []
    for grid in grids:
        for rings in halos:
            shutil.rmtree(work, ignore_errors=True)
            manifest = S.write_tiles(str(path), str(work), grid, "taubin", halo=T.Halo(rings), rings=1)
            total = sum(t["vertices"] for t in manifest["tile_files"])
            rows.append((grid, rings, manifest["vertices"] / len(manifest["tile_files"]),
                         total / manifest["vertices"] - 1))
    shutil.rmtree(work, ignore_errors=True)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=7100, help="the grid's side (7100: 50.4M vertices)")
    parser.add_argument("--n-sweep", type=int, default=1000, help="the side of the grid of the overhead sweep")
    parser.add_argument("--n-points", type=int, default=2240, help="the side of the point set's grid")
    parser.add_argument("--tiles", default="4x4")
    parser.add_argument("--scratch", default="/work/scratch-tiles")
    parser.add_argument("--out", default=str(ROOT / "benchmark" / "TILES_STREAMED.md"))
    a = parser.parse_args()
    tiles = tuple(int(t) for t in a.tiles.split("x"))
    scratch = Path(a.scratch)
    scratch.mkdir(parents=True, exist_ok=True)

    mesh, points = scratch / f"grid{a.n}.ply", scratch / f"points{a.n_points}.ply"
    small = scratch / f"grid{a.n_sweep}.ply"
    start = time.monotonic()
    write_grid(mesh, a.n)
    write_seconds = time.monotonic() - start
    write_grid(small, a.n_sweep)
    m = run(mesh, scratch / "work", tiles)
    mesh_bytes = mesh.stat().st_size
    mesh.unlink()
    write_grid(points, a.n_points, points=True)
    p = run(points, scratch / "work", tiles)
    points_bytes = points.stat().st_size
    points.unlink()
    rows = sweep(small, scratch / "work", [(2, 2), (4, 4), (8, 8)], [1, 3, 5])
    small.unlink()

    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        "# Tiles of a file on one machine",
        "",
        f"Written by `benchmark/tiles_streamed.py` on {date} ({platform.processor() or platform.machine()}, "
        f"{os.cpu_count()} cores). Input: the {a.n} x {a.n} jittered height-field grid as a binary PLY "
        f"({mesh_bytes / 2**30:.2f} GiB, written streaming in {write_seconds:.0f} s) and the {a.n_points} x "
        f"{a.n_points} point set ({points_bytes / 2**30:.2f} GiB), each cut by `write_tiles` "
        f"(reading it in chunks of {2**20} rows) into {a.tiles} tiles, run by `run_directory` on a "
        "LocalCluster of 2 worker processes of 1 thread each (memory limit 4 GiB each). Peaks: the resident "
        "high-water mark (VmHWM) of each worker at the end of its run, and of the driver (the tiling, the "
        "scheduling, the stitching into memmapped columns) over the whole benchmark.",
        "",
        "| input | vertices | tiles | largest tile | cut s | run s | sum of tasks s | tasks / run | re-cuts | "
        "halo overhead | ns/vertex (run, 2 workers) | peak worker MiB | peak driver MiB |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for name, r, size in (("mesh, paraboloid (5 rings)", m, mesh_bytes), ("points, 16 neighbors", p, points_bytes)):
        lines.append(f"| {name} | {r['vertices']} | {r['tiles']} | {r['largest']} | {r['cut']:.0f} | {r['run']:.0f} | "
                     f"{r['tasks']:.0f} | {r['tasks'] / r['run']:.2f} | {r['recuts']} | {100 * r['overhead']:.1f}% | "
                     f"{1e9 * r['run'] / r['vertices']:.0f} | {' / '.join(f'{w:.0f}' for w in r['workers'])} | "
                     f"{peak_mib():.0f} |")
    lines += ["", f"The point set's first halo (a distance, widened by 1.5 where the check flags a tile): "
              f"{p['halo'][1]:.5f}.", "",
              f"Halo overhead against tile size and halo width ({a.n_sweep} x {a.n_sweep} grid, halos in rings of "
              "faces):", "", "| tiles | vertices a tile | halo rings | overhead |", "| --- | --- | --- | --- |"]
    for grid, rings, per_tile, overhead in rows:
        lines.append(f"| {grid[0]}x{grid[1]} | {per_tile:.0f} | {rings} | {100 * overhead:.1f}% |")
    Path(a.out).write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
