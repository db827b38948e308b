# SPDX-License-Identifier: GPL-3.0-or-later
"""The speed sections: the targets of issue 16, the tables and plots of bench_estimators, and
the tool end to end."""
import os
import re

import matplotlib.pyplot as plt
import numpy as np

from report.inputs import nominal_ghz
from report.markdown import fmt_bytes, fmt_count, fmt_ns, mesh_order, save_figure, table

# The speed targets of the project's issue 16, for the default on the largest grid: its
# time, how many times faster it is than CGAL 6's ICC (defaults) and than jet fitting of
# degree 2 on 2 rings in the same run, its change from the smallest grid, its parallel
# speed-up, and its time on the real meshes over that on the grid.
TARGET_NS = 150.0
TARGET_ICC_RATIO = 4.0
TARGET_JET_RATIO = 70.0
TARGET_SCALING = 0.25
TARGET_SPEEDUP = 1.9
TARGET_REAL_MESHES = ("bunny00", "armadillo", "ChineseDragon-10kv")
TARGET_REAL_RATIO = 1.5
# "No allocation per vertex": fewer than this many heap allocations per vertex and call on
# the largest grid, i.e. a bounded number per call (buffers, threads), none per vertex.
TARGET_ALLOCATIONS = 1e-3
# Temporary memory of the default: the most heap one call holds at once beyond the mesh and
# the output maps, in bytes per vertex (issue 16).
TARGET_PEAK_HEAP = 64.0
# The tool end to end on the clean 1M-vertex OFF with the CSV, one thread (issue 16).
TARGET_END_TO_END_SECONDS = 2.0
TARGET_END_TO_END_BYTES = 400.0

END_TO_END_TITLE = "## The tool end to end"


def seq_par_rows(est, values, meshes, fmt):
    """A row per estimator of "seq / par" cells from {(estimator, mesh, seq|par): value}."""
    return [[est.label[e]] + ["%s / %s" % (fmt(values.get((e, m, "seq"))), fmt(values.get((e, m, "par")))) for m in meshes]
            for e, _ in est.shown]


