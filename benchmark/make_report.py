#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes benchmark/REPORT.md and benchmark/figures/*.png from the outputs of
bench_estimators (Google Benchmark JSON) and accuracy_runner (CSV).

Run by scripts/make_report.sh; by hand:

  /usr/bin/python3 benchmark/make_report.py --bench-json speed.json \
      --accuracy-dir DIR --build-dir build [--quick]

Needs matplotlib and numpy (Debian: python3-matplotlib python3-numpy, installed by
scripts/install_dependencies.sh --report). Every number in the report comes from
the two input files and the machine; nothing is typed in here except the issue's
targets.
"""
import argparse
import csv
import datetime
import json
import math
import os
import platform
import re
import subprocess
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # headless: no display on CI machines
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))

# Estimators in report order, with labels; must match benchmark/estimators.h. The report shows
# those the run measured (ESTIMATORS, set by select_estimators): CGAL 6's only when the programs
# were built against CGAL 6.
ALL_ESTIMATORS = [
    ("paraboloid", "paraboloid (default normals)"),
    ("paraboloid_area_normals", "paraboloid (area normals)"),
    ("paraboloid_given_normals", "paraboloid (given normals)"),
    ("paraboloid_d3", "paraboloid, fit degree 3"),
    ("paraboloid_d4", "paraboloid, fit degree 4"),
    ("paraboloid_ball_2h", "paraboloid, ball radius 2 h"),
    ("paraboloid_ball_4h", "paraboloid, ball radius 4 h"),
    ("paraboloid_ball_8h", "paraboloid, ball radius 8 h"),
    ("curve_network_1", "curve network O(h^2)"),
    ("curve_network_2", "curve network O(h^4)"),
    ("gauss_map", "Gauss map"),
    ("taubin", "Taubin"),
    ("chen_schmitt", "Chen-Schmitt"),
    ("jet_d2_1ring", "jet d=2, 1 ring"),
    ("jet_d2_2rings", "jet d=2, 2 rings"),
    ("jet_d4_3rings", "jet d=4, 3 rings"),
    ("icc", "ICC (defaults)"),
    ("icc_ball_1h", "ICC, ball radius 1 h"),
    ("icc_ball_2h", "ICC, ball radius 2 h"),
    ("icc_our_normals", "ICC (our normals, timed)"),
    ("discrete_mean", "CGAL discrete H (cotangent)"),
    ("discrete_Gaussian", "CGAL discrete K (angle defect)"),
]
LABEL = dict(ALL_ESTIMATORS)
ESTIMATORS = ALL_ESTIMATORS
# CGAL 6's own estimators (Polygon_mesh_processing): sequential only.
CGAL6 = {"icc", "icc_ball_1h", "icc_ball_2h", "icc_our_normals", "discrete_mean", "discrete_Gaussian"}


def is_ours(e):
    """Our code, not CGAL's (jet fitting is CGAL's Monge_via_jet_fitting behind our interface)."""
    return not e.startswith("jet") and e not in CGAL6


def select_estimators(speed, rows):
    """Keeps in ESTIMATORS the estimators that the speed or the accuracy run measured."""
    global ESTIMATORS
    measured = {e for (e, _, _) in speed} | {r["estimator"] for r in rows}
    ESTIMATORS = [(e, label) for e, label in ALL_ESTIMATORS if e in measured]


def style(e):
    """Line style of estimator e, the same in every plot: tab20 has 20 colours for our 13
    estimators and CGAL's 3 jets, CGAL 6's estimators take Dark2's; the jets are also
    dashed, CGAL 6's dash-dotted, and every line has its own marker (23 of them)."""
    i = [name for name, _ in ALL_ESTIMATORS].index(e)
    if e in CGAL6:
        color = plt.get_cmap("Dark2")([name for name, _ in ALL_ESTIMATORS if name in CGAL6].index(e))
    else:
        color = plt.get_cmap("tab20")(i)
    return {"color": color, "marker": "os^vD<>pPX*hH8d+x1234|_"[i],
            "ls": "--" if e.startswith("jet") else "-." if e in CGAL6 else "-"}


