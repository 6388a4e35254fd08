#!/usr/bin/env bash
# Installs kiln's build and test dependencies (Debian 12 packages) when missing, then configures
# and builds kiln in Release. Idempotent: quick when nothing changed. KILN_SETUP=render installs
# only what building and rendering need (no test frameworks, no Slurm).
#   scripts/bootstrap.sh [extra cmake --build arguments, e.g. --target kiln]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_BUILD_DIR:-$root/build}"

# What rendering needs (scripts/demo.sh: KILN_SETUP=render), and what the tests add
packages=(build-essential cmake pkg-config libembree-dev libopenimageio-dev libopenexr-dev
          libpng-dev libjpeg-dev libopencolorio-dev libtbb-dev zlib1g-dev libopenvdb-dev libboost-dev
          pybind11-dev python3-dev python3-numpy  # the Python module
          # Debian 12's OpenImageIO CMake package names /usr/bin/iconvert and the other tools
          # among its targets, so find_package(OpenImageIO) fails without them
          openimageio-tools)
if [ "${KILN_SETUP:-all}" != render ]; then
    packages+=(libgtest-dev libbenchmark-dev libfmt-dev clang-format
               dpkg-dev  # the Debian package test (dpkg-shlibdeps)
               munge slurmctld slurmd slurm-client  # the Slurm cluster test
               python3-pytest python3-matplotlib blender)  # the Python and Blender tests
fi
source "$root/scripts/packages.sh"
kiln_install_missing "${packages[@]}"

jobs="$(nproc 2>/dev/null || echo 2)"
# Configured again after a render-only set-up, so that the test frameworks are found, and
# whenever an earlier configuration did not finish (a cache but no build system)
if [ ! -f "$build/Makefile" ] && [ ! -f "$build/build.ninja" ] || [ "${KILN_SETUP:-all}" != render ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$jobs" "$@"
