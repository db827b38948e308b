# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by the build scripts. cmake_generator DIR prints the CMake options that choose the
# generator of a new build directory DIR: Ninja where it is installed (it compiles the units of
# all the targets asked for at once, where make builds the targets of one
# `cmake --build --target a b` one after another); nothing for a directory already configured,
# which keeps its generator.
cmake_generator() {
  if [ ! -f "$1/CMakeCache.txt" ] && command -v ninja > /dev/null; then
    echo "-G Ninja"
  fi
}
