# SPDX-License-Identifier: GPL-3.0-or-later
"""The raw outputs of a run: bench_estimators' JSON, accuracy_runner's CSVs,
tool_end_to_end.sh's table, the callgrind count of instructions, and the machine."""
import collections
import csv
import datetime
import json
import os
import platform
import re
import subprocess

import numpy as np

# The speed run: {(estimator, mesh, seq|par): (ns per vertex, vertices)}; by the same keys the
# heap allocations per vertex and call, the peak heap of a call in bytes per vertex and the
# minor page faults per vertex and call; and the JSON context.
Speed = collections.namedtuple("Speed", "times allocations peak_heap page_faults context")


def run(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, check=False).stdout
    except OSError:
        return ""


def cmake_cache(build_dir, pattern):
    """{name: value} of the entries of BUILD/CMakeCache.txt whose names match `pattern`."""
    cache = {}
    path = os.path.join(build_dir, "CMakeCache.txt")
    if os.path.exists(path):
        for line in open(path):
            m = re.match(r"^(%s):[A-Z]+=(.*)$" % pattern, line)
            if m:
                cache[m.group(1)] = m.group(2)
    return cache


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
    cgal_dir = cmake_cache(build_dir, "CGAL_DIR").get("CGAL_DIR")
    return "%s (CGAL_DIR = `%s`)" % (version, cgal_dir) if cgal_dir is not None else version


def cpu_model():
    m = re.search(r"^Model name:\s*(.+)$", run(["lscpu"]), re.M)
    return m.group(1).strip() if m else platform.processor() or "unknown"


def nominal_ghz():
    """The clock the CPU's model name states (as in "... @ 2.10GHz"), or None."""
    m = re.search(r"@\s*([0-9.]+)\s*GHz", cpu_model())
    return float(m.group(1)) if m else None


def machine(build_dir, bench_context, accuracy_dir):
    cache = cmake_cache(build_dir, "CMAKE_CXX_COMPILER|CMAKE_BUILD_TYPE|CMAKE_CXX_FLAGS_RELEASE")
    compiler = run([cache.get("CMAKE_CXX_COMPILER", "c++"), "--version"]).splitlines()
    return {
        # When the speed benchmarks ran (Google Benchmark's context), not when this script ran.
        "Date": bench_context.get("date") or datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
        "CPU": cpu_model(),
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


def read_speed(path):
    """The Speed of bench_estimators' JSON. Of repeated runs the fastest counts: on a shared
    machine it is the least disturbed; of the counters, the largest."""
    data = json.load(open(path))
    times, allocations, peak_heap, page_faults = {}, {}, {}, {}
    for b in data.get("benchmarks", []):
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        key = tuple(b["name"].split("/")[:3])  # ESTIMATOR/MESH/seq|par/min_time:...
        ns = b["time_per_vertex"] * 1e9
        if key not in times or ns < times[key][0]:
            times[key] = (ns, int(b["vertices"]))
        for counter, values in (("allocations_per_vertex", allocations), ("peak_heap_bytes_per_vertex", peak_heap),
                                ("page_faults_per_vertex", page_faults)):
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
    return Speed(times, allocations, peak_heap, page_faults, context)


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


def read_scale_selection(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            r["vertices"] = int(r["vertices"])
            for k in ("h", "H_rms"):
                r[k] = float(r[k])
            # radius_edges empty on the rows of the selection; the medians empty on the others.
            for k in ("radius_edges", "median_radius_edges", "median_noise_ratio"):
                r[k] = float(r[k]) if r[k] else None
            rows.append(r)
    return rows


def read_end_to_end(path):
    """The output of benchmark/tool_end_to_end.sh: its mesh line, its rows (file, output, wall s,
    peak bytes/vertex) and the date of the run."""
    with open(path) as f:
        lines = f.read().splitlines()
    header = lines.index(next(line for line in lines if line.startswith("file ")))
    dates = [line.split(None, 1)[1] for line in lines if line.startswith("date: ")]
    return {"mesh": lines[0], "rows": [line.split() for line in lines[header + 1:] if line.strip()],
            "date": dates[0] if dates else None}


def read_instructions(path):
    """The output of benchmark/instructions.sh: the grid's side and vertex count, and the
    instructions callgrind counted in the default's call on it."""
    with open(path) as f:
        text = f.read()
    grid = re.search(r"^grid (\d+)x\d+: (\d+) vertices$", text, re.M)
    count = re.search(r"^instructions: (\d+)$", text, re.M)
    if not (grid and count):
        raise ValueError("%s: no grid or instructions line" % path)
    return {"n": int(grid.group(1)), "vertices": int(grid.group(2)), "instructions": int(count.group(1))}


def read_first_calls(path):
    """The lines of benchmark/first_calls, one per estimator and mesh (each from a fresh
    process): {(estimator, mesh): (vertices, [ns per vertex of each call], [minor page faults
    per vertex of each call])}."""
    calls = {}
    with open(path) as f:
        for line in f:
            if line.strip():
                r = json.loads(line)
                calls[(r["estimator"], r["mesh"])] = (int(r["vertices"]), r["ns_per_vertex"], r["faults_per_vertex"])
    return calls