QUANTITIES = ["k_max", "k_min", "H", "K"]

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

# Below this RMS an error is rounding, and its "order" means nothing.
ROUNDING = 1e-12


# ---------------------------------------------------------------------------
# Inputs
# ---------------------------------------------------------------------------

def run(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, check=False).stdout
    except OSError:
        return ""


def cgal_used(build_dir, bench_context, accuracy_dir):
    """The CGAL the programs were compiled against (CGAL_VERSION_STR, recorded by both) and
    the CGAL_DIR of the build."""
    speed = bench_context.get("cgal_version")
    path = os.path.join(accuracy_dir, "cgal_version.txt")
    accuracy = open(path).read().strip() if os.path.exists(path) else None
    if speed and accuracy and speed != accuracy:
        version = "speed %s, accuracy %s" % (speed, accuracy)
    else:
        version = speed or accuracy or "unknown"
    cache_path = os.path.join(build_dir, "CMakeCache.txt")
    if os.path.exists(cache_path):
        for line in open(cache_path):
            m = re.match(r"^CGAL_DIR:[A-Z]+=(.*)$", line)
            if m:
                return "%s (CGAL_DIR = `%s`)" % (version, m.group(1))
    return version


def machine(build_dir, bench_context, accuracy_dir):
    lscpu = run(["lscpu"])
    cpu = re.search(r"^Model name:\s*(.+)$", lscpu, re.M)
    cache = {}
    cache_path = os.path.join(build_dir, "CMakeCache.txt")
    if os.path.exists(cache_path):
        for line in open(cache_path):
            m = re.match(r"^(CMAKE_CXX_COMPILER|CMAKE_BUILD_TYPE|CMAKE_CXX_FLAGS_RELEASE):[A-Z]+=(.*)$", line)
            if m:
                cache[m.group(1)] = m.group(2)
    compiler = run([cache.get("CMAKE_CXX_COMPILER", "c++"), "--version"]).splitlines()
    return {
        # When the speed benchmarks ran (Google Benchmark's context), not when this script ran.
        "Date": bench_context.get("date") or datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
        "CPU": cpu.group(1).strip() if cpu else platform.processor() or "unknown",
        "Cores (nproc)": str(os.cpu_count()),
        "Load average when the benchmarks started": ", ".join(
            "%.2f" % x for x in bench_context.get("load_avg", [])) or "unknown",
        "Share of a core the sequential runs got (median CPU time / wall time)":
            "%.0f%%" % (100 * bench_context["core_share"]) if "core_share" in bench_context else "unknown",
        "Compiler": compiler[0] if compiler else "unknown",
        "Build type": "%s (%s)" % (cache.get("CMAKE_BUILD_TYPE", "?"), cache.get("CMAKE_CXX_FLAGS_RELEASE", "")),
        "CGAL": cgal_used(build_dir, bench_context, accuracy_dir),
        # Debian's libbenchmark calls itself a debug build: that is the timing harness only,
        # the estimators are compiled with the build type above.
        "Google Benchmark library build (harness only)": bench_context.get("library_build_type", "unknown"),
        "OS": platform.platform(),
    }


# {(estimator, mesh, seq|par): heap allocations per vertex and call}, filled by read_speed.
ALLOCATIONS = {}
# {(estimator, mesh, seq|par): peak heap of a call, bytes per vertex}, filled by read_speed.
PEAK_HEAP = {}


