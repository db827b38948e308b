# SPDX-License-Identifier: GPL-3.0-or-later
"""The scale-selection section: the error of H over fixed balls against the radius chosen per vertex
(ball_radius_range) on the noisy family (accuracy_runner's scale_selection.csv), and the radius and the
noise per vertex on the bunny. accuracy_runner --only scale writes its inputs alone, and
make_report.py --section scale writes this section alone into an existing report."""
import math
import os
from collections import defaultdict

import matplotlib
import matplotlib.pyplot as plt
import numpy as np

from report import inputs
from report.bunny import bunny_figure
from report.markdown import save_figure, table

TITLE = "## Scale selection on the noisy family"
# The estimators of the section: ours, CGAL's jet fitting, CGAL 6's ICC (fixed balls only).
COMPARED = ["paraboloid_ball", "jet_d2_ball", "icc_ball"]


def best_fixed(fixed):
    """(error, radius in h) of the least error of {radius: error}."""
    r = min(fixed, key=fixed.get)
    return fixed[r], r


def fmt_radius(r):
    return "%.3g h" % r


def scale_plot(est, meshes, fixed, selected, labels, path):
    """One panel per mesh: H RMS against the fixed radius, the selection as a horizontal line."""
    fig, axes = plt.subplots(1, len(meshes), figsize=(4.2 * len(meshes), 4.2), squeeze=False)
    for ax, mesh in zip(axes[0], meshes):
        for e in COMPARED:
            if (mesh, e) not in fixed:
                continue
            style = est.style(labels[e][1])
            radii = sorted(fixed[(mesh, e)])
            ax.plot(radii, [fixed[(mesh, e)][r] for r in radii], label="%s, ball" % labels[e][0], **style)
            if (mesh, e) in selected:
                ax.axhline(selected[(mesh, e)]["H_rms"], color=style["color"], ls=":", lw=1.5,
                           label="%s, selected per vertex" % labels[e][0])
        radii = sorted({r for (m, _), v in fixed.items() if m == mesh for r in v})
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xticks(radii)
        ax.set_xticklabels(["%.3g" % r for r in radii], fontsize=7)
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("ball radius r (mean edge lengths h)")
        ax.set_title(mesh, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("interior RMS error of H")
    axes[0][0].legend(fontsize=7)
    save_figure(fig, path, 80)


def radius_scale(lo, hi):
    return matplotlib.colors.Normalize(lo, hi), "viridis", "radius chosen (mean edge lengths h)"


def noise_scale(lo, hi):
    return matplotlib.colors.Normalize(lo, hi), "magma", "noise estimated (mean edge lengths h)"


def bunny_scale(accuracy_dir, figures):
    """The bunny coloured by the radius chosen and by the noise estimated, as scanned and with noise."""
    fpath = os.path.join(accuracy_dir, "bunny_faces.csv")
    paths = [os.path.join(accuracy_dir, "bunny_scale_%s.csv" % q) for q in ("radius", "noise")]
    if not all(os.path.exists(p) for p in paths + [fpath]):
        return ["No bunny with the scale selection (accuracy_runner did not write it).", ""]

    def title(name):
        return {"scan": "bunny00 as scanned", "noisy": "with noise of 0.1 h added"}[name]

    medians = {}
    for q, p in zip(("radius", "noise"), paths):
        values = np.genfromtxt(p, delimiter=",", names=True)
        medians[q] = {c: float(np.nanmedian(values[c])) for c in ("scan", "noisy")}
    vertices, lo_r, hi_r = bunny_figure(paths[0], fpath, title, os.path.join(figures, "bunny_scale_radius.png"),
                                        radius_scale, 6.75)
    _, lo_n, hi_n = bunny_figure(paths[1], fpath, title, os.path.join(figures, "bunny_scale_noise.png"), noise_scale,
                                 6.75)
    return ["### The radius and the noise per vertex on the bunny", "",
            "![radius chosen on the bunny](figures/bunny_scale_radius.png)", "",
            "![noise estimated on the bunny](figures/bunny_scale_noise.png)", "",
            "`bunny00.off` (%s vertices) as scanned, and with Gaussian noise of 0.1 of its mean edge length h added "
            "in each coordinate (`ce_test::add_gaussian_noise`, seed 1; drawn on the scan's points): the radius the "
            "default paraboloid fit with `ball_radius_range(1 h, 16 h)` chooses per vertex (`vertex_ball_radius_map`; "
            "where the default 1-ring estimate is kept, the largest distance of the 1-ring) and the noise it "
            "estimates (`vertex_noise_map`), both in h of each mesh; face colour = mean of its vertices' values, "
            "clamped at the 5th and 95th percentiles over both panels ([%.3g, %.3g] h for the radius; "
            "[%.3g, %.3g] h for the noise). Medians: radius %.3g h as scanned, %.3g h with the noise; noise "
            "estimated %.3g h as scanned, %.3g h with the noise (the scan's own noise and the noise added, "
            "0.1 h, add as variances)."
            % ("{:,}".format(vertices), lo_r, hi_r, lo_n, hi_n, medians["radius"]["scan"], medians["radius"]["noisy"],
               medians["noise"]["scan"], medians["noise"]["noisy"]), ""]


def scale_section(est, accuracy_dir, figures):
    """The selection against fixed balls on the noisy family (scale_selection.csv), and the bunny."""
    path = os.path.join(accuracy_dir, "scale_selection.csv")
    if not os.path.exists(path):
        return [TITLE, "", "No scale-selection output (accuracy_runner did not write it).", ""]
    rows = inputs.read_scale_selection(path)
    fixed = defaultdict(dict)  # {(mesh, estimator): {radius in h: H RMS}}
    selected = {}  # {(mesh, estimator): row of the selection}
    for r in rows:
        if r["radius_edges"] is None:
            selected[(r["mesh"], r["estimator"])] = r
        else:
            fixed[(r["mesh"], r["estimator"])][r["radius_edges"]] = r["H_rms"]
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))
    vertices = {r["mesh"]: r["vertices"] for r in rows}
    labels = {e: (label, like) for e, label, like in est.ball if e in COMPARED}
    shown = [e for e in COMPARED if e in labels and any(k[1] == e for k in fixed)]
    with_selection = [e for e in shown if any(k[1] == e for k in selected)]
    radii = sorted({r for v in fixed.values() for r in v})
    cgal_path = os.path.join(accuracy_dir, "cgal_version.txt")
    cgal = open(cgal_path).read().strip() if os.path.exists(cgal_path) else "unknown"

    lines = [TITLE, ""]
    size = {m.split()[0]: "{:,}".format(vertices[m]) for m in meshes}
    lines.append("The noisy family of `test_scale_selection` (`ce_test::noisy_family_soup`, test/common/noisy_meshes.h): "
                 "an ellipsoid (semi-axes 1, 0.8, 0.6) of %s vertices, a torus (R = 1, r = 0.4) of %s and a Delaunay "
                 "mesh of %s random points over Hamann's trigonometric graph, each jittered, then with Gaussian noise "
                 "of 1%%, 5%% or 15%% of the mean edge length in each coordinate, or of 0 to 15%% varying along x. "
                 "Interior RMS error of H against the exact curvature of the points before the noise (the Delaunay "
                 "mesh: the vertices whose balls of 16 h stay inside the domain; the closed surfaces: every vertex). "
                 "Fixed balls: `ball_radius(r)` with r = %s mean edge lengths h of the noisy mesh, of %s. Selected per "
                 "vertex: `ball_radius_range(std::make_pair(1 h, 16 h))` (the manual's \"Choosing the radius per "
                 "vertex\") of %s; ICC has no selection. All threads; CGAL %s. Written alone by "
                 "`accuracy_runner --only scale` and `make_report.py --section scale`."
                 % (size.get("ellipsoid", "?"), size.get("torus", "?"), size.get("delaunay", "?"),
                    ", ".join("%.3g" % r for r in radii), ", ".join(labels[e][0] for e in shown),
                    ", ".join(labels[e][0] for e in with_selection), cgal))
    lines.append("")

    ours = with_selection[0] if with_selection else None  # the paraboloid fit, against ICC's best ball
    header = ["mesh"]
    for e in shown:
        header += ["%s: best ball (radius)" % labels[e][0]]
        if e in with_selection:
            header += ["selected (median radius)", "selected / best"]
    if ours and "icc_ball" in shown:
        header += ["%s selected / ICC's best" % labels[ours][0]]
    if ours:
        header += ["noise estimated / added (median)"]
    body = []
    for m in meshes:
        row = [m]
        for e in shown:
            err, r = best_fixed(fixed[(m, e)])
            row.append("%.3g (%s)" % (err, fmt_radius(r)))
            if e in with_selection:
                s = selected[(m, e)]
                row += ["%.3g (%s)" % (s["H_rms"], fmt_radius(s["median_radius_edges"])), "**%.2f**" % (s["H_rms"] / err)]
        if ours and "icc_ball" in shown:
            row.append("%.2f" % (selected[(m, ours)]["H_rms"] / best_fixed(fixed[(m, "icc_ball")])[0]))
        if ours:
            noise = selected[(m, ours)]["median_noise_ratio"]
            row.append("%.2f" % noise if math.isfinite(noise) else "—")
        body.append(row)
    lines += ["### Interior RMS error of H: the best fixed ball and the selection", ""]
    lines += [table(header, body), ""]
    lines += ["Best ball: the least error over the fixed radii (known only from the exact curvature), and its radius; "
              "a best radius of 1 h or %s h lies at the end of the range. The median radius and the noise "
              "estimated (`vertex_noise_map` over the standard deviation added, where some was added) are over the "
              "interior vertices." % ("%.3g" % radii[-1] if radii else "?"), ""]

    for shape in ("ellipsoid", "torus", "delaunay"):
        of_shape = [m for m in meshes if m.split()[0] == shape]
        if not of_shape:
            continue
        name = "scale_selection_%s.png" % shape
        scale_plot(est, of_shape, fixed, selected, labels, os.path.join(figures, name))
        lines += ["![%s: H RMS against the radius](figures/%s)" % (shape, name), ""]
    lines += ["Log-log; solid and dashed lines: fixed balls; dotted horizontal lines: the radius selected per vertex, "
              "in the colour of its estimator.", ""]
    lines += bunny_scale(accuracy_dir, figures)
    return lines