def speed_section(est, run, figures):
    """The speed tables and plots of `run` (inputs.Speed)."""
    speed = run.times
    meshes = mesh_order(list(dict.fromkeys(m for (_, m, _) in speed)))
    vertices = {m: v for (_, m, _), (_, v) in speed.items()}
    lines = ["## Speed", ""]
    lines.append("Nanoseconds per vertex (wall clock, `time_per_vertex` of `bench_estimators`), on "
                 "`CGAL::Surface_mesh` with all of H, K and principal curvatures and directions requested. "
                 "Grids: `grid_n` is the n x n grid of .1(cos pi x + cos pi y). `seq` is `CGAL::Sequential_tag`, "
                 "`par` is `CGAL::Parallel_tag` with at most 2 TBB threads; speed-up = seq / par. "
                 "The \"given normals\" variant gets precomputed normals (not timed). Best of 3 repetitions "
                 "(jet d=2 1 ring and jet d=4: one; quick runs: one), each of at least 1 s or one call; "
                 "the repetitions of all cases run interleaved in a random order, so that a case's best "
                 "escapes a disturbance of the shared machine that lasts a few minutes.")
    if est.any_cgal6_shown():
        lines.append("")
        lines.append("CGAL 6's estimators have no parallel version: sequential only. ICC is "
                     "`CGAL::Polygon_mesh_processing::interpolated_corrected_curvatures`: with its defaults "
                     "(CGAL's `compute_vertex_normals`, the faces around the vertex), with `ball_radius` of 1 and "
                     "2 h (h = the mesh's mean edge length, computed once per mesh, not timed; one repetition), and "
                     "with our default normals (`estimate_vertex_normals`, timed with ICC). The discrete operators are "
                     "`discrete_mean_curvatures` (H only) and `discrete_Gaussian_curvatures` (K only).")
    lines.append("")
    header = ["estimator"] + ["%s (%s v)" % (m, "{:,}".format(vertices[m])) for m in meshes]
    for mode, title in (("seq", "sequential"), ("par", "parallel, 2 threads")):
        lines += ["### ns per vertex, %s" % title, ""]
        rows = [[est.label_of(e)] + [fmt_ns(speed.get((e, m, mode), (None,))[0]) for m in meshes]
                for e, _ in est.shown]
        lines += [table(header, rows), ""]
    lines += ["### Parallel speed-up (seq / par)", ""]
    rows = []
    for e, _ in est.shown:
        row = [est.label[e]]
        for m in meshes:
            s, p = speed.get((e, m, "seq")), speed.get((e, m, "par"))
            row.append("%.2f" % (s[0] / p[0]) if s and p else "—")
        rows.append(row)
    lines += [table(header, rows), ""]
    if run.allocations:
        lines += ["### Heap allocations per vertex and call (all threads)", "",
                  "Counted by `bench_estimators` (its own `operator new`), seq / par. A bounded number per call "
                  "(buffers that grow to the largest neighborhood, one worker per thread, TBB) shrinks as "
                  "1/vertices; an allocation per vertex shows as 1 or more.", ""]
        lines += [table(header, seq_par_rows(est, run.allocations, meshes, fmt_count)), ""]
    if run.peak_heap:
        lines += ["### Peak heap per vertex of a call, bytes (temporary memory)", "",
                  "The most heap that one call held at once beyond the mesh and the output maps, over the size of "
                  "the mesh, seq / par: `bench_estimators` counts the bytes that its `operator new` hands out and "
                  "takes back, per thread, and keeps each call's peak (with 2 threads, the sum of each thread's "
                  "peak: an upper bound). Memory that a library takes with `malloc` (Eigen's dynamic matrices "
                  "in jet fitting) is not seen. The target for the default is %g bytes per vertex." % TARGET_PEAK_HEAP, ""]
        lines += [table(header, seq_par_rows(est, run.peak_heap, meshes, fmt_bytes)), ""]
    lines += ["### CGAL's estimators / paraboloid (default normals), same run", ""]
    rows = []
    for e, mode in (("jet_d2_2rings", "seq"), ("jet_d2_2rings", "par"), ("icc", "seq"), ("icc_our_normals", "seq")):
        if e not in dict(est.shown):
            continue
        row = [est.label[e], mode]
        for m in meshes:
            c, p = speed.get((e, m, mode)), speed.get(("paraboloid", m, mode))
            row.append("%.1f" % (c[0] / p[0]) if c and p else "—")
        rows.append(row)
    lines += [table(["estimator", "mode"] + meshes, rows), ""]

    # Figures: ns/vertex against grid size (scaling), and bars on the real meshes.
    grids = [m for m in meshes if m.startswith("grid_")]
    real = [m for m in meshes if not m.startswith("grid_")]
    fig, axes = plt.subplots(1, 2, figsize=(14, 5.5))
    for ax, mode in zip(axes, ("seq", "par")):
        for e, label in est.shown:
            pts = [(vertices[m], speed[(e, m, mode)][0]) for m in grids if (e, m, mode) in speed]
            if pts:
                ax.plot(*zip(*pts), label=label, **est.style(e))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("vertices (grid)")
        ax.set_ylabel("ns per vertex")
        ax.set_title("time per vertex, %s" % ("sequential" if mode == "seq" else "parallel (2 threads)"))
        ax.axhline(TARGET_NS, color="k", ls=":", lw=1)
        ax.grid(True, which="both", alpha=0.3)
    # One legend below both panels: inside, it would hide the lines.
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8)
    save_figure(fig, os.path.join(figures, "speed_scaling.png"), 110, rect=(0, 0.14, 1, 1))

    if real:
        fig, ax = plt.subplots(figsize=(14, 5.5))
        width = 0.8 / len(real)
        x = np.arange(len(est.shown))
        for i, m in enumerate(real):
            ys = [speed.get((e, m, "seq"), (np.nan,))[0] for e, _ in est.shown]
            ax.bar(x + i * width, ys, width, label="%s (%s v)" % (m, "{:,}".format(vertices[m])))
        ax.set_xticks(x + 0.4 - width / 2)
        ax.set_xticklabels([label for _, label in est.shown], rotation=30, ha="right", fontsize=8)
        ax.set_yscale("log")
        ax.set_ylabel("ns per vertex (sequential)")
        ax.set_title("time per vertex on real meshes, sequential")
        ax.grid(True, axis="y", which="both", alpha=0.3)
        ax.legend(fontsize=8)
        save_figure(fig, os.path.join(figures, "speed_real_meshes.png"), 110)

    lines += ["![time per vertex on grids](figures/speed_scaling.png)", ""]
    lines += ["Time per vertex against grid size (log-log); the dotted line is the %g ns target. "
              "A flat line means linear total time." % TARGET_NS, ""]
    if real:
        lines += ["![time per vertex on real meshes](figures/speed_real_meshes.png)", ""]
    return lines


