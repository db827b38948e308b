# SPDX-License-Identifier: GPL-3.0-or-later
"""Tiles of a file larger than one process holds: the input read in chunks, never whole,
its tiles with their halos written to a directory, run one task per tile (serially or on
Dask), the results stitched by global index into .npy columns or a binary PLY.

Inputs: a binary little-endian PLY (a mesh: vertices with float or double x, y, z and
faces as lists of one size; a point set: vertices only, normals nx, ny, nz if any), an
ASCII OFF mesh, an ASCII .xyz point set (x y z [nx ny nz] a line). A PLY is read in
place (numpy memmaps of its fixed-stride sections); an OFF or .xyz is converted once, in
chunks, to .npy files in the work directory. Memory is bounded by a tile and a chunk:

1. scan: the bounds in x and y, the longest edge in x and y (a ring of faces reaches no
   farther), the faces' sizes and indices checked;
2. distribute: each tile's candidates, the vertices in its cell widened by what its halo
   can reach and the faces with a vertex there (in global order), appended to files;
3. cut: each tile from its candidates, with tiles.cut_tiles' halo, in memory. A radius
   "Nx" is made absolute with the mean edge length of the whole mesh, summed in the
   library's order from the tiles' own edges (tiles.mean_edge_length, bit for bit).

The work directory holds manifest.json (the input, the grid, the settings made global,
the halo, the tiles), tiles/ (a tile: its vertices' global indices, coordinates, owned
and complete flags, its faces) and results/ (a tile's owned values, by global index).
"""

import json
import os
import shutil
import time
from typing import NamedTuple

import numpy as np

from . import (MeshCurvatures, MeshReach, PointSetCurvatures, Status, _mesh_curvatures, point_set_curvatures,
               point_set_reach)
from . import tiles as T

__all__ = ["Source", "open_input", "run_directory", "run_file", "write_tiles"]

CHUNK = 1 << 20  # rows read at a time

_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
              "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
              "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


class InputError(ValueError):
    """The input is not a file the streamed tiler reads."""


class Source:
    """An input read in chunks: n vertices (points(a, b): float64 rows a to b), m faces of
    k vertices each (faces(a, b): int64 rows), normals or None."""

    def __init__(self, path, vertices, faces=None, xyz=("x", "y", "z"), normals=None):
        self.path, self._vertices, self._faces, self._xyz, self._normals = path, vertices, faces, xyz, normals
        self.n = len(vertices)
        self.m = 0 if faces is None else len(faces)
        self.k = 0 if faces is None else faces.dtype["index"].shape[0] if faces.dtype.names else faces.shape[1]

    @property
    def is_mesh(self):
        return self._faces is not None

    @property
    def has_normals(self):
        return self._normals is not None

    def _columns(self, rows, names):
        if names is None:
            return np.asarray(rows, dtype=np.float64)
        return np.column_stack([rows[name].astype(np.float64) for name in names])

    def points(self, a=0, b=None):
        return self._columns(self._vertices[a:b], None if self._vertices.dtype.names is None else self._xyz)

    def points_at(self, index):
        return self._columns(self._vertices[index], None if self._vertices.dtype.names is None else self._xyz)

    def normals_at(self, index):
        if self._normals is None:
            return None
        rows = self._vertices[index] if self._vertices.dtype.names else self._normals[index]
        return self._columns(rows, self._normals if self._vertices.dtype.names else None)

    def faces(self, a=0, b=None):
        rows = self._faces[a:b]
        if rows.dtype.names:
            if np.any(rows["count"] != self.k):
                raise InputError(f"{self.path}: faces of other sizes than {self.k} after face {a}: the tiles take "
                                 "faces of one size")
            rows = rows["index"]
        return np.asarray(rows, dtype=np.int64)


def _ply_header(path):
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    end = head.find(b"end_header\n")
    if not head.startswith(b"ply\n") or end < 0:
        raise InputError(f"{path}: not a PLY file (no 'ply' line or no 'end_header' in its first 64 KiB)")
    lines = [line.split() for line in head[:end].decode("ascii", errors="replace").splitlines()[1:]]
    elements = []
    for words in lines:
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format":
            if words[1:2] != ["binary_little_endian"]:
                raise InputError(f"{path}: PLY format {' '.join(words[1:])}: the tiles read binary_little_endian")
        elif words[0] == "element" and len(words) == 3:
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property" and elements and len(words) >= 3:
            kind = words[1:-1]
            if any(t not in _PLY_TYPES for t in kind if t != "list"):
                raise InputError(f"{path}: unknown PLY type in 'property {' '.join(words[1:])}'")
            elements[-1][2].append((words[-1], kind))
        else:
            raise InputError(f"{path}: bad PLY header line '{' '.join(words)}'")
    return elements, end + len(b"end_header\n")


