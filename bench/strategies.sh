#!/usr/bin/env bash
# Sampling strategies at equal time: MIS vs light-only vs BSDF-only direct lighting, and 4
# (hero) vs 1 wavelength per path, on one scene (default: the gold Kirchhoff spheres with
# ambient light, cropped). Prints wall time, relMSE against a high-spp reference, and each
# strategy's error relative to the default at equal time (relMSE x time, normalised; < 1 is
# better than the default).
#   bench/strategies.sh [scene.pbrt] [spp]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
scene="${1:-$root/scenes/wilkie2011/gold-kirchhoff-ambient.pbrt}"
spp="${2:-16}"
crop=(--crop 0.3 0.7 0.05 0.55)
out="$root/bench/out/strategies/$(basename "$scene" .pbrt)"
mkdir -p "$out"
[ -f "$out/ref.exr" ] || "$kiln" "$scene" "${crop[@]}" --spp 512 --seed 4242 --quiet -o "$out/ref.exr"
run() {  # name, extra kiln arguments...
    local name="$1"
    shift
    local start end
    start=$(date +%s.%N)
    "$kiln" "$scene" "${crop[@]}" --spp "$spp" --quiet -o "$out/$name.exr" "$@"
    end=$(date +%s.%N)
    local t e
    t=$(echo "$end - $start" | bc -l)
    e=$("$kiln" diff "$out/$name.exr" "$out/ref.exr" | awk '$1 == "relmse" {print $2}')
    echo "$name $t $e"
}
{
    run default
    run light-only --strategy light
    run bsdf-only --strategy bsdf
    run one-wavelength --wavelengths 1
} > "$out/results.txt"
awk 'NR == 1 {base = $2 * $3}
     {printf "%-15s %6.2f s  relMSE %.4g  error at equal time vs default: %.2fx\n",
             $1, $2, $3, ($2 * $3) / base}' "$out/results.txt"