def targets_section(est, run, quick, end_to_end, instructions):
    """The targets of issue 16, met or not, and why not where the time is not met."""
    speed = run.times
    grids = mesh_order([m for (e, m, _) in speed if e == "paraboloid" and m.startswith("grid_")])
    lines = ["## Speed targets of issue 16", ""]
    if not grids:
        return lines + ["No paraboloid timings: targets not evaluated.", ""]
    small, large = grids[0], grids[-1]
    if quick:
        lines += ["**Quick run**: evaluated on %s instead of the 1M-vertex grid; not the targets' setting." % large, ""]

    def ns(e, m, mode):
        v = speed.get((e, m, mode))
        return v[0] if v else None

    rows = []
    p_seq = ns("paraboloid", large, "seq")
    rows.append(["paraboloid (default) single thread on %s" % large, "≤ %g ns/vertex" % TARGET_NS,
                 fmt_ns(p_seq) + " ns", met(p_seq is not None and p_seq <= TARGET_NS)])
    jet = ns("jet_d2_2rings", large, "seq")
    ratio = jet / p_seq if jet and p_seq else None
    rows.append(["jet d=2 2 rings / paraboloid, same run, %s seq" % large, "≥ %g×" % TARGET_JET_RATIO,
                 "%.1f×" % ratio if ratio else "—", met(ratio is not None and ratio >= TARGET_JET_RATIO)])
    p_small = ns("paraboloid", small, "seq")
    change = p_seq / p_small - 1 if p_seq and p_small else None
    rows.append(["ns/vertex %s → %s (paraboloid seq)" % (small, large), "within ±%d%%" % (100 * TARGET_SCALING),
                 "%s → %s ns (%+.0f%%)" % (fmt_ns(p_small), fmt_ns(p_seq), 100 * change) if change is not None else "—",
                 met(change is not None and abs(change) <= TARGET_SCALING)])
    p_par = ns("paraboloid", large, "par")
    speedup = p_seq / p_par if p_seq and p_par else None
    rows.append(["parallel speed-up, 2 threads, %s (paraboloid)" % large, "≥ %g×" % TARGET_SPEEDUP,
                 "%.2f×" % speedup if speedup else "—", met(speedup is not None and speedup >= TARGET_SPEEDUP)])
    icc = ns("icc", large, "seq")
    icc_ratio = icc / p_seq if icc and p_seq else None
    rows.append(["ICC (defaults) / paraboloid (default), same run, %s seq" % large, "≥ %g×" % TARGET_ICC_RATIO,
                 "%.2f×" % icc_ratio if icc_ratio else "— (built without CGAL 6)",
                 met(icc_ratio is not None and icc_ratio >= TARGET_ICC_RATIO)])
    real = [(ns("paraboloid", m, "seq") / p_seq, m) for m in TARGET_REAL_MESHES
            if p_seq and ns("paraboloid", m, "seq") is not None]
    if real:
        worst_real = max(real)
        rows.append(["paraboloid seq on %s / on %s" % (", ".join(m for _, m in real), large),
                     "each ≤ %g×" % TARGET_REAL_RATIO,
                     "at most %.2f× (%s)" % worst_real, met(worst_real[0] <= TARGET_REAL_RATIO)])
    ours = [(run.allocations[(e, large, mode)], e, mode) for e, _ in est.shown for mode in ("seq", "par")
            if est.is_ours(e) and (e, large, mode) in run.allocations]
    if ours:
        worst = max(ours)
        rows.append(["heap allocations per vertex, our estimators, %s" % large,
                     "none per vertex (< %g per vertex and call)" % TARGET_ALLOCATIONS,
                     "at most %s (%s, %s)" % (fmt_count(worst[0]), est.label[worst[1]], worst[2]),
                     met(worst[0] < TARGET_ALLOCATIONS)])
    peaks = [(run.peak_heap[("paraboloid", large, mode)], mode) for mode in ("seq", "par")
             if ("paraboloid", large, mode) in run.peak_heap]
    if peaks:
        worst = max(peaks)
        rows.append(["temporary memory of the default (peak heap of a call), %s" % large,
                     "≤ %g bytes per vertex" % TARGET_PEAK_HEAP,
                     " / ".join("%s %s" % (fmt_bytes(v), mode) for v, mode in peaks),
                     met(worst[0] <= TARGET_PEAK_HEAP)])
    if end_to_end:
        clean_csv = [r for r in end_to_end["rows"] if r[0] == "clean" and r[1] == "csv"]
        if clean_csv:
            seconds, bytes_per_vertex = float(clean_csv[0][2]), float(clean_csv[0][3])
            vertices = re.search(r"(\d+) vertices", end_to_end["mesh"])
            rows.append(["the tool end to end, clean OFF of %s vertices to CSV, 1 thread"
                         % ("{:,}".format(int(vertices.group(1))) if vertices else "?"),
                         "≤ %g s, ≤ %g bytes per vertex" % (TARGET_END_TO_END_SECONDS, TARGET_END_TO_END_BYTES),
                         "%.2f s, %.0f bytes" % (seconds, bytes_per_vertex),
                         met(seconds <= TARGET_END_TO_END_SECONDS and bytes_per_vertex <= TARGET_END_TO_END_BYTES)])
    lines += [table(["target", "goal", "measured", "status"], rows), ""]
    if not quick and p_seq is not None and p_seq > TARGET_NS:
        lines += [why_not_met(ns("paraboloid", large, "seq"), ns("paraboloid_area_normals", large, "seq"),
                              ns("paraboloid_given_normals", large, "seq"), instructions), ""]
    lines += ["Times are wall clock. On a machine shared with other work (see the load average and the share of a "
              "core above) they are pessimistic, and a parallel speed-up cannot show when the second core is busy.",
              ""]
    return lines


