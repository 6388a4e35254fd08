#!/usr/bin/env bash
# What polarised transport costs scenes that do not use it, and what it costs those that do:
# renders scenes with kiln as built (build/) and with kiln built at an earlier revision (before
# polarisation; default 93d61a1, checked out into build-base/src with git worktree and built in
# build-base/ if missing), alternating the binaries on one thread, and prints the ratios of the
# median render-loop times (kiln's "s wall" line, loading excluded). Then the same scenes with
# --stokes (the polarised variant) against plain, both with build/.
#   bench/polarization_overhead.sh [repeats] [base revision]   (defaults 5, 93d61a1)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
now="${KILN_BUILD_DIR:-$root/build}/kiln"
repeats="${1:-5}"
rev="${2:-93d61a1}"
base="$root/build-base/kiln"
source "$root/bench/compare_lib.sh"
build_revision "$root" "$rev" "$root/build-base"
scenes=("cornell-box/cornell-box 16" "textured-meshes/textured-meshes 8"
        "wilkie2011/gold-kirchhoff-ambient 8" "thermal/lava 8")
for s in "${scenes[@]}"; do
    read -r scene spp <<< "$s"
    compare "unpolarised: now / before" "$root/scenes/$scene.pbrt" "$spp" "$now" "" "$base" ""
done
for s in "${scenes[@]}"; do
    read -r scene spp <<< "$s"
    compare "polarised (--stokes) / unpolarised" "$root/scenes/$scene.pbrt" "$spp" "$now" \
        "--stokes" "$now" ""
done
