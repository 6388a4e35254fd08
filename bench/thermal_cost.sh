#!/usr/bin/env bash
# What a hot material costs per sample: two hot spheres (1500 K) on a floor, rendered with the
# spheres in different materials (Kirchhoff emission computed from each material's BSDF and
# emissivity tables), and, for each material, with the temperature replaced by an ordinary
# diffuse area light of blackbody colour on the same spheres (same material, so the same
# scattering work). Prints the render-loop times (median of the repeats, alternating the
# variants, one thread), the ratio of each hot material to the hot smooth conductor, and to
# the same material lit by the area light instead (what thermal emission itself costs).
#   bench/thermal_cost.sh [repeats]   (default 5)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
repeats="${1:-5}"
dir="$root/bench/out/thermal-cost"
mkdir -p "$dir"
scene() {  # name material-line hot|area
    local f="$dir/$1.pbrt"
    cat > "$f" <<EOT
Film "rgb" "integer xresolution" 200 "integer yresolution" 150
Sampler "zsobol" "integer pixelsamples" 32
Integrator "path" "integer maxdepth" 5
LookAt 0 2 -6  0 0.6 0  0 1 0
Camera "perspective" "float fov" 40
WorldBegin
Texture "checks" "spectrum" "checkerboard" "float uscale" 8 "float vscale" 8
    "rgb tex1" [0.8 0.3 0.2] "rgb tex2" [0.1 0.1 0.1]
Texture "rough" "float" "checkerboard" "float uscale" 8 "float vscale" 8 "float tex1" 0.05
    "float tex2" 0.4
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-10 0 -10 10 0 -10 10 0 10 -10 0 10]
$2
EOT
    for x in -1.2 1.2; do
        if [ "$3" = hot ]; then
            echo "AttributeBegin Translate $x 1 0 Shape \"sphere\" \"float radius\" 1 \"float temperature\" 1500 AttributeEnd" >> "$f"
        else
            echo "AttributeBegin Translate $x 1 0 AreaLightSource \"diffuse\" \"blackbody L\" [1500] Shape \"sphere\" \"float radius\" 1 AttributeEnd" >> "$f"
        fi
    done
}
metal='"conductor" "spectrum eta" "metal-Cu-eta" "spectrum k" "metal-Cu-k"'
materials=(smooth-conductor "Material $metal"
           rough-conductor "Material $metal \"float roughness\" 0.2"
           textured-roughness "Material $metal \"texture roughness\" \"rough\""
           diffuse 'Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]'
           textured-diffuse 'Material "diffuse" "texture reflectance" "checks"'
           coated-textured 'Material "coateddiffuse" "texture reflectance" "checks" "float roughness" 0.1')
names=()
for ((i = 0; i < ${#materials[@]}; i += 2)); do
    names+=("${materials[i]}")
    scene "${materials[i]}" "${materials[i + 1]}" hot
    scene "${materials[i]}-area" "${materials[i + 1]}" area
done
variants=""
for n in "${names[@]}"; do variants="$variants $n $n-area"; done
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
for v in $variants; do : > "$dir/$v.times"; done
for _ in $(seq "$repeats"); do
    for v in $variants; do
        "$kiln" "$dir/$v.pbrt" --threads 1 -o "$dir/$v.exr" 2>&1 | grep "wall" |
            sed 's/.* spp, \([0-9.]*\)s wall.*/\1/' >> "$dir/$v.times"
    done
done
ref=$(median < "$dir/smooth-conductor.times")
printf "%-20s %8s %12s %24s %22s\n" "material" "hot" "area light" "hot / hot smooth metal" \
    "hot / area light"
for n in "${names[@]}"; do
    t=$(median < "$dir/$n.times")
    a=$(median < "$dir/$n-area.times")
    printf "%-20s %7.2fs %11.2fs %24.3f %22.3f\n" "$n" "$t" "$a" "$(echo "$t / $ref" | bc -l)" \
        "$(echo "$t / $a" | bc -l)"
done