def why_not_met(default, area, given, instructions):
    """The paragraph on the default's time (`default` ns per vertex; `area` and `given` with
    area-weighted and given normals) and, where the run counted them (inputs.read_instructions),
    its instructions per vertex."""
    text = ("**Why the time targets are not met.** Every vertex does two least-squares fits (the normal "
            "correction, then the curvature fit, which at interior vertices keeps the linear terms and is "
            "solved a second time less the curvature's quartic term) and gathers its 1-ring. In this run the "
            "default takes %s ns, the same fit with area-weighted normals %s ns and with given normals %s ns."
            % (fmt_ns(default), fmt_ns(area), fmt_ns(given)))
    if instructions:
        per_vertex = instructions["instructions"] / instructions["vertices"]
        per_ns = per_vertex / default
        ghz = nominal_ghz()
        text += (" Callgrind counts %s instructions per vertex in the default's call (`curvature --threads 1` "
                 "on the %d x %d grid of `benchmark/tool_end_to_end.sh`, the call alone, writing its outputs "
                 "included; a count does not depend on the machine's load): %s ns for them is %.1f "
                 "instructions per ns%s, and at that rate %g ns leaves about %s instructions per vertex."
                 % ("{:,}".format(int(round(per_vertex))), instructions["n"], instructions["n"], fmt_ns(default),
                    per_ns, " (%.1f per cycle at the CPU's nominal %g GHz)" % (per_ns / ghz, ghz) if ghz else "",
                    TARGET_NS, "{:,}".format(int(round(per_ns * TARGET_NS, -2)))))
    return text + " The ICC and jet ratios follow from the same time."


