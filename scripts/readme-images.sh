#!/usr/bin/env bash
# Renders the small images of README.md and the user guide (docs/guide/) into docs/images/.
# Usage: scripts/readme-images.sh [spp] [all|thermal|paper|polarization|media|infrared]
#        (default 64 all)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
spp="${1:-64}"
out="$root/docs/images"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
render() {  # scene output.png [extra kiln args]
    local scene="$1" png="$2"
    shift 2
    "$kiln" "$scene" --spp "$spp" --quiet -o "$png" "$@"
}
mode="${2:-all}"
if [ "$mode" = all ]; then
for material in silver gold; do
    for model in additive kirchhoff; do
        render "$root/scenes/wilkie2011/$material-$model-ambient.pbrt" "$tmp/$material-$model.png"
    done
    # Side by side: additive (left) vs kirchhoff (right), half size.
    oiiotool "$tmp/$material-additive.png" "$tmp/$material-kirchhoff.png" --mosaic 2x1 \
        --resize 50% -o "$out/$material-additive-vs-kirchhoff.png"
done
render "$root/scenes/coins/coins.pbrt" "$tmp/coins.png"
oiiotool "$tmp/coins.png" --resize 66.67% -o "$out/coins.png"
fi
# Wilkie & Weidlich 2011 Figs. 6 and 7 (docs/paper.md): Kirchhoff's law, each image at its own
# automatic exposure as the paper's tone reproduction; Fig. 6 with ambient light (selenium,
# platinum / silver, black quartz), Fig. 7 without (black quartz, silver / gold, copper)
if [ "$mode" = all ] || [ "$mode" = paper ]; then
for m in selenium platinum silver black-quartz; do
    render "$root/scenes/wilkie2011/$m-kirchhoff-ambient.pbrt" "$tmp/fig6-$m.png" --exposure auto
done
oiiotool "$tmp/fig6-selenium.png" "$tmp/fig6-platinum.png" "$tmp/fig6-silver.png" \
    "$tmp/fig6-black-quartz.png" --mosaic 2x2 --resize 50% -o "$out/fig6-materials.png"
for m in black-quartz silver gold copper; do
    render "$root/scenes/wilkie2011/$m-kirchhoff.pbrt" "$tmp/fig7-$m.png" --exposure auto
done
oiiotool "$tmp/fig7-black-quartz.png" "$tmp/fig7-silver.png" "$tmp/fig7-gold.png" \
    "$tmp/fig7-copper.png" --mosaic 2x2 --resize 50% -o "$out/fig7-glow-colours.png"
fi
[ "$mode" = paper ] && exit 0
# Polarisation (scenes/polarization/, Wilkie & Weidlich 2011 Figs. 8-10)
if [ "$mode" = all ] || [ "$mode" = polarization ]; then
pol="$root/scenes/polarization"
for o in horizontal vertical; do
    render "$pol/fig8-gold-disc-$o.pbrt" "$tmp/fig8-$o.png"
done
oiiotool "$tmp/fig8-horizontal.png" "$tmp/fig8-vertical.png" --mosaic 2x1 --resize 50% \
    -o "$out/fig8-gold-disc.png"
for m in black-quartz silver; do
    for a in "" -ambient; do
        render "$pol/fig9-$m$a.pbrt" "$tmp/fig9-$m$a.exr" --polarisation
    done
done
oiiotool "$tmp/fig9-black-quartz-ambient-dop.png" "$tmp/fig9-silver-ambient-dop.png" \
    "$tmp/fig9-black-quartz-dop.png" "$tmp/fig9-silver-dop.png" --mosaic 2x2 --resize 50% \
    -o "$out/fig9-degree-of-polarisation.png"
oiiotool "$tmp/fig9-black-quartz-aop.png" "$tmp/fig9-silver-aop.png" --mosaic 2x1 \
    --resize 50% -o "$out/fig9-angle-of-polarisation.png"
render "$pol/fig10-black-glass.pbrt" "$tmp/fig10-without.exr" -o "$tmp/fig10-without.png"
render "$pol/fig10-black-glass.pbrt" "$tmp/fig10-with.exr" -o "$tmp/fig10-with.png" --stokes
# The difference of the linear images, 8 times brighter
oiiotool "$tmp/fig10-without.exr" "$tmp/fig10-with.exr" --ch R,G,B --sub --abs --mulc 8 \
    --colorconvert linear sRGB -o "$tmp/fig10-diff.png"
oiiotool "$tmp/fig10-without.png" "$tmp/fig10-with.png" "$tmp/fig10-diff.png" --mosaic 3x1 \
    --resize 50% -o "$out/fig10-black-glass.png"
fi
[ "$mode" = polarization ] && exit 0
# Hot glass and smoke (scenes/media/)
if [ "$mode" = all ] || [ "$mode" = media ]; then
media="$root/scenes/media"
render "$media/glass-blowing.pbrt" "$tmp/glass-blowing.png"
oiiotool "$tmp/glass-blowing.png" --resize 66.67% -o "$out/glass-blowing.png"
for q in black smoky; do
    render "$media/quartz-ring-$q.pbrt" "$tmp/quartz-ring-$q.png"
done
oiiotool "$tmp/quartz-ring-black.png" "$tmp/quartz-ring-smoky.png" --mosaic 2x1 --resize 50% \
    -o "$out/quartz-ring.png"
render "$media/lava-smoke.pbrt" "$tmp/lava-smoke.png"
oiiotool "$tmp/lava-smoke.png" --resize 66.67% -o "$out/lava-smoke.png"
fi
[ "$mode" = media ] && exit 0
# Infrared (docs/guide/infrared.md): a 653 nm pyrometer's temperatures of hot tungsten wires;
# a car at night in LWIR (README); a furnace through view ports in MWIR
if [ "$mode" = all ] || [ "$mode" = infrared ]; then
render "$root/scenes/infrared/pyrometer-filament.pbrt" "$out/pyrometer-filament.png"
render "$root/scenes/infrared/car-lwir.pbrt" "$out/car-lwir.png"
render "$root/scenes/infrared/furnace-mwir.pbrt" "$out/furnace-mwir.png"
fi
[ "$mode" = infrared ] && exit 0
# Temperature fields (scenes/thermal/): gradient, per-vertex lava, heat map, cooling blade
for scene in heated-bar lava heat-map; do
    render "$root/scenes/thermal/$scene.pbrt" "$tmp/$scene.png"
done
oiiotool "$tmp/heated-bar.png" "$tmp/lava.png" --mosaic 2x1 --resize 50% \
    -o "$out/heated-bar-and-lava.png"
oiiotool "$tmp/heat-map.png" --resize 50% -o "$out/heat-map.png"
"$kiln" "$root/scenes/thermal/cooling-blade.pbrt" --spp "$spp" --quiet --frames 0-48 --fps 12 \
    -o "$tmp/blade.####.png"
oiiotool "$tmp/blade.0000.png" "$tmp/blade.0024.png" "$tmp/blade.0048.png" --mosaic 3x1 \
    --resize 50% -o "$out/cooling-blade.png"