def read_speed(path):
    """{(estimator, mesh, seq|par): (ns per vertex, vertices)} and the JSON context.
    Of repeated runs the fastest counts: on a shared machine it is the least disturbed."""
    data = json.load(open(path))
    speed = {}
    for b in data.get("benchmarks", []):
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        key = tuple(b["name"].split("/")[:3])  # ESTIMATOR/MESH/seq|par/min_time:...
        ns = b["time_per_vertex"] * 1e9
        if key not in speed or ns < speed[key][0]:
            speed[key] = (ns, int(b["vertices"]))
        # Heap allocations per vertex and call, and the peak heap of a call in bytes per
        # vertex: the largest of the repetitions.
        for counter, values in (("allocations_per_vertex", ALLOCATIONS), ("peak_heap_bytes_per_vertex", PEAK_HEAP)):
            if counter in b:
                values[key] = max(b[counter], values.get(key, 0.0))
    context = data.get("context", {})
    # How much of a core a sequential run got: its CPU time over its wall-clock time. Near 1 on
    # an idle machine; well below 1 when other processes compete for the cores, and then no
    # wall-clock time (least of all a parallel speed-up) is the code's own.
    shares = [b["cpu_time"] / b["real_time"] for b in data.get("benchmarks", [])
              if b.get("run_type", "iteration") == "iteration" and not b.get("error_occurred")
              and b["name"].split("/")[2] == "seq" and b.get("real_time")]
    if shares:
        context["core_share"] = float(np.median(shares))
    return speed, context


def read_accuracy(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in ("level", "vertices", "count", "not_estimable"):
                r[k] = int(r[k])
            for k in ("h", "rms", "max"):
                r[k] = float(r[k])
            rows.append(r)
    return rows


# ---------------------------------------------------------------------------
# Formatting
# ---------------------------------------------------------------------------

def fmt_ns(x):
    if x is None:
        return "—"
    return "%.0f" % x if x >= 100 else "%.1f" % x


def fmt_count(x):
    if x is None:
        return "—"
    return "0" if x == 0 else "%.2g" % x


def fmt_bytes(x):
    return "—" if x is None else "%.1f" % x


def fmt_e(x):
    return "—" if x is None or not math.isfinite(x) else "%.1e" % x


def fmt_order(x):
    return "—" if x is None or not math.isfinite(x) else "%.2f" % x


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out)


def save_figure(fig, path, dpi, **layout):
    """Lays fig out (tight_layout, with its keywords), writes it to path and closes it."""
    fig.tight_layout(**layout)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def mesh_order(meshes):
    """Grids by size, then real meshes by name: the same columns in every report, whatever order
    the interleaved repetitions wrote them in."""
    grids = sorted((m for m in meshes if m.startswith("grid_")), key=lambda m: int(m[5:]))
    return grids + sorted(m for m in meshes if not m.startswith("grid_"))


# ---------------------------------------------------------------------------
# Speed
# ---------------------------------------------------------------------------

def seq_par_rows(values, meshes, fmt):
    """A row per estimator of "seq / par" cells from {(estimator, mesh, seq|par): value}."""
    return [[LABEL[e]] + ["%s / %s" % (fmt(values.get((e, m, "seq"))), fmt(values.get((e, m, "par")))) for m in meshes]
            for e, _ in ESTIMATORS]


