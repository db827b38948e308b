# SPDX-License-Identifier: GPL-3.0-or-later
"""The README's install: pip into a fresh virtual environment with the system's site packages,
offline (--no-build-isolation, --no-index), then an import from outside the source tree.
After scripts/run_tests.sh's own install the build in build/python/ is up to date: pip
compiles nothing again."""

import os
import subprocess
import sys
from pathlib import Path

from conftest import ROOT


def test_pip_install_into_a_fresh_venv(tmp_path):
    base = getattr(sys, "_base_executable", sys.executable)
    env = tmp_path / "env"
    subprocess.run([base, "-m", "venv", "--system-site-packages", str(env)], check=True)
    python = env / "bin" / "python"
    install = subprocess.run([str(python), "-m", "pip", "install", "--no-build-isolation", "--no-index",
                              "--no-deps", str(ROOT)], capture_output=True, text=True, check=False)
    assert install.returncode == 0, install.stdout + install.stderr
    code = ("import curvature_estimation as ce, numpy as np; "
            "r = ce.mesh_curvatures(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]]), "
            "np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])); "
            "print(ce.__file__); print(r.status.tolist())")
    run = subprocess.run([str(python), "-c", code], capture_output=True, text=True, cwd=tmp_path, check=False,
                         env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"})
    assert run.returncode == 0, run.stderr
    module_file, status = run.stdout.splitlines()
    assert Path(module_file).resolve().is_relative_to(env.resolve())
    assert status == "[3, 3, 3, 3]"  # a tetrahedron's vertices: the paraboloid fit's fallback
