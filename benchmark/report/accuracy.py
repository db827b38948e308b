# SPDX-License-Identifier: GPL-3.0-or-later
"""The accuracy section: errors against exact curvature and observed orders, from
accuracy_runner's accuracy.csv."""
import math
import os
from collections import defaultdict

import matplotlib.pyplot as plt
import numpy as np

from report.markdown import fmt_e, fmt_order, save_figure, table

# Below this RMS an error is rounding, and its "order" means nothing.
ROUNDING = 1e-12
QUANTITIES = ["k_max", "k_min", "H", "K"]


def accuracy_series(rows):
    """{(surface, mesh, estimator, region, quantity): [rows by level]}"""
    series = defaultdict(list)
    for r in rows:
        series[(r["surface"], r["mesh"], r["estimator"], r["region"], r["quantity"])].append(r)
    for v in series.values():
        v.sort(key=lambda r: r["level"])
    return series


def order_of(levels):
    """Observed order between the two finest sizes: log(e_coarse/e_fine)/log(h_coarse/h_fine)."""
    if len(levels) < 2:
        return None
    a, b = levels[-2], levels[-1]
    if not (a["count"] and b["count"]) or not (a["rms"] > ROUNDING and b["rms"] > ROUNDING):
        return None
    return math.log(a["rms"] / b["rms"]) / math.log(a["h"] / b["h"])


def surfaces_and_meshes(rows):
    surfaces = list(dict.fromkeys(r["surface"] for r in rows))
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))
    return surfaces, meshes


def short(surface):
    """Column label: graph_sphere (Hamann's sphere cap) must not read as the closed sphere."""
    return surface.replace("graph_", "f:")


def headline_region(surface):
    # Graphs have a boundary: the interior shows the convergence of the method itself.
    return "interior" if surface.startswith("graph_") else "all"


