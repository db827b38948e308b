#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""mesh_curvatures beside libigl's principal_curvature and PyVista's curvature, where those
Python packages are importable (`import igl`, `import pyvista`; Debian packages neither: they
come from pip, e.g. in a virtual environment). Where neither is, says so and exits with 0.

    python3 compare_with_libigl_pyvista.py [MESH.off] [-m METHOD]

MESH as mean_curvature_picture.py takes it (default: the bunny of the build, else a torus).
For each package and quantity, over the vertices both estimate: the correlation of the two
estimates and the median of |theirs - ours| / median |ours|. A package whose mean curvature
correlates negatively with ours orients its normals the other way: its values are negated
(k_max and k_min exchanged) first, and the script says so.
"""
import argparse
import importlib.util

import numpy as np

import curvature_estimation as ce
from mean_curvature_picture import load

QUANTITIES = ("k_max", "k_min", "mean", "gaussian")


def libigl(vertices, faces):
    import igl

    # principal_curvature gives the max and min directions, then values (and, in newer
    # versions, the vertices it could not estimate).
    _, _, k_max, k_min = igl.principal_curvature(vertices, faces)[:4]
    return {"k_max": k_max, "k_min": k_min, "mean": (k_max + k_min) / 2, "gaussian": k_max * k_min}


def pyvista(vertices, faces):
    import pyvista as pv

    mesh = pv.PolyData(vertices, np.column_stack([np.full(len(faces), faces.shape[1]), faces]).ravel())
    names = {"k_max": "maximum", "k_min": "minimum", "mean": "mean", "gaussian": "gaussian"}
    return {q: np.asarray(mesh.curvature(name), dtype=np.float64) for q, name in names.items()}


OTHERS = {"libigl": ("igl", libigl), "PyVista": ("pyvista", pyvista)}


def compare(name, ours, theirs):
    both = np.all([np.isfinite(ours[q]) & np.isfinite(theirs[q]) for q in QUANTITIES], axis=0)
    if np.corrcoef(ours["mean"][both], theirs["mean"][both])[0, 1] < 0:
        print(f"{name}: its mean curvature has the opposite sign: its normals point the other way; negated")
        theirs = {"k_max": -theirs["k_min"], "k_min": -theirs["k_max"], "mean": -theirs["mean"],
                  "gaussian": theirs["gaussian"]}
    print(f"{name}, {np.count_nonzero(both)} vertices both estimate:")
    print(f"  {'quantity':10} {'correlation':>12} {'median |theirs - ours| / median |ours|':>40}")
    for q in QUANTITIES:
        a, b = ours[q][both], theirs[q][both]
        relative = np.median(np.abs(b - a)) / np.median(np.abs(a))
        print(f"  {q:10} {np.corrcoef(a, b)[0, 1]:12.4f} {relative:40.4f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", nargs="?", help="an OFF file (default: the bunny of the build, else a torus)")
    parser.add_argument("-m", "--method", default=ce.METHODS[0], choices=ce.METHODS)
    args = parser.parse_args()

    present = {name: run for name, (module, run) in OTHERS.items() if importlib.util.find_spec(module) is not None}
    if not present:
        print("neither libigl (import igl) nor PyVista (import pyvista) is importable here: nothing to compare "
              "(neither is a Debian package; pip installs them, e.g. in a virtual environment)")
        return
    vertices, faces, name = load(args.mesh)
    r = ce.mesh_curvatures(vertices, faces, args.method)
    ours = {q: getattr(r, q) for q in QUANTITIES}
    print(f"{name}: {len(vertices)} vertices, {len(faces)} faces; ours: {args.method}")
    for other, run in present.items():
        compare(other, ours, run(vertices, faces))


if __name__ == "__main__":
    main()
