#!/usr/bin/env bash
# What an infrared render costs (issue 26: at most 1.5 times the visible one): a yard at night
# (a floor, rough gold, a dark diffuse ball and a wall) rendered by Film "thermal" in LWIR,
# where every surface emits (Option "ambienttemperature" 290, a sky at 230 K, the spheres at
# 330-350 K), against the same geometry and materials in the visible with one spherical area
# light and no temperatures. Prints the render-loop times (median of the repeats, alternating
# the variants, one thread) and their ratio.
#   bench/infrared_cost.sh [repeats]   (default 5)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
repeats="${1:-5}"
dir="$root/bench/out/infrared-cost"
mkdir -p "$dir"
scene() {  # name film-and-options light-line gold-temperature ball-temperature
    cat > "$dir/$1.pbrt" <<EOT
$2
Sampler "zsobol" "integer pixelsamples" 32
Integrator "path" "integer maxdepth" 5
LookAt 0 2 -6  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
$3
Material "diffuse" "spectrum reflectance" [300 0.3 20000 0.3]
Shape "bilinearmesh" "point3 P" [-10 0 -10  10 0 -10  -10 0 10  10 0 10]
Shape "bilinearmesh" "point3 P" [-10 0 6  10 0 6  -10 6 6  10 6 6]
AttributeBegin
  Translate -1 0.8 0
  Material "conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k"
      "float roughness" 0.1 $4
  Shape "sphere" "float radius" 0.8
AttributeEnd
AttributeBegin
  Translate 1.2 0.6 0
  Material "diffuse" "spectrum reflectance" [300 0.05 20000 0.05] $5
  Shape "sphere" "float radius" 0.6
AttributeEnd
EOT
}
scene infrared 'Option "float ambienttemperature" 290
Film "thermal" "string sensor" "lwir" "integer xresolution" 200 "integer yresolution" 150' \
    'LightSource "infinite" "float temperature" 230' '"float temperature" 350' \
    '"float temperature" 330'
scene visible 'Film "rgb" "integer xresolution" 200 "integer yresolution" 150' \
    'AttributeBegin Translate 0 4 -2 AreaLightSource "diffuse" "rgb L" [20 20 20] Shape "sphere" "float radius" 0.5 AttributeEnd' \
    '' ''
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
for v in infrared visible; do : > "$dir/$v.times"; done
for _ in $(seq "$repeats"); do
    for v in infrared visible; do
        "$kiln" "$dir/$v.pbrt" --threads 1 -o "$dir/$v.exr" 2>&1 | grep "wall" |
            sed 's/.* spp, \([0-9.]*\)s wall.*/\1/' >> "$dir/$v.times"
    done
done
i=$(median < "$dir/infrared.times")
v=$(median < "$dir/visible.times")
printf "infrared (LWIR, everything emits) %7.2fs\nvisible (one area light)          %7.2fs\n" "$i" "$v"
printf "infrared / visible                %7.3f\n" "$(echo "$i / $v" | bc -l)"