def _open_ply(path):
    elements, offset = _ply_header(path)
    names = [e[0] for e in elements]
    if names not in (["vertex"], ["vertex", "face"]):
        raise InputError(f"{path}: PLY elements {names}: the tiles read 'vertex' and, for a mesh, 'face'")
    _, n, properties = elements[0]
    if any(kind[0] == "list" for _, kind in properties):
        raise InputError(f"{path}: a list property of the vertices")
    vertex_type = np.dtype([(name, "<" + _PLY_TYPES[kind[0]]) for name, kind in properties])
    if not {"x", "y", "z"} <= set(vertex_type.names):
        raise InputError(f"{path}: the vertices have no x, y and z")
    size = os.path.getsize(path)
    face_offset = offset + n * vertex_type.itemsize
    normals = ("nx", "ny", "nz") if {"nx", "ny", "nz"} <= set(vertex_type.names) else None
    faces = None
    m = elements[1][1] if len(elements) == 2 else 0
    if m:
        properties = elements[1][2]
        if len(properties) != 1 or properties[0][1][0] != "list" or len(properties[0][1]) != 3:
            raise InputError(f"{path}: the faces must have one property, the list of their vertices")
        count_type, index_type = (np.dtype("<" + _PLY_TYPES[t]) for t in properties[0][1][1:])
        if face_offset + count_type.itemsize > size:
            raise InputError(f"{path}: truncated: {size} bytes, the header's {n} vertices need more")
        k = int(np.fromfile(path, dtype=count_type, count=1, offset=face_offset)[0])
        if k < 3:
            raise InputError(f"{path}: a face of {k} vertices")
        face_type = np.dtype([("count", count_type), ("index", index_type, (k,))])
        expected = face_offset + m * face_type.itemsize
    else:
        expected = face_offset
    if size < expected:
        raise InputError(f"{path}: truncated: {size} bytes, the header's {n} vertices and {m} faces of "
                         f"{k if m else 0} need {expected}")
    if size > expected:
        raise InputError(f"{path}: {size} bytes, the header's vertices and faces of one size need {expected}: "
                         "faces of several sizes, or more data than the header says")
    vertices = np.zeros(0, vertex_type)
    if n:
        vertices = np.memmap(path, dtype=vertex_type, mode="r", offset=offset, shape=(n,))
    if m:
        faces = np.memmap(path, dtype=face_type, mode="r", offset=face_offset, shape=(m,))
    elif len(elements) == 2:
        faces = np.zeros((0, 3), dtype=np.int64)
    return Source(path, vertices, faces, normals=normals)


def _text_rows(f, count, path, what):
    """Up to CHUNK of the next `count` non-empty, non-comment lines of f, as lists of words."""
    rows = []
    while len(rows) < min(count, CHUNK):
        line = f.readline()
        if not line:
            raise InputError(f"{path}: the file ends before its {what}")
        words = line.split("#", 1)[0].split()
        if words:
            rows.append(words)
    return rows