def accuracy_section(est, rows, figures):
    """The accuracy tables and plots of accuracy_runner's rows (inputs.read_accuracy)."""
    series = accuracy_series(rows)
    surfaces, meshes = surfaces_and_meshes(rows)
    lines = ["## Accuracy", ""]
    lines.append("`accuracy_runner` compares every estimator with the exact curvature of: five of Hamann's "
                 "graph functions on [-1,1]^2 (`graph_*`), a sphere (r = 1), an ellipsoid (1.5, 1, 0.6) and a torus "
                 "(R = 3, r = 1). Each as a `regular` mesh (grid, icosphere, parameter grid), a `jittered` one "
                 "(parameter domain perturbed by up to 0.2 of the local spacing, points on the surface) and, for "
                 "the graphs, a `delaunay` one (Delaunay triangulation of random points). Each on a refinement "
                 "series; h is the mean edge length. **Order** = log(e_coarse/e_fine)/log(h_coarse/h_fine) between "
                 "the two finest meshes, from the RMS error. `interior`: graph vertices with |x|, |y| ≤ 0.8 "
                 "(closed surfaces: all vertices). In this section the \"given normals\" variant of the paraboloid "
                 "fit is given the **exact** normals. Vertices an estimator cannot estimate are left out of its "
                 "errors and counted in the detailed tables. A dash: a quantity the estimator does not give, "
                 "or an order that cannot be measured.")
    lines.append("")
    if est.any_cgal6_shown():
        lines.append("CGAL 6's estimators: \"ICC (our normals)\" gets our default normal estimate, not the exact "
                     "normals. CGAL's discrete H (`discrete_mean_curvatures`) is **unsigned**: it returns |H|, the norm "
                     "of the cotangent Laplacian over four mixed Voronoi areas (1/r on a sphere of radius r), so "
                     "where the exact H is negative its error is 2|H| and says nothing of its accuracy; its discrete K "
                     "is the angle defect over the mixed Voronoi area. CGAL does not define either at border "
                     "vertices: on the graphs, read the interior.")
        lines.append("")

    # Headline: median order over the surfaces, regular against irregular meshes.
    lines += ["### Observed orders in brief: median over the surfaces", ""]
    lines += ["Median of the per-series orders below (H and K; interior for graphs); irregular = jittered and "
              "Delaunay meshes. Series whose error is at rounding level are left out.", ""]
    out = []
    for e, label in est.shown:
        row = [label]
        for quantity in ("H", "K"):
            for irregular in (False, True):
                orders = [order_of(v) for (s, m, est, region, q), v in series.items()
                          if est == e and q == quantity and region == headline_region(s)
                          and (m != "regular") == irregular]
                orders = [o for o in orders if o is not None]
                row.append(fmt_order(float(np.median(orders))) if orders else "—")
        out.append(row)
    lines += [table(["estimator", "H regular", "H irregular", "K regular", "K irregular"], out), ""]

    # Summary: order of H and K per estimator, regular vs irregular, per surface.
    for quantity in ("H", "K"):
        lines += ["### Observed order of %s (RMS; interior for graphs, all vertices for closed surfaces)" % quantity, ""]
        header = ["estimator"]
        cols = []
        for s in surfaces:
            for m in meshes:
                if any(k[0] == s and k[1] == m for k in series):
                    cols.append((s, m))
                    header.append("%s %s" % (short(s), m[:3]))
        out = []
        for e, label in est.shown:
            out.append([label] + [fmt_order(order_of(series.get((s, m, e, headline_region(s), quantity), [])))
                                  for s, m in cols])
        lines += [table(header, out), ""]
        lines += ["(`f:` Hamann's graph functions; `reg` regular, `jit` jittered, `del` Delaunay.)", ""]

    # Summary: finest-mesh RMS of H.
    lines += ["### RMS error of H on the finest mesh of each series", ""]
    header = ["estimator"] + ["%s %s" % (short(s), m[:3]) for s, m in cols]
    out = []
    for e, label in est.shown:
        out.append([label] + [fmt_e((series.get((s, m, e, headline_region(s), "H")) or [{"rms": None}])[-1]["rms"])
                              for s, m in cols])
    lines += [table(header, out), ""]

    # Plots: error vs h per surface, interior/all headline region, H and K, one panel per mesh type.
    lines += ["### Error against mesh size", ""]
    lines += ["Log-log RMS error against mean edge length h; the legend gives each line's order between the "
              "two finest meshes. Lines that stop have errors at rounding level.", ""]
    for s in surfaces:
        mesh_types = [m for m in meshes if any(k[0] == s and k[1] == m for k in series)]
        fig, axes = plt.subplots(2, len(mesh_types), figsize=(5.2 * len(mesh_types), 9), squeeze=False)
        region = headline_region(s)
        for col, m in enumerate(mesh_types):
            for row, quantity in enumerate(("H", "K")):
                ax = axes[row][col]
                for e, label in est.shown:
                    lv = [r for r in series.get((s, m, e, region, quantity), []) if r["count"] and r["rms"] > ROUNDING]
                    if not lv:
                        continue
                    p = order_of(lv)
                    ax.plot([r["h"] for r in lv], [r["rms"] for r in lv], ms=4,
                            label="%s (%s)" % (label, fmt_order(p)), **est.style(e))
                ax.set_xscale("log")
                ax.set_yscale("log")
                ax.set_title("%s, %s: %s (%s)" % (s, m, quantity, region), fontsize=9)
                ax.set_xlabel("h (mean edge length)")
                ax.set_ylabel("RMS error of %s" % quantity)
                ax.grid(True, which="both", alpha=0.3)
                ax.legend(fontsize=6)
        name = "accuracy_%s.png" % s
        save_figure(fig, os.path.join(figures, name), 90)
        lines += ["![%s](figures/%s)" % (s, name), ""]

    # Details.
    lines += ["### Detailed tables", ""]
    lines += ["<details><summary>RMS, max and order of k_max, k_min, H, K per surface, mesh, region "
              "(finest mesh)</summary>", ""]
    for s in surfaces:
        for m in meshes:
            for region in ("all", "interior") if s.startswith("graph_") else ("all",):
                if not any(k[:2] == (s, m) for k in series):
                    continue
                finest = series.get((s, m, est.shown[0][0], region, "H"), [None])[-1]
                lines += ["#### %s, %s, %s vertices (finest: %s vertices, h = %.3g)" % (
                    s, m, region, "{:,}".format(finest["vertices"]), finest["h"]), ""]
                header = ["estimator"]
                for q in QUANTITIES:
                    header += ["%s RMS" % q, "%s max" % q, "%s order" % q]
                header.append("not estimable")
                out = []
                for e, label in est.shown:
                    row = [label]
                    failed = 0
                    for q in QUANTITIES:
                        lv = series.get((s, m, e, region, q), [])
                        last = lv[-1] if lv else None
                        row += [fmt_e(last["rms"] if last else None), fmt_e(last["max"] if last else None),
                                fmt_order(order_of(lv))]
                        if last:
                            failed = last["not_estimable"]
                    row.append(str(failed))
                    out.append(row)
                lines += [table(header, out), ""]
    lines += ["</details>", ""]
    return lines
