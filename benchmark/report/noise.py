# SPDX-License-Identifier: GPL-3.0-or-later
"""The noise section: the error of the estimators over a ball against its radius, on a noisy
ellipsoid (accuracy_runner's noise_radius.csv), and the bunny over balls."""
import math
import os
from collections import defaultdict

import matplotlib.pyplot as plt
import numpy as np

from report import inputs
from report.bunny import bunny_radius
from report.markdown import save_figure, table

def noise_bound(runs):
    """The standard deviation of the coefficient of |x|^2 / 2 of a least-squares fit over N samples,
    uniform in a disc of radius r, of noise sigma along the normal: sqrt(48) sigma / (sqrt(N) r^2),
    with N the mean number of vertices in the ball; the mean over the runs (seeds) of one radius."""
    return float(np.mean([math.sqrt(48) * r["sigma"] /
                          (math.sqrt(r["ball_vertices"]) * (r["radius_edges"] * r["h"]) ** 2) for r in runs]))


def noise_section(est, accuracy_dir, figures):
    """The error against the radius of the ball on the noisy ellipsoid (noise_radius.csv)."""
    path = os.path.join(accuracy_dir, "noise_radius.csv")
    if not os.path.exists(path):
        return ["## Curvature of a noisy mesh against the radius", "",
                "No noise output (accuracy_runner did not write it).", ""]
    rows = inputs.read_noise(path)
    runs = defaultdict(list)  # {(estimator, radius in edges or None): the rows of the seeds}
    for r in rows:
        runs[(r["estimator"], r["radius_edges"])].append(r)
    radii = sorted({r["radius_edges"] for r in rows if r["radius_edges"] is not None})
    seeds = sorted({r["seed"] for r in rows})
    ball = [(e, label, like) for e, label, like in est.ball if any(k[0] == e for k in runs)]
    # The references, on their usual neighborhoods: the rows without a radius.
    references = list(dict.fromkeys(e for e, r in runs if r is None))
    first = rows[0]

    def mean_of(key, fmt):
        return lambda v: fmt % np.mean([r[key] for r in v])

    def rms_and_spread(v):
        x = [r["H_rms"] for r in v]
        return "%.3g ± %.1g" % (np.mean(x), (max(x) - min(x)) / 2)

    def radius_table(cell, extra_rows=()):
        header = ["estimator", "default neighborhood"] + ["r = %d h" % r for r in radii]
        out = [[est.label_of(e), cell(runs[(e, None)])] + ["—"] * len(radii) for e in references]
        out += [[label, "—"] + [cell(runs[(e, r)]) if (e, r) in runs else "—" for r in radii]
                for e, label, _ in ball]
        return table(header, out + list(extra_rows))

    ball_sizes = ["vertices in the ball (mean)", "—"] + [
        "%.1f" % np.mean([x["ball_vertices"] for x in runs[(ball[0][0], r)]]) for r in radii]
    lines = ["## Curvature of a noisy mesh against the radius", ""]
    lines.append("The noisy ellipsoid of the tests (`ce_test::noisy_ellipsoid_soup`, test/common/noisy_meshes.h): "
                 "semi-axes 1, 0.8 and 0.6, an icosphere of %s vertices jittered by 0.2 of the local spacing, then "
                 "Gaussian noise of σ = 7%% of the mean edge length in each coordinate; the exact curvature is "
                 "that of the points before the noise. Seeds %s. The radius r of the ball is in mean edge lengths h of "
                 "the noisy mesh (`CGAL::Curvature_estimation::mean_edge_length`; seed %d: σ = %.3g, h = %.3g): "
                 "`ball_radius(r)` of `paraboloid_fitting_curvatures` with fit degree 2 and 3, of "
                 "`jet_fitting_curvatures` (CGAL's jet fitting of degree 2) and of `gauss_map_curvatures`%s. Ours "
                 "and jet fitting take the connected part of the mesh in the ball, and widen a ball that holds "
                 "fewer than twice the fit's unknowns. The Gauss map differentiates normals that are fitted over "
                 "balls of the same radius about each vertex of its ball: its data reach twice the radius. "
                 "For reference, the default paraboloid fit and the Gauss map on their usual neighborhoods. "
                 "Every vertex counts; one thread."
                 % ("{:,}".format(first["vertices"]), ", ".join(str(s) for s in seeds), first["seed"], first["sigma"],
                    first["h"], ", and `ball_radius(r)` of CGAL 6's interpolated corrected curvatures (ICC)"
                    if any(e == "icc_ball" for e, _, _ in ball)
                    else "; not CGAL 6's interpolated corrected curvatures (ICC): this run was built against an older CGAL"))
    lines.append("")
    lines += ["### RMS error of H: mean over the seeds ± half their range", ""]
    lines += [radius_table(rms_and_spread, [ball_sizes]), ""]

    # Plot: H RMS against the radius, log-log, the seeds' range as error bars.
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for e, label, like in ball:
        pts = [(r, [x["H_rms"] for x in runs[(e, r)]]) for r in radii if (e, r) in runs]
        xs = [r for r, _ in pts]
        ys = np.array([np.mean(v) for _, v in pts])
        err = np.array([[y - min(v) for y, (_, v) in zip(ys, pts)], [max(v) - y for y, (_, v) in zip(ys, pts)]])
        ax.errorbar(xs, ys, yerr=err, label=label, capsize=3, **est.style(like))
    for e in references:
        ax.axhline(np.mean([x["H_rms"] for x in runs[(e, None)]]), lw=1, label="%s, default neighborhood" % est.label[e],
                   **{k: v for k, v in est.style(e).items() if k != "marker"})
    bound_radii = [r for r in radii if (ball[0][0], r) in runs]
    ax.plot(bound_radii, [noise_bound(runs[(ball[0][0], r)]) for r in bound_radii], "k:", lw=1.5,
            label="least-squares noise bound √48 σ / (√N r²)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks(radii)
    ax.set_xticklabels([str(r) for r in radii])
    ax.set_xlabel("ball radius r (mean edge lengths h)")
    ax.set_ylabel("RMS error of H")
    ax.set_title("noisy ellipsoid (%s vertices, σ = %.2g h): error of H against the radius" % (
        "{:,}".format(first["vertices"]), first["sigma"] / first["h"]), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save_figure(fig, os.path.join(figures, "noise_radius.png"), 90)
    lines += ["![H RMS against the radius](figures/noise_radius.png)", ""]
    lines += ["Log-log; the bars span the seeds. The dotted line is the standard deviation that noise σ along the "
              "normal leaves in the coefficient of |x|²/2 of a least-squares fit over N samples uniform in a disc "
              "of radius r, √48 σ / (√N r²), with N the mean number of vertices in the ball (above): while the noise "
              "dominates, a fit over the ball cannot do better, and the error falls as r⁻³. It does not apply where "
              "the balls are widened (see below): those fits have more samples than N; nor to the Gauss map, "
              "whose data reach twice the radius. Once the ball is large, the "
              "shape's own variation over it takes over, and the error grows again.", ""]

    lines += ["### Time per vertex (ns, one thread, mean over the seeds) and widened vertices", ""]
    lines += [radius_table(mean_of("ns_per_vertex", "%.0f")), ""]
    widened = [[label] + ["%.0f%%" % (100 * np.mean([x["widened"] / x["vertices"] for x in runs[(e, r)]]))
                          if (e, r) in runs else "—" for r in radii] for e, label, _ in ball]
    lines += ["Share of the vertices whose estimate is `widened` (the ball grown to hold enough vertices for the "
              "fit, or to condition it):", ""]
    lines += [table(["estimator"] + ["r = %d h" % r for r in radii], widened), ""]
    lines += ["<details><summary>RMS error of K and largest error of H (mean over the seeds)</summary>", ""]
    lines += ["#### RMS error of K", "", radius_table(mean_of("K_rms", "%.3g")), ""]
    lines += ["#### Largest error of H", "", radius_table(mean_of("H_max", "%.3g")), ""]
    lines += ["</details>", ""]

    lines += bunny_radius(est, accuracy_dir, figures)
    return lines