def speed_section(speed, figures, quick):
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
    if any(e in CGAL6 for e, _ in ESTIMATORS):
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
        rows = [[LABEL.get(e, e)] + [fmt_ns(speed.get((e, m, mode), (None,))[0]) for m in meshes]
                for e, _ in ESTIMATORS]
        lines += [table(header, rows), ""]
    lines += ["### Parallel speed-up (seq / par)", ""]
    rows = []
    for e, _ in ESTIMATORS:
        row = [LABEL[e]]
        for m in meshes:
            s, p = speed.get((e, m, "seq")), speed.get((e, m, "par"))
            row.append("%.2f" % (s[0] / p[0]) if s and p else "—")
        rows.append(row)
    lines += [table(header, rows), ""]
    if ALLOCATIONS:
        lines += ["### Heap allocations per vertex and call (all threads)", "",
                  "Counted by `bench_estimators` (its own `operator new`), seq / par. A bounded number per call "
                  "(buffers that grow to the largest neighborhood, one worker per thread, TBB) shrinks as "
                  "1/vertices; an allocation per vertex shows as 1 or more.", ""]
        lines += [table(header, seq_par_rows(ALLOCATIONS, meshes, fmt_count)), ""]
    if PEAK_HEAP:
        lines += ["### Peak heap per vertex of a call, bytes (temporary memory)", "",
                  "The most heap that one call held at once beyond the mesh and the output maps, over the size of "
                  "the mesh, seq / par: `bench_estimators` counts the bytes that its `operator new` hands out and "
                  "takes back, per thread, and keeps each call's peak (with 2 threads, the sum of each thread's "
                  "peak: an upper bound). Memory that a library takes with `malloc` (Eigen's dynamic matrices "
                  "in jet fitting) is not seen. The target for the default is %g bytes per vertex." % TARGET_PEAK_HEAP, ""]
        lines += [table(header, seq_par_rows(PEAK_HEAP, meshes, fmt_bytes)), ""]
    lines += ["### CGAL's estimators / paraboloid (default normals), same run", ""]
    rows = []
    for e, mode in (("jet_d2_2rings", "seq"), ("jet_d2_2rings", "par"), ("icc", "seq"), ("icc_our_normals", "seq")):
        if e not in dict(ESTIMATORS):
            continue
        row = [LABEL[e], mode]
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
        for e, label in ESTIMATORS:
            pts = [(vertices[m], speed[(e, m, mode)][0]) for m in grids if (e, m, mode) in speed]
            if pts:
                ax.plot(*zip(*pts), label=label, **style(e))
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
        x = np.arange(len(ESTIMATORS))
        for i, m in enumerate(real):
            ys = [speed.get((e, m, "seq"), (np.nan,))[0] for e, _ in ESTIMATORS]
            ax.bar(x + i * width, ys, width, label="%s (%s v)" % (m, "{:,}".format(vertices[m])))
        ax.set_xticks(x + 0.4 - width / 2)
        ax.set_xticklabels([label for _, label in ESTIMATORS], rotation=30, ha="right", fontsize=8)
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


def targets_section(speed, quick, end_to_end):
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
    ours = [(ALLOCATIONS[(e, large, mode)], e, mode) for e, _ in ESTIMATORS for mode in ("seq", "par")
            if is_ours(e) and (e, large, mode) in ALLOCATIONS]
    if ours:
        worst = max(ours)
        rows.append(["heap allocations per vertex, our estimators, %s" % large,
                     "none per vertex (< %g per vertex and call)" % TARGET_ALLOCATIONS,
                     "at most %s (%s, %s)" % (fmt_count(worst[0]), LABEL[worst[1]], worst[2]),
                     met(worst[0] < TARGET_ALLOCATIONS)])
    peaks = [(PEAK_HEAP[("paraboloid", large, mode)], mode) for mode in ("seq", "par")
             if ("paraboloid", large, mode) in PEAK_HEAP]
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
        area = ns("paraboloid_area_normals", large, "seq")
        given = ns("paraboloid_given_normals", large, "seq")
        # Callgrind, 2026-12-03: instructions per vertex of the default's per-vertex call on
        # the 317 x 317 grid (output writing not counted), which do not depend on the load.
        instructions = 5600
        two_fits = 2470
        # The rate in instructions per ns, not per cycle: the virtual CPU reports its nominal
        # 2.1 GHz, at which the default would run 4 to 5 instructions per cycle, more than is
        # plausible; the clock it really runs at is not known here.
        per_ns = instructions / p_seq
        budget = per_ns * TARGET_NS
        lines += ["**Why the time targets are not met.** Callgrind (2026-12-03, the 317 x 317 grid; counts "
                  "do not depend on the machine's load) counts about 5,600 instructions per vertex in the "
                  "default's per-vertex call: its two 5-unknown Taylor fits %s (the normal's, in the frame "
                  "of the area-weighted normal, and the curvature's, in the frame of the corrected normal, "
                  "each with the 1-norm condition test that decides the widening), the curvature fit solved "
                  "again less its quartic term and the estimate from it 630, the scaled 1-ring offsets 580, "
                  "the 1-ring's circulation 540, the area-weighted normal 300, the fitted graph's curvatures "
                  "and directions 200, tangent frames 160, the boundary vertices' cubic fits 120, the rest "
                  "640. In this run the default takes %s ns, the same fit with area-weighted normals %s ns "
                  "and with given normals %s ns. %s ns for %s instructions is %.1f instructions per ns "
                  "(%.1f per cycle at the CPU's nominal 2.1 GHz, which suggests that it runs faster than "
                  "that); at that rate %g ns leaves about %s instructions per vertex%s. What each way there "
                  "gives: (1) one fit instead of two (estimated, not built): correcting the first fit's "
                  "samples for the frame's tilt, per sample, costs about as much as the second fit (13%% at "
                  "most to gain), and "
                  "the second fit, in the corrected frame, is what makes the quartic correction exact on "
                  "spheres and cylinders; (2) the rings from compact index arrays (the neighbor table of the "
                  "wider fits): building it costs 12 to 17 ns per vertex, more than the default's 1-ring "
                  "gathering wins back; (3) two vertices at a time, each step of the fits run for both before "
                  "the next (2026-12-05, the 1M grid, A/B in one process): 1%% to 2%%, within the noise, with "
                  "the same instructions, although the same interleaving of the fits alone, on pre-gathered "
                  "1-rings, took 20%% off their time: in the whole call the CPU already overlaps one vertex's "
                  "fits with the next one's gathering. The next step is the two vertices' fits in the two "
                  "lanes of an SSE2 register, which would halve the fits' 3,100 instructions (1,500 fewer of "
                  "the 5,600); 150 ns needs that with four lanes (AVX2, which a default build does not enable) "
                  "and one fit. The ICC and jet ratios follow from the same time."
                  % ("{:,}".format(two_fits), fmt_ns(p_seq), fmt_ns(area), fmt_ns(given), fmt_ns(p_seq),
                     "{:,}".format(instructions), per_ns, per_ns / 2.1, TARGET_NS,
                     "{:,}".format(int(round(budget, -2))),
                     ", fewer than the two fits alone take" if budget < two_fits else ""), ""]
    lines += ["Times are wall clock. On a machine shared with other work (see the load average and the share of a "
              "core above) they are pessimistic, and a parallel speed-up cannot show when the second core is busy.",
              ""]
    return lines


