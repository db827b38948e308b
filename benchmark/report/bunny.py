# SPDX-License-Identifier: GPL-3.0-or-later
"""The bunny coloured by mean curvature: of every estimator, and of the default over balls."""
import math
import os
import re

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

def curvature_scale(lo, hi):
    """The colour scale of H: centred on 0 so that the colour tells the sign."""
    if lo < 0 < hi:
        return matplotlib.colors.TwoSlopeNorm(0.0, lo, hi), "coolwarm", "mean curvature H"
    return matplotlib.colors.Normalize(lo, hi), "coolwarm", "mean curvature H"


def bunny_figure(vpath, fpath, title, path, scale=curvature_scale, panel_width=4.5):
    """Renders the bunny of fpath (three vertex indices per row) once per column of vpath
    (x,y,z, then one column per name; by default H), four panels a row, titled title(name), in one
    colour scale, into path. scale(lo, hi) gives the colour scale's norm, colour map and label from
    the bounds of the values; the colour bar takes a share of the width, which fewer or narrower
    panels than three of 4.5 inches leave too small for its label. Returns the number of vertices
    and the bounds of the colour scale."""
    with open(vpath) as f:
        header = f.readline().strip().split(",")
    values = np.genfromtxt(vpath, delimiter=",", skip_header=1)
    faces = np.genfromtxt(fpath, delimiter=",", skip_header=1, dtype=np.int64)
    xyz = values[:, :3]
    names = header[3:]
    # bunny00.off is y-up; matplotlib's 3D axes are z-up.
    pts = xyz[:, [0, 2, 1]]
    tris = pts[faces]
    # One colour scale for all panels, clamped at the 5th and 95th percentiles over every
    # panel (the scanned bunny is noisy: a few per cent of the vertices have |H| ten times
    # the median and would wash the rest out).
    lo_h, hi_h = (float(x) for x in np.nanpercentile(values[:, 3:], [5, 95]))
    norm, cmap_name, label = scale(lo_h, hi_h)
    cmap = matplotlib.colormaps[cmap_name]
    ncols = min(4, len(names))
    nrows = int(math.ceil(len(names) / ncols))
    fig = plt.figure(figsize=(panel_width * ncols, 4.2 * nrows))
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    for i, name in enumerate(names):
        ax = fig.add_subplot(nrows, ncols, i + 1, projection="3d")
        h = values[:, 3 + i]
        face_h = h[faces].mean(axis=1)
        colors = cmap(norm(np.nan_to_num(face_h, nan=0.0)))
        colors[~np.isfinite(face_h)] = (0.5, 0.5, 0.5, 1.0)  # not estimable: grey
        ax.add_collection3d(Poly3DCollection(tris, facecolors=colors, linewidths=0))
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect(hi - lo, zoom=1.6)  # the default leaves the bunny small in its panel
        ax.view_init(elev=10, azim=-80)
        ax.set_axis_off()
        ax.set_title(title(name), fontsize=10)
    fig.subplots_adjust(left=0, right=0.92, bottom=0, top=0.95, wspace=0, hspace=0.05)
    cax = fig.add_axes([0.94, 0.2, 0.012, 0.6])
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), cax=cax, label=label)
    fig.savefig(path, dpi=72)  # ~1 MB for the bunny of every estimator: it is committed
    plt.close(fig)
    return len(xyz), lo_h, hi_h


def bunny_section(est, accuracy_dir, figures):
    """The bunny coloured by H of every estimator that gives it."""
    vpath = os.path.join(accuracy_dir, "bunny_mean_curvature.csv")
    fpath = os.path.join(accuracy_dir, "bunny_faces.csv")
    if not (os.path.exists(vpath) and os.path.exists(fpath)):
        return ["## The bunny", "", "No bunny output (accuracy_runner did not write it).", ""]
    vertices, lo_h, hi_h = bunny_figure(vpath, fpath, est.label_of,
                                        os.path.join(figures, "bunny_mean_curvature.png"))
    return ["## The bunny coloured by mean curvature", "",
            "![bunny](figures/bunny_mean_curvature.png)", "",
            "`bunny00.off` (%s vertices, about 1 unit across), face colour = mean of its vertices' H, one colour "
            "scale for every panel, clamped at [%.3g, %.3g] (5th and 95th percentiles of H over all estimators) "
            "and centred on 0; grey = not estimable. The \"given normals\" panel is given the package's default "
            "normal estimate. Red: H > 0 (convex with outward normals), blue: H < 0." % (
                "{:,}".format(vertices), lo_h, hi_h), ""]


def bunny_radius(est, accuracy_dir, figures):
    """The bunny coloured by the default paraboloid fit over its 1-ring and over two balls."""
    vpath = os.path.join(accuracy_dir, "bunny_ball_mean_curvature.csv")
    fpath = os.path.join(accuracy_dir, "bunny_faces.csv")
    if not (os.path.exists(vpath) and os.path.exists(fpath)):
        return ["No bunny over balls (accuracy_runner did not write it).", ""]

    def title(name):
        m = re.match(r"^ball_(\d+)h$", name)
        return "ball radius %s h" % m.group(1) if m else "%s (1 ring)" % est.label_of(name)

    vertices, lo_h, hi_h = bunny_figure(vpath, fpath, title, os.path.join(figures, "bunny_radius.png"))
    return ["### The bunny over balls", "",
            "![bunny over balls](figures/bunny_radius.png)", "",
            "`bunny00.off` (%s vertices) coloured by H of the default paraboloid fit over its 1-ring and over balls "
            "(`ball_radius` in mean edge lengths h of the bunny), as in the bunny section: one colour scale, clamped at "
            "[%.3g, %.3g] (5th and 95th percentiles of H over these panels), centred on 0; red H > 0, blue H < 0. "
            "The scan's noise fades as the ball grows; where the ball is wider than the surface is round (the rims of the "
            "ears, whose radius of curvature 1/H is a few edges), the surface in the ball is no graph over the tangent "
            "plane, and the fit's H changes sign." % ("{:,}".format(vertices), lo_h, hi_h), ""]