def _convert_off(path, directory):
    with open(path, encoding="ascii", errors="replace") as f:
        header = _text_rows(f, 1, path, "header")[0]
        if not header[0].endswith("OFF") or header[0].lstrip("STCN") != "OFF":
            raise InputError(f"{path}: not an ASCII OFF file (header {' '.join(header)})")
        counts = header[1:] or _text_rows(f, 1, path, "counts")[0]
        try:
            n, m = int(counts[0]), int(counts[1])
        except (IndexError, ValueError):
            raise InputError(f"{path}: no counts of vertices and faces after the header") from None
        vertices = np.lib.format.open_memmap(os.path.join(directory, "vertices.npy"), "w+", np.float64, (n, 3))
        for a in range(0, n, CHUNK):
            rows = _text_rows(f, n - a, path, f"{n} vertices")
            try:
                vertices[a:a + len(rows)] = np.array([r[:3] for r in rows], dtype=np.float64)
            except ValueError:
                raise InputError(f"{path}: a vertex line among lines {a} to {a + len(rows)} is not x y z") from None
        k = None
        faces = None
        for a in range(0, m, CHUNK):
            rows = _text_rows(f, m - a, path, f"{m} faces")
            k = k or int(rows[0][0])
            if faces is None:
                faces = np.lib.format.open_memmap(os.path.join(directory, "faces.npy"), "w+", np.int64, (m, k))
            if any(int(r[0]) != k or len(r) < k + 1 for r in rows):
                raise InputError(f"{path}: faces of other sizes than {k} after face {a}: the tiles take faces "
                                 "of one size")
            faces[a:a + len(rows)] = np.array([r[1:k + 1] for r in rows], dtype=np.int64)
    vertices.flush()
    if faces is None:
        faces = np.zeros((0, 3), dtype=np.int64)
    else:
        faces.flush()
    return Source(path, np.load(os.path.join(directory, "vertices.npy"), mmap_mode="r"),
                  faces if not m else np.load(os.path.join(directory, "faces.npy"), mmap_mode="r"))


def _convert_xyz(path, directory):
    target = os.path.join(directory, "points.npy")
    parts, columns = [], None
    with open(path, encoding="ascii", errors="replace") as f:
        n = 0
        while True:
            lines = f.readlines(1 << 24)
            if not lines:
                break
            rows = [w for w in (line.split("#", 1)[0].split() for line in lines) if w]
            width = {len(r) for r in rows}
            columns = columns or (6 if width == {6} else 3)
            if not rows:
                continue
            if width - {columns} or columns not in (3, 6):
                raise InputError(f"{path}: lines of {sorted(width)} values after point {n}: x y z [nx ny nz] a line")
            try:
                part = np.array(rows, dtype=np.float64)
            except ValueError:
                raise InputError(f"{path}: a value that is not a number after point {n}") from None
            parts.append(os.path.join(directory, f"points.{len(parts)}.npy"))
            np.save(parts[-1], part)
            n += len(part)
    points = np.lib.format.open_memmap(target, "w+", np.float64, (n, columns or 3))
    a = 0
    for part in parts:
        rows = np.load(part)
        points[a:a + len(rows)] = rows
        a += len(rows)
        os.remove(part)
    points.flush()
    points = np.load(target, mmap_mode="r")
    return Source(path, points[:, :3], normals=points[:, 3:] if points.shape[1] == 6 else None)


def open_input(path, directory):
    """The Source of `path` (.ply, .off or .xyz); an OFF or .xyz is converted into `directory`."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    kind = os.path.splitext(path)[1].lower()
    if kind == ".ply":
        return _open_ply(path)
    if kind == ".off":
        return _convert_off(path, directory)
    if kind == ".xyz":
        return _convert_xyz(path, directory)
    raise InputError(f"{path}: give a binary .ply, an ASCII .off or an .xyz")


class TileFile(NamedTuple):
    """A tile written to the work directory: its cell, box, halo, file, vertices and owned vertices."""

    cell: tuple
    box: tuple
    halo: T.Halo
    path: str
    vertices: int
    owned: int


def _scan(source, tiles):
    """Pass 1: the grid, each vertex chunk's bounds, the longest edge in x and y; checks the faces."""
    lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
    for a in range(0, source.n, CHUNK):
        points = source.points(a, a + CHUNK)
        if not np.isfinite(points).all():
            # A tile is owned by position: a vertex without one would be in no tile.
            raise InputError(f"{source.path}: a vertex after vertex {a} has a coordinate that is not finite")
        if len(points):
            lo, hi = np.minimum(lo, points[:, :2].min(axis=0)), np.maximum(hi, points[:, :2].max(axis=0))
    if not np.all(lo <= hi):
        raise InputError(f"{source.path}: no vertex")
    longest = 0.0
    for a in range(0, source.m, CHUNK):
        faces = source.faces(a, a + CHUNK)
        if faces.size and (faces.min() < 0 or faces.max() >= source.n):
            raise InputError(f"{source.path}: a face after face {a} has a vertex index outside 0 to {source.n - 1}")
        xy = source.points_at(faces.ravel())[:, :2].reshape(len(faces), -1, 2)
        d = xy - np.roll(xy, -1, axis=1)
        longest = max(longest, float(np.nanmax(np.hypot(d[..., 0], d[..., 1]), initial=0.0)))
    lo, size = T.grid_of(lo, hi)
    if isinstance(tiles, int):  # vertices per tile: a grid of about that many, square cells
        cells = max(1.0, source.n / tiles)
        nx = max(1, round(np.sqrt(cells * size[0] / size[1])))
        tiles = (nx, max(1, round(cells / nx)))
    return tuple(tiles), lo, size, longest


