#!/usr/bin/env bash
# Power-proportional vs area-proportional light selection on a big cool emitter mesh with a
# small hot spot (bench/scenes/hot-spot-mesh.pbrt). Prints wall time and relMSE against a
# high-spp reference for each, and the error ratio at equal time.
#   bench/hotspot.sh [spp]   (default 16)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
scene="$root/bench/scenes/hot-spot-mesh.pbrt"
out="$root/bench/out/hotspot"
spp="${1:-16}"
mkdir -p "$out"
[ -f "$out/ref.exr" ] || "$kiln" "$scene" --spp 1024 --seed 12345 --quiet -o "$out/ref.exr"
declare -A err secs
for ls in power area; do
    start=$(date +%s.%N)
    "$kiln" "$scene" --spp "$spp" --light-sampler "$ls" --quiet -o "$out/$ls.exr"
    secs[$ls]=$(echo "$(date +%s.%N) - $start" | bc -l)
    err[$ls]=$("$kiln" diff "$out/$ls.exr" "$out/ref.exr" | awk '$1 == "relmse" {print $2}')
    printf "%-6s %6.2f s  relMSE %.4g\n" "$ls" "${secs[$ls]}" "${err[$ls]}"
done
# relMSE falls as 1/time, so at equal time the ratio is err_area * t_area / (err_power * t_power)
echo "area/power error ratio at equal time: $(echo "${err[area]} * ${secs[area]} / (${err[power]} * ${secs[power]})" | bc -l | cut -c1-6)"
