#!/usr/bin/env bash
# Installs kiln's build and test dependencies (Debian 12 packages) when missing, then configures
# and builds kiln in Release. Idempotent: quick when nothing changed.
#   scripts/bootstrap.sh [extra cmake --build arguments, e.g. --target kiln]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_BUILD_DIR:-$root/build}"

packages=(build-essential cmake pkg-config libembree-dev libopenimageio-dev openimageio-tools
          libopenexr-dev libpng-dev libopencolorio-dev libtbb-dev zlib1g-dev libgtest-dev
          libbenchmark-dev libfmt-dev libopenvdb-dev libboost-dev clang-format
          munge slurmctld slurmd slurm-client)  # the last four: the Slurm cluster test
source "$root/scripts/packages.sh"
kiln_install_missing "${packages[@]}"

jobs="$(nproc 2>/dev/null || echo 2)"
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$jobs" "$@"