def _distribute(source, boxes, width, directory):
    """Pass 2: per box, the vertices within `width` of it in x and y, and the faces with such a vertex
    (their global indices and rows), appended to files in `directory`; returns their paths."""
    paths = [(os.path.join(directory, f"{i}.vertices"), os.path.join(directory, f"{i}.faces"),
              os.path.join(directory, f"{i}.face_index")) for i in range(len(boxes))]
    files = [[open(p, "wb") for p in three] for three in paths]

    def inside(x, y, box):
        x0, x1, y0, y1 = box
        return (x >= x0 - width) & (x <= x1 + width) & (y >= y0 - width) & (y <= y1 + width)

    try:
        for a in range(0, source.n, CHUNK):
            xy = source.points(a, a + CHUNK)[:, :2]
            for box, (out, _, _) in zip(boxes, files):
                out.write((a + np.flatnonzero(inside(xy[:, 0], xy[:, 1], box))).astype(np.int64).tobytes())
        for a in range(0, source.m, CHUNK):
            faces = source.faces(a, a + CHUNK)
            xy = source.points_at(faces.ravel())[:, :2].reshape(len(faces), -1, 2)
            for box, (_, out, index) in zip(boxes, files):
                touch = inside(xy[..., 0], xy[..., 1], box).any(axis=1)
                out.write(faces[touch].tobytes())
                index.write((a + np.flatnonzero(touch)).astype(np.int64).tobytes())
    finally:
        for three in files:
            for f in three:
                f.close()
    return paths


class _Candidates(NamedTuple):
    vertices: np.ndarray  # global indices, ascending
    points: np.ndarray
    faces: np.ndarray  # in local indices, global order
    face_index: np.ndarray


def _candidates(source, paths):
    listed, faces_path, index_path = paths
    faces = np.fromfile(faces_path, dtype=np.int64).reshape(-1, max(source.k, 1))
    vertices = np.union1d(np.fromfile(listed, dtype=np.int64), faces.ravel())
    return _Candidates(vertices, source.points_at(vertices), np.searchsorted(vertices, faces),
                       np.fromfile(index_path, dtype=np.int64))


