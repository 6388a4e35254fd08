#!/usr/bin/env bash
# Cost of thermal emission in scenes without hot objects: renders scenes with no temperatures
# with kiln as built (build/) and with a kiln built without thermal emission
# (-DKILN_THERMAL_EMISSION=OFF, in build-nothermal/, configured and built here if missing),
# alternating the two binaries, and prints the ratio of their median wall times.
#   bench/thermal_overhead.sh [repeats]   (default 5)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
with="${KILN_BUILD_DIR:-$root/build}/kiln"
without="$root/build-nothermal/kiln"
repeats="${1:-5}"
if [ ! -x "$without" ]; then
    cmake -S "$root" -B "$root/build-nothermal" -DCMAKE_BUILD_TYPE=Release \
        -DKILN_THERMAL_EMISSION=OFF >/dev/null
    cmake --build "$root/build-nothermal" -j "$(nproc)" --target kiln >/dev/null
fi
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
time_one() {  # binary scene spp
    local start end
    start=$(date +%s.%N)
    "$1" "$2" --spp "$3" --threads 2 --quiet -o /tmp/kiln-overhead.exr
    end=$(date +%s.%N)
    echo "$end - $start" | bc -l
}
for scene in cornell-box/cornell-box textured-meshes/textured-meshes; do
    file="$root/scenes/$scene.pbrt"
    : > /tmp/kiln-with.txt
    : > /tmp/kiln-without.txt
    for _ in $(seq "$repeats"); do
        time_one "$with" "$file" 16 >> /tmp/kiln-with.txt
        time_one "$without" "$file" 16 >> /tmp/kiln-without.txt
    done
    a=$(median < /tmp/kiln-with.txt)
    b=$(median < /tmp/kiln-without.txt)
    printf "%-18s with thermal %.3f s, without %.3f s, ratio %.4f\n" "$(basename "$scene")" \
        "$a" "$b" "$(echo "$a / $b" | bc -l)"
done
