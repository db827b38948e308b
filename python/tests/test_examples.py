# SPDX-License-Identifier: GPL-3.0-or-later
"""The example scripts of python/examples/ run, on a small mesh made here: the picture of H is
a PNG of many colours; the comparison with libigl and PyVista exits with 0 (and says so where
neither is importable)."""

import importlib.util
import subprocess
import sys

import matplotlib.image
import numpy as np

from conftest import ROOT, torus, write_off

EXAMPLES = ROOT / "python" / "examples"


def run_example(name, *arguments, cwd):
    result = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, arguments)], capture_output=True,
                            text=True, cwd=cwd, check=False)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_mean_curvature_picture(tmp_path):
    mesh, png = tmp_path / "torus.off", tmp_path / "out" / "H.png"
    write_off(mesh, *torus(major=24, minor=12))
    png.parent.mkdir()
    stdout = run_example("mean_curvature_picture.py", mesh, "-o", png, cwd=tmp_path)
    assert "torus.off: 288 vertices, 576 faces" in stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    pixels = matplotlib.image.imread(png)[..., :3].reshape(-1, 3)
    # A torus's H runs from its inner to its outer side: a range of colours of the
    # colour map, shaded, not a blank or one-coloured picture.
    assert len(np.unique(np.round(pixels * 255), axis=0)) > 100


def test_comparison_with_libigl_and_pyvista(tmp_path):
    mesh = tmp_path / "torus.off"
    write_off(mesh, *torus(major=24, minor=12))
    stdout = run_example("compare_with_libigl_pyvista.py", mesh, cwd=tmp_path)
    if importlib.util.find_spec("igl") is None and importlib.util.find_spec("pyvista") is None:
        assert "nothing to compare" in stdout
    else:
        assert "vertices both estimate" in stdout
