#!/usr/bin/env bash
# Installs kiln's build dependencies (Debian 12 packages) when missing, then configures and
# builds kiln in Release. Idempotent: quick when nothing changed.
#   scripts/bootstrap.sh [extra cmake --build arguments, e.g. --target kiln]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_BUILD_DIR:-$root/build}"

packages=(build-essential cmake pkg-config libembree-dev libopenimageio-dev openimageio-tools
          libopenexr-dev libopencolorio-dev libtbb-dev zlib1g-dev libgtest-dev libbenchmark-dev libfmt-dev
          clang-format)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "kiln: installing missing packages: ${missing[*]}" >&2
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${missing[@]}" >/dev/null
fi

jobs="$(nproc 2>/dev/null || echo 2)"
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$jobs" "$@"
