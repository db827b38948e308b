#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module's overhead (issue 46): curvature_estimation.mesh_curvatures on an
N x N grid of the height field z = 0.1 sin(3x) cos(2y) + 0.05 x y over [0, 1]^2 (N = 1000:
1M vertices, 2M triangles; the grid of grid_off.py, at full precision), against its C++
peer python_overhead_peer, which does the same work on the same arrays without Python
(the module's own soup of the arrays, the tool's mesh build with its repair check, the
registry's run, the rows into new arrays), in the same run.

- Time: each side in a process of its own that loads the arrays, then calls CALLS times;
  the least time of a call (its arrays in, its arrays out), for threads=1 and threads=0
  (all cores); the two sides alternate, ROUNDS times. The checksums of the two sides'
  results (the XOR of the bits of k_max, k_min, mean and gaussian) must be equal.
- Peak memory: the peak resident set (ru_maxrss, by /usr/bin/time) of a process that loads the
  arrays (np.load) and makes one call, against the tool's `curvature --threads T mesh.off
  -o out.csv` on the same mesh (an OFF of the same doubles) and the peer's one call.
  Targets: Python time at most 1.15x the C++ peer's, Python peak memory at most 2x the tool's.

Writes OUT (default benchmark/PYTHON_OVERHEAD.md) from the numbers it measures. Run it
with an interpreter that imports curvature_estimation, under the machine's lock:
  flock /work/build.lock build/python-venv/bin/python benchmark/python_overhead.py \\
      [--peer build/benchmark/python_overhead_peer] [--tool build/tools/curvature] [--n 1000]
"""
import argparse
import datetime
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

# The Python side: loads the arrays, calls `calls` times, a line per call as the peer prints it.
PYTHON_CALLS = """
import sys, time
import numpy as np
import curvature_estimation as ce
vertices, faces = np.load(sys.argv[1]), np.load(sys.argv[2])
method, threads, calls = sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
for _ in range(calls):
    start = time.perf_counter()
    r = ce.mesh_curvatures(vertices, faces, method, threads=threads)
    seconds = time.perf_counter() - start
    checksum = 0
    for values in (r.k_max, r.k_min, r.mean, r.gaussian):
        checksum ^= int(np.bitwise_xor.reduce(values.view(np.uint64)))
    print(f"seconds {seconds:.6f} checksum {checksum}", flush=True)
    del r
"""

TARGET_TIME, TARGET_MEMORY = 1.15, 2.0


def grid(n):
    """The grid_off.py grid: vertices row by row (y, then x), triangles (a, b, d), (a, d, c) a cell."""
    h = 1.0 / (n - 1)
    y, x = np.meshgrid(np.arange(n) * h, np.arange(n) * h, indexing="ij")
    x, y = x.ravel(), y.ravel()
    vertices = np.column_stack([x, y, 0.1 * np.sin(3 * x) * np.cos(2 * y) + 0.05 * x * y])
    a = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    b, c, d = a + 1, a + n, a + n + 1
    faces = np.stack([np.column_stack([a, b, d]), np.column_stack([a, d, c])], axis=1).reshape(-1, 3)
    return vertices, faces.astype(np.int64)


def write_off(path, vertices, faces):
    """Every double written with 17 significant digits: the tool reads the same doubles back."""
    with open(path, "w") as out:
        out.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        np.savetxt(out, vertices, fmt="%.17g")
        np.savetxt(out, np.column_stack([np.full(len(faces), faces.shape[1]), faces]), fmt="%d")


def run(command):
    """The output of `command` and its peak resident memory in bytes, by /usr/bin/time (Debian package
    `time`): a child of this interpreter would count the interpreter's own memory, which the kernel
    keeps in its peak through the exec."""
    with tempfile.NamedTemporaryFile("r") as peak:
        result = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", peak.name, *map(str, command)],
                                capture_output=True, text=True, check=False)
        if result.returncode != 0:
            raise RuntimeError(f"{' '.join(map(str, command))} failed:\n{result.stderr}")
        return result.stdout, int(peak.read().split()[-1]) * 1024


def calls(stdout):
    """(seconds, checksum) of each line `seconds S checksum C`."""
    rows = [line.split() for line in stdout.splitlines() if line.startswith("seconds ")]
    return [(float(row[1]), int(row[3])) for row in rows]


def table(columns, rows):
    """The lines of a markdown table."""
    return ["| " + " | ".join(row) + " |" for row in [columns, ["---"] * len(columns), *rows]]


def threads_label(threads):
    return str(threads) if threads else "all cores (0)"


def verdict(ratio, target):
    return "met" if ratio <= target else "**not met**"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--peer", default=ROOT / "build" / "benchmark" / "python_overhead_peer", type=Path)
    parser.add_argument("--tool", default=ROOT / "build" / "tools" / "curvature", type=Path)
    parser.add_argument("--n", default=1000, type=int, help="grid size (n x n vertices)")
    parser.add_argument("--method", default="paraboloid")
    parser.add_argument("--calls", default=3, type=int, help="calls a process makes")
    parser.add_argument("--rounds", default=2, type=int, help="processes per side and threads setting")
    parser.add_argument("--out", default=ROOT / "benchmark" / "PYTHON_OVERHEAD.md", type=Path)
    args = parser.parse_args()
    for program in (args.peer, args.tool, Path("/usr/bin/time")):
        if not os.access(program, os.X_OK):
            sys.exit(f"python_overhead.py: no executable {program} (build the targets python_overhead_peer "
                     "and curvature; /usr/bin/time: scripts/install_dependencies.sh --report)")

    vertices, faces = grid(args.n)
    n, m = len(vertices), len(faces)
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        np.save(work / "vertices.npy", vertices)
        np.save(work / "faces.npy", faces)
        vertices.tofile(work / "vertices.f64")
        faces.tofile(work / "faces.i64")
        write_off(work / "mesh.off", vertices, faces)
        del vertices, faces

        def python(threads, count):
            return run([sys.executable, "-c", PYTHON_CALLS, str(work / "vertices.npy"), str(work / "faces.npy"),
                        args.method, str(threads), str(count)])

        def peer(threads, count):
            return run([str(args.peer), str(work / "vertices.f64"), str(work / "faces.i64"), "3", args.method,
                        str(threads), str(count)])

        def tool(threads):
            return run([str(args.tool), "-m", args.method, "--threads", str(threads), str(work / "mesh.off"), "-o",
                        str(work / "out.csv")])

        times, memory = {}, {}
        for threads in (1, 0):
            results = {"Python": [], "C++": []}
            for _ in range(args.rounds):
                results["Python"] += calls(python(threads, args.calls)[0])
                results["C++"] += calls(peer(threads, args.calls)[0])
            checksums = {side: {checksum for _, checksum in rows} for side, rows in results.items()}
            if len(checksums["Python"] | checksums["C++"]) != 1:
                sys.exit(f"python_overhead.py: the two sides' results differ (checksums {checksums})")
            times[threads] = {side: min(seconds for seconds, _ in rows) for side, rows in results.items()}
            memory[threads] = {"Python": python(threads, 1)[1], "C++ peer": peer(threads, 1)[1],
                               "tool": tool(threads)[1]}
        baseline = run([sys.executable, "-c", "import numpy, curvature_estimation"])[1]

    cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                if line.startswith("model name")), platform.processor())
    lines = [
        "# The Python module's overhead",
        "",
        f"Written by `benchmark/python_overhead.py` on {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} "
        f"UTC ({cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, numpy {np.__version__}). "
        f"Mesh: the {args.n} x {args.n} grid of z = 0.1 sin(3x) cos(2y) + 0.05 xy ({n} vertices, {m} triangles, "
        "float64 and int64 arrays); method "
        f"`{args.method}` with its defaults. The C++ peer (`python_overhead_peer`) does the Python call's work "
        "on the same arrays without Python: the soup of the arrays, the tool's mesh build (its repair check "
        "included), the registry's run, the rows into new arrays. The two sides' results have the same "
        "checksum (the XOR of the bits of k_max, k_min, mean and gaussian).",
        "",
        f"Time: the least of {args.rounds * args.calls} calls a side ({args.rounds} processes of {args.calls} "
        f"calls, alternating with the other side's). Target: Python at most {TARGET_TIME}x the C++ peer.",
        "",
    ]
    lines += table(["threads", "Python s", "C++ s", "Python ns/vertex", "C++ ns/vertex", "Python / C++", "target"],
                   [[threads_label(threads), f"{t['Python']:.3f}", f"{t['C++']:.3f}", f"{t['Python'] / n * 1e9:.0f}",
                     f"{t['C++'] / n * 1e9:.0f}", f"{t['Python'] / t['C++']:.3f}",
                     verdict(t["Python"] / t["C++"], TARGET_TIME)] for threads, t in times.items()])
    lines += [
        "",
        "Peak resident memory (ru_maxrss) of a process making one call: the Python one loads the arrays "
        "(`np.load`) and calls; the peer reads them and calls; the tool reads the mesh as an OFF of the same "
        f"doubles and writes the CSV (`curvature -m {args.method} --threads T mesh.off -o out.csv`). "
        f"Target: Python at most {TARGET_MEMORY}x the tool. An interpreter that only imports numpy and "
        f"curvature_estimation peaks at {baseline / 2**20:.0f} MiB.",
        "",
    ]
    lines += table(["threads", "Python MiB", "C++ peer MiB", "tool MiB", "Python bytes/vertex", "Python / tool",
                    "target"],
                   [[threads_label(threads), f"{peak['Python'] / 2**20:.0f}", f"{peak['C++ peer'] / 2**20:.0f}",
                     f"{peak['tool'] / 2**20:.0f}", f"{peak['Python'] / n:.0f}", f"{peak['Python'] / peak['tool']:.2f}",
                     verdict(peak["Python"] / peak["tool"], TARGET_MEMORY)] for threads, peak in memory.items()])
    args.out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
