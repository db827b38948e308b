# SPDX-License-Identifier: GPL-3.0-or-later
"""The estimators of a run, as accuracy_runner lists them (estimators.json): their order in the
report, labels, origins and line styles."""
import json

import matplotlib.pyplot as plt

# "ours", "cgal_fit" (CGAL's fit behind our interface: jet fitting) or "cgal6" (CGAL 6's own
# estimators, Polygon_mesh_processing: sequential only).
OURS, CGAL_FIT, CGAL6 = "ours", "cgal_fit", "cgal6"
MARKERS = "os^vD<>pPX*hH8d+x1234|_"


class Estimators:
    """The estimators of estimators.json in report order (`all`); `shown` keeps those the run
    measured (CGAL 6's only when the programs were built against CGAL 6), as (name, label)."""

    def __init__(self, path, measured):
        with open(path) as f:
            data = json.load(f)
        self.all = [(e["name"], e["label"]) for e in data["estimators"]]
        self.origin = {e["name"]: e["origin"] for e in data["estimators"]}
        self.label = dict(self.all)
        self.shown = [(e, label) for e, label in self.all if e in measured]
        # The estimators over a ball of any radius (the noise section): name, label, and the
        # estimator whose line style each takes.
        self.ball = [(b["name"], b["label"], b["style_of"]) for b in data["ball_estimators"]]

    def label_of(self, e):
        return self.label.get(e, e)

    def is_ours(self, e):
        """Our code, not CGAL's (jet fitting is CGAL's Monge_via_jet_fitting behind our interface)."""
        return self.origin.get(e) == OURS

    def is_cgal6(self, e):
        return self.origin.get(e) == CGAL6

    def any_cgal6_shown(self):
        return any(self.is_cgal6(e) for e, _ in self.shown)

    def style(self, e):
        """Line style of estimator e, the same in every plot: tab20's colours for ours and CGAL's
        fits, Dark2's for CGAL 6's estimators; CGAL's fits are also dashed, CGAL 6's
        dash-dotted, and every line has its own marker."""
        names = [name for name, _ in self.all]
        i = names.index(e)
        if self.is_cgal6(e):
            color = plt.get_cmap("Dark2")([name for name in names if self.is_cgal6(name)].index(e))
        else:
            color = plt.get_cmap("tab20")(i)
        return {"color": color, "marker": MARKERS[i % len(MARKERS)],
                "ls": "--" if self.origin[e] == CGAL_FIT else "-." if self.is_cgal6(e) else "-"}
