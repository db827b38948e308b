# SPDX-License-Identifier: GPL-3.0-or-later
"""What the tests of curvature_estimation share: the tool `curvature` they compare with
(CE_CURVATURE_TOOL, default build/tools/curvature), meshes made here, the bunny of the
build (CE_BUNNY, default build/data/meshes/bunny00.off), and the tool's files."""

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import curvature_estimation as ce

ROOT = Path(__file__).resolve().parents[2]


def tool_path():
    path = Path(os.environ.get("CE_CURVATURE_TOOL", ROOT / "build" / "tools" / "curvature"))
    if not path.is_file():
        pytest.fail(f"the tool {path} does not exist: build it (cmake --build build --target curvature) "
                    "or set CE_CURVATURE_TOOL")
    return path


def bunny_path():
    return Path(os.environ.get("CE_BUNNY", ROOT / "build" / "data" / "meshes" / "bunny00.off"))


def text(x):
    """The shortest text that reads back to the same double (as the tool's to_chars)."""
    return repr(float(x))


def write_off(path, vertices, faces):
    lines = ["OFF", f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(text(c) for c in v) for v in vertices]
    lines += [" ".join(str(int(i)) for i in [len(f), *f]) for f in faces]
    Path(path).write_text("\n".join(lines) + "\n")


def write_medit(mesh_path, sol_path, vertices, tetrahedra, scalars):
    lines = ["MeshVersionFormatted 2", "Dimension 3", "Vertices", str(len(vertices))]
    lines += [" ".join(text(c) for c in v) + " 0" for v in vertices]
    lines += ["Tetrahedra", str(len(tetrahedra))]
    lines += [" ".join(str(int(i) + 1) for i in t) + " 0" for t in tetrahedra]
    lines += ["End"]
    Path(mesh_path).write_text("\n".join(lines) + "\n")
    lines = ["MeshVersionFormatted 2", "Dimension 3", "SolAtVertices", str(len(scalars)), "1 1"]
    lines += [text(f) for f in scalars] + ["End"]
    Path(sol_path).write_text("\n".join(lines) + "\n")


def run_tool(tmp_path, input_path, *options):
    """The tool's CSV of `input_path`: its header's names, the values (float64, NaN for "nan") and statuses."""
    out = tmp_path / "out.csv"
    result = subprocess.run([str(tool_path()), *map(str, options), "-o", str(out), str(input_path)],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    rows = out.read_text().splitlines()
    header = rows[0].split(",")
    values = np.array([[float(x) for x in row.split(",")[:-1]] for row in rows[1:]])
    status = np.array([int(ce.Status[row.rsplit(",", 1)[1]]) for row in rows[1:]], dtype=np.uint8)
    return header, values, status, result.stderr


def assert_bit_identical(actual, expected):
    """Equal bit for bit, every NaN matched by a NaN (the tool writes any NaN as "nan")."""
    actual = np.asarray(actual, dtype=np.float64)
    expected = np.asarray(expected, dtype=np.float64)
    assert actual.shape == expected.shape
    nan = np.isnan(expected)
    np.testing.assert_array_equal(np.isnan(actual), nan)
    different = actual[~nan].view(np.uint64) != expected[~nan].view(np.uint64)
    assert not different.any(), (f"{different.sum()} of {different.size} values differ, e.g. "
                                 f"{actual[~nan][different][:3]} against {expected[~nan][different][:3]}")


# Meshes made here.

def grid_graph(n=17, jitter=0.0, seed=1):
    """Triangulated grid over [-1, 1]^2 lifted onto z = 0.3 sin(x) cos(1.5 y) (boundary included)."""
    rng = np.random.default_rng(seed)
    u, v = np.meshgrid(np.linspace(-1, 1, n), np.linspace(-1, 1, n), indexing="ij")
    step = 2.0 / (n - 1)
    u = u + jitter * step * rng.uniform(-0.5, 0.5, u.shape) * (np.abs(u) < 1)
    v = v + jitter * step * rng.uniform(-0.5, 0.5, v.shape) * (np.abs(v) < 1)
    vertices = np.column_stack([u.ravel(), v.ravel(), 0.3 * np.sin(u.ravel()) * np.cos(1.5 * v.ravel())])
    faces = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
            faces += [[a, b, c], [a, c, d]]
    return vertices, np.array(faces, dtype=np.int64)


def torus(major=16, minor=10, R=1.0, r=0.4, quads=False):
    """A closed torus grid, of quads or triangles."""
    s, t = np.meshgrid(np.arange(major) * 2 * np.pi / major, np.arange(minor) * 2 * np.pi / minor, indexing="ij")
    s, t = s.ravel(), t.ravel()
    vertices = np.column_stack([(R + r * np.cos(t)) * np.cos(s), (R + r * np.cos(t)) * np.sin(s), r * np.sin(t)])
    faces = []
    for i in range(major):
        for j in range(minor):
            a, b = i * minor + j, ((i + 1) % major) * minor + j
            c, d = ((i + 1) % major) * minor + (j + 1) % minor, i * minor + (j + 1) % minor
            faces += [[a, b, c, d]] if quads else [[a, b, c], [a, c, d]]
    return vertices, np.array(faces, dtype=np.int64)


@pytest.fixture(scope="session")
def tiles_mesh():
    """The jittered grid the tiles are tested on: 50,176 vertices."""
    return grid_graph(n=224, jitter=0.4)


@pytest.fixture(scope="session")
def bunny():
    path = bunny_path()
    if not path.is_file():
        pytest.skip(f"no bunny at {path} (CMake extracts it from libcgal-demo; or set CE_BUNNY)")
    return ce.read_off(path)