def met(ok):
    return "**met**" if ok else "**not met**"


# ---------------------------------------------------------------------------
# Accuracy
# ---------------------------------------------------------------------------

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


def accuracy_section(rows, figures):
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
    if any(e in CGAL6 for e, _ in ESTIMATORS):
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
    for e, label in ESTIMATORS:
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
        for e, label in ESTIMATORS:
            out.append([label] + [fmt_order(order_of(series.get((s, m, e, headline_region(s), quantity), [])))
                                  for s, m in cols])
        lines += [table(header, out), ""]
        lines += ["(`f:` Hamann's graph functions; `reg` regular, `jit` jittered, `del` Delaunay.)", ""]

    # Summary: finest-mesh RMS of H.
    lines += ["### RMS error of H on the finest mesh of each series", ""]
    header = ["estimator"] + ["%s %s" % (short(s), m[:3]) for s, m in cols]
    out = []
    for e, label in ESTIMATORS:
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
                for e, label in ESTIMATORS:
                    lv = [r for r in series.get((s, m, e, region, quantity), []) if r["count"] and r["rms"] > ROUNDING]
                    if not lv:
                        continue
                    p = order_of(lv)
                    ax.plot([r["h"] for r in lv], [r["rms"] for r in lv], ms=4,
                            label="%s (%s)" % (label, fmt_order(p)), **style(e))
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
                finest = series.get((s, m, ESTIMATORS[0][0], region, "H"), [None])[-1]
                lines += ["#### %s, %s, %s vertices (finest: %s vertices, h = %.3g)" % (
                    s, m, region, "{:,}".format(finest["vertices"]), finest["h"]), ""]
                header = ["estimator"]
                for q in QUANTITIES:
                    header += ["%s RMS" % q, "%s max" % q, "%s order" % q]
                header.append("not estimable")
                out = []
                for e, label in ESTIMATORS:
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


