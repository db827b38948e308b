# SPDX-License-Identifier: GPL-3.0-or-later
# The extension curvature_estimation._core: python/src/ and the command-line tool's parts
# (tools/), compiled as CMake compiles the tool in Release (CMakeLists.txt, tools/CMakeLists.txt),
# so that the module's values are the tool's bit for bit. Its objects go to build/python/,
# or CE_PYTHON_BUILD_DIR (relative to the source tree, where pip builds): a second install
# with unchanged sources compiles nothing. CE_PYTHON_JOBS: compile jobs (default: all cores).
# CE_TOOL_PARTS_BUILD: a CMake build directory configured with -DCE_TOOL_PARTS_PIC=ON, its tool
# built: the extension links that build's tool parts instead of compiling them again
# (scripts/run_tests.sh; the same objects as the tool's).
import os
import re
import shutil
import subprocess
from glob import glob

from pybind11.setup_helpers import ParallelCompile, Pybind11Extension
from setuptools import setup

ROOT = os.path.dirname(os.path.abspath(__file__))
os.chdir(ROOT)

with open("CMakeLists.txt", encoding="utf-8") as cmake:
    VERSION = re.search(r"project\(CGAL_Curvature_estimation VERSION ([0-9.]+)", cmake.read()).group(1)

TOOL_PARTS = ["command_line", "input_files", "point_set_estimation", "registry", "soup_repair", "surface_estimation",
              "tetrahedral"]


def pkg_config(*arguments):
    """The words pkg-config prints, or None where it or the package is missing."""
    if shutil.which("pkg-config") is None:
        return None
    result = subprocess.run(["pkg-config", *arguments], capture_output=True, text=True, check=False)
    return result.stdout.split() if result.returncode == 0 else None


eigen = pkg_config("--cflags-only-I", "eigen3") or ["-I/usr/include/eigen3"]
tbb = pkg_config("--libs", "tbb")
define_macros = [("NDEBUG", None), ("BOOST_ALL_NO_LIB", None), ("CGAL_EIGEN3_ENABLED", None), ("CGAL_USE_GMPXX", "1"),
                 ("NOMINMAX", None)]
libraries = ["gmpxx", "mpfr", "gmp"]
if tbb is not None:  # as CE_WITH_TBB: parallel when TBB is there
    define_macros.append(("CGAL_LINKED_WITH_TBB", None))
    libraries += [word[2:] for word in tbb if word.startswith("-l")] + ["tbbmalloc"]

sources = sorted(glob("python/src/*.cpp"))
extra_objects = []
parts_build = os.environ.get("CE_TOOL_PARTS_BUILD")
if parts_build:
    extra_objects = [os.path.join(parts_build, "tools", f"libcurvature_{name}.a") for name in ("parts", "registry")]
    missing = [path for path in extra_objects if not os.path.exists(path)]
    if missing:
        raise SystemExit(f"CE_TOOL_PARTS_BUILD={parts_build}: no {', '.join(missing)} (build the tool there first)")
else:
    sources += [f"tools/{part}.cpp" for part in TOOL_PARTS]

core = Pybind11Extension(
    "curvature_estimation._core",
    sources,
    extra_objects=extra_objects,
    include_dirs=["python/src", "tools", "include", *(flag[2:] for flag in eigen)],
    define_macros=define_macros,
    libraries=libraries,
    extra_compile_args=["-O3", "-frounding-math"],
    depends=sorted(glob("include/**/*.h", recursive=True) + glob("tools/*.h") + glob("python/src/*.h")),
    cxx_std=17,
)

BUILD_BASE = os.environ.get("CE_PYTHON_BUILD_DIR") or os.path.join("build", "python")
os.makedirs(BUILD_BASE, exist_ok=True)  # egg_info's directory must exist
ParallelCompile("CE_PYTHON_JOBS").install()
setup(
    version=VERSION,
    packages=["curvature_estimation"],
    package_dir={"": "python"},
    ext_modules=[core],
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
    zip_safe=False,
)
