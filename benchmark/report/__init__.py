# SPDX-License-Identifier: GPL-3.0-or-later
"""The parts of benchmark/make_report.py: inputs (the raw outputs of the run), estimators
(their list, labels and line styles), markdown (tables, number formats, figures), and one
module per section of the report (speed, accuracy, bunny, noise)."""
import matplotlib

matplotlib.use("Agg")  # headless: no display on CI machines; before any module imports pyplot