def _owned_edges(source, candidates, owned):
    """The positions in the input's faces.ravel() and lengths of the edges the faces first meet whose
    lower vertex is owned: all the faces of such an edge are candidates."""
    first, a, b = T.first_edges(candidates.faces, len(candidates.vertices))
    mine = owned[np.minimum(a, b)]  # local indices keep the global order
    position = candidates.face_index[first // source.k] * source.k + first % source.k
    return position[mine], T.edge_lengths(candidates.points[a[mine]] - candidates.points[b[mine]])


def _ordered_mean(parts, total):
    """The mean of the finite lengths of parts [(positions, lengths)], summed in the order of their
    positions as one cumsum, in ranges of CHUNK positions."""
    carry, count = 0.0, 0
    for a in range(0, total, CHUNK):
        position, length = [], []
        for p, v in parts:
            i, j = np.searchsorted(p, [a, a + CHUNK])
            position.append(p[i:j])
            length.append(v[i:j])
        length = np.concatenate(length)[np.argsort(np.concatenate(position), kind="stable")]
        length = length[np.isfinite(length)]
        if len(length):
            carry = np.cumsum(np.concatenate([[carry], length]))[-1]
            count += len(length)
    return float(carry / count) if count else 0.0


def _owned_mask(points, tiles, lo, size, cell):
    return (T.cell_of(points[:, :2], tiles, lo, size) == cell).all(axis=1)


def _point_reach(settings):
    return point_set_reach(**{k: settings[k] for k in ("number_of_neighbors", "neighbor_radius", "fit_degree")
                              if settings.get(k) is not None})


def _point_halo(source, tiles, lo, size, settings):
    """The distance a point set's tile reaches at first (checked and widened at run time): the radius,
    or the largest distance to the widened neighborhood's farthest point (point_set_reach) over a sample
    of 10^4 points of the first chunk, away from the chunk's edges in x and y (noise in the data makes it
    several times that of a flat surface of the bounds' area, the fallback where the chunk is too small)."""
    from scipy.spatial import cKDTree
    reach = _point_reach(settings)
    if reach.distance > 0:
        return reach.distance
    k = reach.widened_neighbors
    flat = float(np.sqrt(size[0] * size[1] / max(source.n, 1) * k / np.pi))
    points = source.points_at(np.arange(min(source.n, CHUNK)))
    x, y = points[:, 0], points[:, 1]
    margin = 2 * flat
    inner = np.flatnonzero((x > x.min() + margin) & (x < x.max() - margin) & (y > y.min() + margin)
                           & (y < y.max() - margin))
    if len(points) <= k or len(inner) == 0:
        return 1.5 * flat
    sample = np.random.default_rng(0).choice(inner, min(len(inner), 10_000), replace=False)
    return float(cKDTree(points).query(points[sample], k=[k + 1])[0][:, 0].max())


def _write_tile(directory, cell, box, halo, arrays):
    path = os.path.join(directory, "tiles", f"{cell[0]}_{cell[1]}.r{halo.rings}.npz")
    np.savez(path, cell=cell, box=box, halo=np.array(halo, dtype=np.float64), **arrays)
    return TileFile(tuple(int(c) for c in cell), tuple(box), halo, path, len(arrays["vertices"]),
                    int(np.count_nonzero(arrays["owned"])))


def _cut_mesh_tile(directory, candidates, cell, box, halo, owned):
    degree = np.bincount(candidates.faces.ravel(), minlength=len(candidates.vertices))
    tile = T._cut(candidates.points, candidates.faces, degree, cell, box, owned, halo)
    return _write_tile(directory, cell, box, halo,
                       dict(vertices=candidates.vertices[tile.vertices], points=candidates.points[tile.vertices],
                            faces=tile.faces, owned=tile.owned, complete=tile.complete))


def _cut_point_tile(directory, source, listed, cell, box, halo, tiles, lo, size):
    index = np.fromfile(listed, dtype=np.int64)
    points = source.points_at(index)
    arrays = dict(vertices=index, points=points, owned=_owned_mask(points, tiles, lo, size, cell),
                  complete=T.box_gap(points, box, halo) >= halo.distance)
    normals = source.normals_at(index)
    if normals is not None:
        arrays["normals"] = normals
    return _write_tile(directory, cell, box, halo, arrays)


def _reach(method, settings, longest):
    """The reach of the settings (a MeshReach) and the width of the candidates around a cell whose
    halo holds it."""
    needed = T.reach_of(method, **settings)
    return needed, (needed.rings + 1) * longest + needed.distance


def _cut_all(source, directory, manifest, cells):
    """The tiles of `cells` with the manifest's halo, their candidates distributed in one pass."""
    tiles, lo, size = tuple(manifest["tiles"]), np.array(manifest["lo"]), np.array(manifest["size"])
    halo = T.Halo(*manifest["halo"])
    boxes = [T.box_of(cell, tiles, lo, size) for cell in cells]
    width = (halo.rings + 1) * manifest["longest_edge"] + halo.distance if source.is_mesh else halo.distance
    scratch = os.path.join(directory, "candidates")
    os.makedirs(scratch, exist_ok=True)
    paths = _distribute(source, boxes, width, scratch)
    result = []
    for cell, box, three in zip(cells, boxes, paths):
        if source.is_mesh:
            candidates = _candidates(source, three)
            owned = _owned_mask(candidates.points, tiles, lo, size, cell)
            if owned.any():
                result.append(_cut_mesh_tile(directory, candidates, cell, box, halo, owned))
        else:
            tile = _cut_point_tile(directory, source, three[0], cell, box, halo, tiles, lo, size)
            if tile.owned:
                result.append(tile)
            else:
                os.remove(tile.path)
    shutil.rmtree(scratch)
    return result


def _mesh_settings(source, directory, method, settings, tiles, lo, size, longest):
    """The settings made global: a radius "Nx" made absolute with the mean edge length of the
    whole mesh, summed from the tiles' owned edges in the input's order."""
    factor = T.relative_radius(settings.get("radius"))
    if factor is None:
        return dict(settings), None
    upper = dict(settings, radius=factor * longest)  # the mean edge is no longer than the longest
    _, width = _reach(method, upper, longest)
    cells = [(i, j) for i in range(tiles[0]) for j in range(tiles[1])]
    scratch = os.path.join(directory, "candidates")
    os.makedirs(scratch, exist_ok=True)
    paths = _distribute(source, [T.box_of(c, tiles, lo, size) for c in cells], width, scratch)
    parts = []
    for cell, three in zip(cells, paths):
        candidates = _candidates(source, three)
        owned = _owned_mask(candidates.points, tiles, lo, size, cell)
        position, length = _owned_edges(source, candidates, owned)
        parts.append((os.path.join(scratch, f"{cell[0]}_{cell[1]}.edges.npy"),
                      os.path.join(scratch, f"{cell[0]}_{cell[1]}.lengths.npy")))
        np.save(parts[-1][0], position)
        np.save(parts[-1][1], length)
    mean = _ordered_mean([(np.load(p, mmap_mode="r"), np.load(v, mmap_mode="r")) for p, v in parts],
                         source.m * source.k)
    shutil.rmtree(scratch)
    return dict(settings, radius=factor * mean), mean


def write_tiles(path, directory, tiles=(3, 3), method="paraboloid", halo=None, **settings):
    """Cuts the input at `path` into tiles with halos in `directory` (created; it must not exist),
    streaming. tiles: a grid (nx, ny) in x and y, or an int: about that many vertices a tile.
    method and settings: as mesh_curvatures' for a mesh, as point_set_curvatures' for a point set
    (method ignored; number_of_neighbors or an absolute neighbor_radius, fit_degree, unsigned).
    halo: a first halo other than the settings' (tiles.Halo). Returns the manifest. On bad input,
    InputError and no directory."""
    if os.path.exists(directory):
        raise FileExistsError(f"{directory} exists: give a new work directory")
    partial = directory.rstrip("/") + ".partial"
    shutil.rmtree(partial, ignore_errors=True)
    os.makedirs(os.path.join(partial, "tiles"))
    try:
        manifest = _write_tiles(path, partial, tiles, method, halo, settings)
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        raise
    os.rename(partial, directory)
    return manifest


def _write_tiles(path, directory, tiles, method, halo, settings):
    source = open_input(os.path.abspath(path), directory)
    grid, lo, size, longest = _scan(source, tiles)
    manifest = dict(input=os.path.abspath(path), kind="mesh" if source.is_mesh else "points", vertices=source.n,
                    faces=source.m, face_size=source.k, tiles=list(grid), lo=list(lo), size=list(size),
                    longest_edge=longest)
    if source.is_mesh:
        settings, mean = _mesh_settings(source, directory, method, settings, grid, lo, size, longest)
        needed, _ = _reach(method, settings, longest)
        first = T.Halo.around(needed)
        manifest.update(method=method, mean_edge_length=mean, needed=list(needed))
    else:
        if isinstance(settings.get("neighbor_radius"), str):
            raise InputError("a point set's tiles take an absolute neighbor_radius")
        if not source.has_normals and not settings.get("unsigned"):
            # The propagation orients the normals over the whole set (normal_orientation.h): a tile
            # alone may orient a part the other way.
            raise InputError(f"{path}: a point set without normals is cut into tiles only with unsigned=True "
                             "(the orientation of its normals is global)")
        first = T.Halo(0, _point_halo(source, grid, lo, size, settings))
        manifest.update(method="point-set")
    halo = halo or first
    manifest.update(settings=settings, halo=list(halo))
    cells = [(i, j) for i in range(grid[0]) for j in range(grid[1])]
    cut = _cut_all(source, directory, manifest, cells)
    manifest["tile_files"] = [t._asdict() for t in cut]
    for entry in manifest["tile_files"]:
        entry["path"] = os.path.relpath(entry["path"], directory)
    with open(os.path.join(directory, "manifest.json"), "w", encoding="utf-8") as f:
        json.dump(manifest, f, indent=1)
    return manifest


def _load_tile(path):
    with np.load(path) as a:
        arrays = {k: a[k] for k in a.files}
    arrays["halo"] = T.Halo(int(arrays["halo"][0]), float(arrays["halo"][1]))
    return arrays


def _point_check(arrays, settings, status):
    """The owned points (local indices) whose neighborhood could reach past the tile's points:
    those nearer in x and y to the edge of the tile's region than their farthest neighbor could be
    (point_set_reach: the radius, or the farthest of the nearest neighbors in the tile it reads, by status)."""
    from scipy.spatial import cKDTree
    points, owned = arrays["points"], np.flatnonzero(arrays["owned"])
    box, halo = tuple(arrays["box"]), arrays["halo"]
    ok = status[owned] == Status.ok
    needed = _point_reach(settings)
    if needed.distance > 0:
        reach = np.where(ok, needed.distance, needed.grown_distance)
    else:
        if len(points) <= needed.widened_neighbors:
            return owned  # fewer points in the tile than a neighborhood may read
        tree = cKDTree(points)
        reach = np.empty(len(owned))
        for where, count in ((ok, needed.neighbors + 1), (~ok, needed.widened_neighbors + 1)):  # the point first
            if where.any():
                reach[where] = tree.query(points[owned[where]], k=[count])[0][:, 0]
    return owned[T.box_gap(points[owned], box, halo) <= reach]


def run_file(tile_path, result_path, kind, method, settings, needed, threads=1):
    """A task: the tile at tile_path estimated and checked; its owned values and their global indices
    written to result_path (.npz, written whole or not at all). Returns (result_path, the global
    indices the check flags, the farthest their balls reached, the task's seconds). needed: a mesh's
    MeshReach (None for a point set)."""
    start = time.monotonic()
    arrays = _load_tile(tile_path)
    owned = arrays["owned"]
    if kind == "mesh":
        tile = T.Tile(tuple(arrays["cell"]), tuple(arrays["box"]), arrays["halo"], arrays["vertices"],
                      arrays["faces"], owned, arrays["complete"])
        r, reach = _mesh_curvatures(arrays["points"], tile.faces, method, threads=threads, **settings)
        flagged = T.check_tile(tile, arrays["points"], reach, needed)
        reached = float(reach[flagged].max(initial=0.0))
    else:
        r = point_set_curvatures(arrays["points"], normals=arrays.get("normals"), threads=threads, **settings)
        flagged = _point_check(arrays, settings, r.status)
        reached = 0.0
    partial = result_path + ".partial.npz"
    np.savez(partial, vertices=arrays["vertices"][owned], **{f: a[owned] for f, a in zip(r._fields, r)})
    os.replace(partial, result_path)
    return result_path, arrays["vertices"][flagged], reached, time.monotonic() - start


def _columns(kind, n):
    fields = MeshCurvatures._fields if kind == "mesh" else PointSetCurvatures._fields
    return [(f, (n, 3) if f in ("d_max", "d_min", "normal") else (n,), np.uint8 if f == "status" else np.float64)
            for f in fields]


def _stitch(directory, manifest, kept):
    """The tiles' results in one .npy a column in directory/columns, by global index."""
    target = os.path.join(directory, "columns")
    os.makedirs(target, exist_ok=True)
    columns = {f: np.lib.format.open_memmap(os.path.join(target, f + ".npy"), "w+", dtype, shape)
               for f, shape, dtype in _columns(manifest["kind"], manifest["vertices"])}
    for path in kept:
        with np.load(path) as r:
            index = r["vertices"]
            for f, column in columns.items():
                column[index] = r[f]
    for column in columns.values():
        column.flush()
    return target


def _write_ply(columns, path):
    """The columns as a binary little-endian PLY of one vertex element, streaming."""
    arrays = _load_columns(columns, "r")
    order = [f for f in PointSetCurvatures._fields if f in arrays]
    fields = []
    for f in order:
        if arrays[f].ndim == 2:
            fields += [(f"{f}_{c}", "<f8") for c in "xyz"]
        else:
            fields.append((f, "u1" if f == "status" else "<f8"))
    row = np.dtype(fields)
    n = len(arrays["status"])
    names = {"u1": "uchar", "<f8": "double"}
    header = ["ply", "format binary_little_endian 1.0", f"element vertex {n}"]
    header += [f"property {names[t]} {name}" for name, t in fields] + ["end_header"]
    with open(path + ".partial", "wb") as out:
        out.write(("\n".join(header) + "\n").encode("ascii"))
        for a in range(0, n, CHUNK):
            chunk = np.empty(min(CHUNK, n - a), dtype=row)
            for f in order:
                if arrays[f].ndim == 2:
                    for i, c in enumerate("xyz"):
                        chunk[f"{f}_{c}"] = arrays[f][a:a + CHUNK, i]
                else:
                    chunk[f] = arrays[f][a:a + CHUNK]
            out.write(chunk.tobytes())
    os.replace(path + ".partial", path)


class StreamedRun(NamedTuple):
    """What run_directory did: the TiledRun and where the columns are."""

    run: T.TiledRun
    columns: str


def run_directory(directory, scheduler="serial", output=None, max_recuts=4, threads=1, progress=None):
    """Runs the tiles written by write_tiles in `directory`, one task per tile (scheduler as
    tiles.run_tiles'), re-cutting a flagged tile from the input with a wider halo; stitches the
    results into directory/columns (one .npy a column, by global index) and, where `output` is
    given, writes them to it: a new directory of .npy columns, or a binary PLY (.ply). Returns a StreamedRun."""
    start = time.monotonic()
    if output is not None and not output.endswith(".ply") and os.path.exists(output):
        raise FileExistsError(f"{output} exists: give a new directory for the columns")
    with open(os.path.join(directory, "manifest.json"), encoding="utf-8") as f:
        manifest = json.load(f)
    kind, method, settings = manifest["kind"], manifest["method"], manifest["settings"]
    needed = MeshReach(*manifest["needed"]) if kind == "mesh" else None
    results = os.path.join(directory, "results")
    os.makedirs(results, exist_ok=True)
    tiles = [TileFile(tuple(t["cell"]), tuple(t["box"]), T.Halo(*t["halo"]), os.path.join(directory, t["path"]),
                      t["vertices"], t["owned"]) for t in manifest["tile_files"]]
    source = None
    kept_results = {}

    def task(driver, tile):
        result = os.path.join(results, f"{tile.cell[0]}_{tile.cell[1]}.npz")
        return driver.submit(run_file, tile.path, result, kind, method, settings, needed, threads)

    def again(tile, reached):
        nonlocal source
        if source is None:
            source = open_input(manifest["input"], directory)
        wider = tile.halo.wider(needed, reached) if kind == "mesh" else T.Halo(0, tile.halo.distance * 1.5)
        return _cut_all(source, directory, dict(manifest, halo=list(wider)), [tile.cell])[0]

    def keep(tile, result):
        kept_results[tile.cell] = result[0]
        with np.load(result[0]) as r:
            return len(r["vertices"])

    kept, recuts, task_seconds = T.schedule(scheduler, tiles, task, again, keep, max_recuts, progress)
    owned = sum(t.owned for t in kept)
    if owned != manifest["vertices"]:
        raise RuntimeError(f"{directory}: the tiles own {owned} vertices of {manifest['vertices']}")
    columns = _stitch(directory, manifest, [kept_results[t.cell] for t in kept])
    if output is not None:
        if output.endswith(".ply"):
            _write_ply(columns, output)
        else:
            shutil.copytree(columns, output)
    n = manifest["vertices"]
    run = T.TiledRun(len(tiles), recuts, sum(t.vertices for t in kept) / n - 1, time.monotonic() - start,
                     task_seconds, {t.cell: t.halo for t in kept})
    return StreamedRun(run, columns)


def _load_columns(directory, mmap_mode=None):
    return {f[:-4]: np.load(os.path.join(directory, f), mmap_mode=mmap_mode)
            for f in os.listdir(directory) if f.endswith(".npy")}


def read_columns(directory):
    """The columns of a run (a directory of .npy) as MeshCurvatures or PointSetCurvatures."""
    arrays = _load_columns(directory)
    kind = PointSetCurvatures if "normal" in arrays else MeshCurvatures
    return kind(*(arrays[f] for f in kind._fields))


def input_kind(path):
    """"mesh" or "points": what the input at `path` holds, from its name or its PLY header."""
    if path.lower().endswith(".ply"):
        elements, _ = _ply_header(path)
        return "mesh" if any(name == "face" for name, _, _ in elements) else "points"
    return "points" if path.lower().endswith(".xyz") else "mesh"
