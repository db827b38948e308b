#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A picture of the mean curvature H on a mesh: reads an OFF file (curvature_estimation.read_off),
estimates with mesh_curvatures and saves a PNG of H on the faces (matplotlib, headless).

    python3 mean_curvature_picture.py [MESH.off] [-o H.png] [-m METHOD] [--up x|y|z]

Without MESH: the bunny of the build (build/data/meshes/bunny00.off), else a torus made here.
The colours are clipped at the 2nd and 98th percentiles of H: a few extreme vertices would
otherwise leave the rest of the mesh one colour. A face takes the mean of its vertices' H;
a face with a failed vertex is grey. The faces are shaded by a light from the viewer.
"""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # headless: no display needed

import matplotlib.pyplot as plt  # noqa: E402 (after the backend)
import numpy as np  # noqa: E402
from matplotlib import colors  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import curvature_estimation as ce  # noqa: E402

BUNNY = Path(__file__).resolve().parents[2] / "build" / "data" / "meshes" / "bunny00.off"


def torus(major=64, minor=32, R=1.0, r=0.4):
    """A closed triangulated torus around the y axis."""
    s, t = np.meshgrid(np.arange(major) * 2 * np.pi / major, np.arange(minor) * 2 * np.pi / minor, indexing="ij")
    ring = R + r * np.cos(t.ravel())
    vertices = np.column_stack([ring * np.cos(s.ravel()), r * np.sin(t.ravel()), ring * np.sin(s.ravel())])
    i, j = np.meshgrid(np.arange(major), np.arange(minor), indexing="ij")
    a, b = i * minor + j, (i + 1) % major * minor + j
    c, d = (i + 1) % major * minor + (j + 1) % minor, i * minor + (j + 1) % minor
    faces = np.concatenate([np.column_stack([a.ravel(), b.ravel(), c.ravel()]),
                            np.column_stack([a.ravel(), c.ravel(), d.ravel()])])
    return vertices, faces


def load(path=None):
    """The mesh at `path`, else the bunny of the build, else the torus; and its name."""
    if path is None and BUNNY.is_file():
        path = BUNNY
    if path is None:
        return (*torus(), "a torus")
    return (*ce.read_off(path), Path(path).name)


def picture(vertices, faces, H, path, title, up="y"):
    """Saves the faces coloured by the mean of their vertices' H, clipped at H's 2nd and 98th percentiles."""
    # Plot coordinates: `up` as matplotlib's z, the other two in order (right-handed).
    axis = "xyz".index(up)
    order = [(axis + 1) % 3, (axis + 2) % 3, axis]
    corners = vertices[:, order][faces]  # (m, k, 3)
    face_H = H[faces].mean(axis=1)  # NaN where a vertex failed
    low, high = np.nanpercentile(H, [2, 98])
    norm = (colors.TwoSlopeNorm(0.0, low, high) if low < 0 < high else colors.Normalize(low, high))
    cmap = plt.get_cmap("coolwarm")
    rgba = cmap(norm(np.clip(face_H, low, high)))
    rgba[np.isnan(face_H)] = colors.to_rgba("0.6")

    fig = plt.figure(figsize=(7, 6))
    ax = fig.add_subplot(projection="3d")
    elevation, azimuth = 20, -60
    ax.view_init(elev=elevation, azim=azimuth)
    # Lambert shading by a light from the viewer, on either side of a face.
    e, a = np.radians(elevation), np.radians(azimuth)
    viewer = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    light = np.abs(normals @ viewer) / np.where(lengths > 0, lengths, 1)
    rgba[:, :3] *= (0.35 + 0.65 * light)[:, None]
    ax.add_collection3d(Poly3DCollection(corners, facecolors=rgba, edgecolors="none"))
    low_corner, high_corner = corners.reshape(-1, 3).min(axis=0), corners.reshape(-1, 3).max(axis=0)
    ax.set(xlim=(low_corner[0], high_corner[0]), ylim=(low_corner[1], high_corner[1]),
           zlim=(low_corner[2], high_corner[2]))
    ax.set_box_aspect(high_corner - low_corner)
    ax.set_axis_off()
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.7)
    bar.set_label("H (clipped at its 2nd and 98th percentiles)")
    ax.set_title(title)
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", nargs="?", help="an OFF file (default: the bunny of the build, else a torus)")
    parser.add_argument("-o", "--output", default="mean_curvature.png", help="the PNG (default: %(default)s)")
    parser.add_argument("-m", "--method", default=ce.METHODS[0], choices=ce.METHODS)
    parser.add_argument("--up", default="y", choices="xyz", help="the axis drawn upwards (default: y)")
    args = parser.parse_args()

    vertices, faces, name = load(args.mesh)
    r = ce.mesh_curvatures(vertices, faces, args.method)
    statuses = ", ".join(f"{np.count_nonzero(r.status == s)} {s.name}" for s in ce.Status if (r.status == s).any())
    print(f"{name}: {len(vertices)} vertices, {len(faces)} faces; {args.method}: {statuses}")
    print("H percentiles 2, 50, 98: " + ", ".join(f"{q:.4g}" for q in np.nanpercentile(r.mean, [2, 50, 98])))
    picture(vertices, faces, r.mean, args.output, f"mean curvature of {name} ({args.method})", args.up)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
