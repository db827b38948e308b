# SPDX-License-Identifier: GPL-3.0-or-later
"""Number formats, markdown tables and figure files."""
import math

import matplotlib.pyplot as plt


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