# ---------------------------------------------------------------------------
# Bunny pictures
# ---------------------------------------------------------------------------

def bunny_figure(vpath, fpath, title, path):
    """Renders the bunny of fpath (three vertex indices per row) once per column of H of vpath
    (x,y,z, then one column per name), four panels a row, titled title(name), in one colour scale,
    into path. Returns the number of vertices and the bounds of the colour scale."""
    with open(vpath) as f:
        header = f.readline().strip().split(",")
    values = np.genfromtxt(vpath, delimiter=",", skip_header=1)
    faces = np.genfromtxt(fpath, delimiter=",", skip_header=1, dtype=np.int64)
    xyz = values[:, :3]
    names = header[3:]
    # bunny00.off is y-up; matplotlib's 3D axes are z-up.
    pts = xyz[:, [0, 2, 1]]
    tris = pts[faces]
    # One colour scale for all panels, clamped at the 5th and 95th percentiles of H over every
    # panel (the scanned bunny is noisy: a few per cent of the vertices have |H| ten times
    # the median and would wash the rest out), and centred on 0 so that the colour tells the sign.
    lo_h, hi_h = (float(x) for x in np.nanpercentile(values[:, 3:], [5, 95]))
    if lo_h < 0 < hi_h:
        norm = matplotlib.colors.TwoSlopeNorm(0.0, lo_h, hi_h)
    else:
        norm = matplotlib.colors.Normalize(lo_h, hi_h)
    cmap = matplotlib.colormaps["coolwarm"]
    ncols = min(4, len(names))
    nrows = int(math.ceil(len(names) / ncols))
    fig = plt.figure(figsize=(4.5 * ncols, 4.2 * nrows))
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
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), cax=cax, label="mean curvature H")
    fig.savefig(path, dpi=72)  # ~1 MB for the bunny of every estimator: it is committed
    plt.close(fig)
    return len(xyz), lo_h, hi_h


def bunny_section(accuracy_dir, figures):
    vpath = os.path.join(accuracy_dir, "bunny_mean_curvature.csv")
    fpath = os.path.join(accuracy_dir, "bunny_faces.csv")
    if not (os.path.exists(vpath) and os.path.exists(fpath)):
        return ["## The bunny", "", "No bunny output (accuracy_runner did not write it).", ""]
    vertices, lo_h, hi_h = bunny_figure(vpath, fpath, lambda name: LABEL.get(name, name),
                                        os.path.join(figures, "bunny_mean_curvature.png"))
    return ["## The bunny coloured by mean curvature", "",
            "![bunny](figures/bunny_mean_curvature.png)", "",
            "`bunny00.off` (%s vertices, about 1 unit across), face colour = mean of its vertices' H, one colour "
            "scale for every panel, clamped at [%.3g, %.3g] (5th and 95th percentiles of H over all estimators) "
            "and centred on 0; grey = not estimable. The \"given normals\" panel is given the package's default "
            "normal estimate. Red: H > 0 (convex with outward normals), blue: H < 0." % (
                "{:,}".format(vertices), lo_h, hi_h), ""]


# ---------------------------------------------------------------------------
# Noise: the error against the radius of the ball
# ---------------------------------------------------------------------------

# The estimators over a ball of any radius (ball_estimators() of benchmark/estimators.h), with
# their labels and the estimator of the other sections whose line style each takes.
BALL_ESTIMATORS = [
    ("paraboloid_ball", "paraboloid, fit degree 2", "paraboloid_ball_4h"),
    ("paraboloid_d3_ball", "paraboloid, fit degree 3", "paraboloid_d3"),
    ("jet_d2_ball", "jet fitting d=2", "jet_d2_2rings"),
    ("gauss_map_ball", "Gauss map over the ball", "gauss_map"),
    ("icc_ball", "ICC", "icc_ball_2h"),
]
# The references of the noise section, over their usual neighborhoods (no radius).
NOISE_REFERENCES = ["paraboloid", "gauss_map"]