def met(ok):
    return "**met**" if ok else "**not met**"


def end_to_end_section(end_to_end):
    """The table of benchmark/tool_end_to_end.sh: the tool's wall time and peak memory per vertex."""
    out = [END_TO_END_TITLE, ""]
    out += ["`benchmark/tool_end_to_end.sh`: `curvature --threads 1 FILE.off` (summary) and with `-o FILE.csv` on a "
            "generated ASCII OFF (%s), clean and with one face flipped (which takes the soup repair). Wall time "
            "(the least of three runs) and peak resident memory per vertex (`/usr/bin/time -v`). Targets (issue 16) for the clean file with the "
            "CSV at 1M vertices: at most %g s and %g bytes per vertex." % (end_to_end["mesh"], TARGET_END_TO_END_SECONDS,
                                                                          TARGET_END_TO_END_BYTES), ""]
    out += [table(["file", "output", "wall s", "peak bytes/vertex"], end_to_end["rows"]), ""]
    if end_to_end["date"]:
        out += ["Run on %s." % end_to_end["date"], ""]
    return out


def first_calls_section(est, run, first_calls):
    """The calls of each estimator in a fresh process (inputs.read_first_calls) beside its warm time,
    page faults and temporary memory in bench_estimators (inputs.Speed `run`)."""
    meshes = mesh_order(list(dict.fromkeys(m for (_, m) in first_calls)))
    calls = max(len(ns) for _, ns, _ in first_calls.values())
    numbers = " / ".join(str(i + 1) for i in range(calls))
    lines = ["### What a program gets: the first calls in a fresh process", ""]
    lines += ["`bench_estimators` builds every input in one process and times each estimator after the others: "
              "its heap is warm. `first_calls ESTIMATOR MESH` builds the one mesh (as above) in a fresh "
              "process, as a program that reads a mesh and calls an estimator does, and times %d calls in a row "
              "on one thread, with the minor page faults of each (`getrusage`): a call whose temporaries the "
              "allocator serves from pages the process has not touched yet faults once per page. Beside them, "
              "the same estimator in `bench_estimators` (sequential): its time, its page faults per vertex and "
              "call, and its temporary memory (the most heap a call held at once beyond the mesh and the "
              "outputs). Estimators that `bench_estimators` runs once (minutes or seconds a call on the largest "
              "grid) are left out." % calls, ""]
    for m in meshes:
        rows = []
        vertices = None
        for e, label in est.shown:
            if (e, m) not in first_calls:
                continue
            vertices, ns, faults = first_calls[(e, m)]
            warm = run.times.get((e, m, "seq"))
            rows.append([label, " / ".join(fmt_ns(x) for x in ns), " / ".join(fmt_count(x) for x in faults),
                         fmt_ns(warm[0] if warm else None), fmt_count(run.page_faults.get((e, m, "seq"))),
                         fmt_bytes(run.peak_heap.get((e, m, "seq")))])
        lines += ["#### %s (%s vertices)" % (m, "{:,}".format(vertices)), ""]
        lines += [table(["estimator", "fresh process: ns/vertex, call %s" % numbers,
                         "page faults per vertex, call %s" % numbers, "warm: ns/vertex", "page faults per vertex",
                         "peak heap bytes/vertex"], rows), ""]
    return lines