def read_noise(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in ("seed", "vertices", "widened"):
                r[k] = int(r[k])
            for k in ("h", "sigma", "H_rms", "H_max", "K_rms", "ns_per_vertex"):
                r[k] = float(r[k])
            # Empty for the references.
            r["radius_edges"] = int(r["radius_edges"]) if r["radius_edges"] else None
            r["ball_vertices"] = float(r["ball_vertices"]) if r["ball_vertices"] else None
            rows.append(r)
    return rows


def noise_bound(runs):
    """The standard deviation of the coefficient of |x|^2 / 2 of a least-squares fit over N samples,
    uniform in a disc of radius r, of noise sigma along the normal: sqrt(48) sigma / (sqrt(N) r^2),
    with N the mean number of vertices in the ball; the mean over the runs (seeds) of one radius."""
    return float(np.mean([math.sqrt(48) * r["sigma"] /
                          (math.sqrt(r["ball_vertices"]) * (r["radius_edges"] * r["h"]) ** 2) for r in runs]))


def noise_section(accuracy_dir, figures):
    path = os.path.join(accuracy_dir, "noise_radius.csv")
    if not os.path.exists(path):
        return ["## Curvature of a noisy mesh against the radius", "",
                "No noise output (accuracy_runner did not write it).", ""]
    rows = read_noise(path)
    runs = defaultdict(list)  # {(estimator, radius in edges or None): the rows of the seeds}
    for r in rows:
        runs[(r["estimator"], r["radius_edges"])].append(r)
    radii = sorted({r["radius_edges"] for r in rows if r["radius_edges"] is not None})
    seeds = sorted({r["seed"] for r in rows})
    ball = [(e, label, like) for e, label, like in BALL_ESTIMATORS if any(k[0] == e for k in runs)]
    references = [e for e in NOISE_REFERENCES if (e, None) in runs]
    first = rows[0]

    def mean_of(key, fmt):
        return lambda v: fmt % np.mean([r[key] for r in v])

    def rms_and_spread(v):
        x = [r["H_rms"] for r in v]
        return "%.3g ± %.1g" % (np.mean(x), (max(x) - min(x)) / 2)

    def radius_table(cell, extra_rows=()):
        header = ["estimator", "default neighborhood"] + ["r = %d h" % r for r in radii]
        out = [[LABEL.get(e, e), cell(runs[(e, None)])] + ["—"] * len(radii) for e in references]
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
        ax.errorbar(xs, ys, yerr=err, label=label, capsize=3, **style(like))
    for e in references:
        ax.axhline(np.mean([x["H_rms"] for x in runs[(e, None)]]), lw=1, label="%s, default neighborhood" % LABEL[e],
                   **{k: v for k, v in style(e).items() if k != "marker"})
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

    lines += bunny_radius(accuracy_dir, figures)
    return lines


def bunny_radius(accuracy_dir, figures):
    """The bunny coloured by the default paraboloid fit over its 1-ring and over two balls."""
    vpath = os.path.join(accuracy_dir, "bunny_ball_mean_curvature.csv")
    fpath = os.path.join(accuracy_dir, "bunny_faces.csv")
    if not (os.path.exists(vpath) and os.path.exists(fpath)):
        return ["No bunny over balls (accuracy_runner did not write it).", ""]

    def title(name):
        m = re.match(r"^ball_(\d+)h$", name)
        return "ball radius %s h" % m.group(1) if m else "%s (1 ring)" % LABEL.get(name, name)

    vertices, lo_h, hi_h = bunny_figure(vpath, fpath, title, os.path.join(figures, "bunny_radius.png"))
    return ["### The bunny over balls", "",
            "![bunny over balls](figures/bunny_radius.png)", "",
            "`bunny00.off` (%s vertices) coloured by H of the default paraboloid fit over its 1-ring and over balls "
            "(`ball_radius` in mean edge lengths h of the bunny), as in the bunny section: one colour scale, clamped at "
            "[%.3g, %.3g] (5th and 95th percentiles of H over these panels), centred on 0; red H > 0, blue H < 0. "
            "The scan's noise fades as the ball grows; where the ball is wider than the surface is round (the rims of the "
            "ears, whose radius of curvature 1/H is a few edges), the surface in the ball is no graph over the tangent "
            "plane, and the fit's H changes sign." % ("{:,}".format(vertices), lo_h, hi_h), ""]


# ---------------------------------------------------------------------------

def read_end_to_end(path):
    """The output of benchmark/tool_end_to_end.sh: its mesh line, its rows (file, output, wall s,
    peak bytes/vertex) and the date of the run."""
    with open(path) as f:
        lines = f.read().splitlines()
    header = lines.index(next(l for l in lines if l.startswith("file ")))
    dates = [l.split(None, 1)[1] for l in lines if l.startswith("date: ")]
    return {"mesh": lines[0], "rows": [l.split() for l in lines[header + 1:] if l.strip()],
            "date": dates[0] if dates else None}


def end_to_end_section(end_to_end):
    """The table of benchmark/tool_end_to_end.sh: the tool's wall time and peak memory per vertex."""
    out = ["## The tool end to end", ""]
    out += ["`benchmark/tool_end_to_end.sh`: `curvature --threads 1 FILE.off` (summary) and with `-o FILE.csv` on a "
            "generated ASCII OFF (%s), clean and with one face flipped (which takes the soup repair). Wall time "
            "(the least of three runs) and peak resident memory per vertex (`/usr/bin/time -v`). Targets (issue 16) for the clean file with the "
            "CSV at 1M vertices: at most %g s and %g bytes per vertex." % (end_to_end["mesh"], TARGET_END_TO_END_SECONDS,
                                                                          TARGET_END_TO_END_BYTES), ""]
    out += [table(["file", "output", "wall s", "peak bytes/vertex"], end_to_end["rows"]), ""]
    if end_to_end["date"]:
        out += ["Run on %s." % end_to_end["date"], ""]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bench-json", required=True)
    ap.add_argument("--accuracy-dir", required=True)
    ap.add_argument("--build-dir", default="build")
    ap.add_argument("--out-dir", default=HERE, help="where REPORT.md and figures/ go (default: benchmark/)")
    ap.add_argument("--quick", action="store_true", help="label the report as a quick (smoke) run")
    ap.add_argument("--duration", default="", help="how long the pipeline took, for the report")
    ap.add_argument("--end-to-end", help="the output of benchmark/tool_end_to_end.sh")
    args = ap.parse_args()

    figures = os.path.join(args.out_dir, "figures")
    os.makedirs(figures, exist_ok=True)
    speed, context = read_speed(args.bench_json)
    rows = read_accuracy(os.path.join(args.accuracy_dir, "accuracy.csv"))
    select_estimators(speed, rows)

    lines = ["# Curvature estimation: speed and accuracy report", ""]
    lines += ["Generated by `scripts/make_report.sh%s` — do not edit by hand." % (" --quick" if args.quick else ""), ""]
    if args.quick:
        lines += ["> **Quick (smoke) run**: small meshes and short timings; not the report's real numbers.", ""]
    lines += ["## Machine", ""]
    info = machine(args.build_dir, context, args.accuracy_dir)
    if args.duration:
        info["Pipeline duration"] = args.duration
    lines += [table(["", ""], [[k, v] for k, v in info.items()]), ""]
    end_to_end = read_end_to_end(args.end_to_end) if args.end_to_end else None
    lines += targets_section(speed, args.quick, end_to_end)
    lines += speed_section(speed, figures, args.quick)
    lines += accuracy_section(rows, figures)
    lines += bunny_section(args.accuracy_dir, figures)
    lines += noise_section(args.accuracy_dir, figures)
    if end_to_end:
        lines += end_to_end_section(end_to_end)

    with open(os.path.join(args.out_dir, "REPORT.md"), "w") as f:
        f.write("\n".join(lines))
    print("make_report: wrote %s and %s" % (os.path.join(args.out_dir, "REPORT.md"), figures))


if __name__ == "__main__":
    main()
