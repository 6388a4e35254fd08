"""kiln's glow scenes for bench/pairbench.py, each with a pbrt-v4 file of the same radiance.

kiln expresses thermal emission by temperature (Kirchhoff: a hot surface emits B(T) times one
minus its BSDF's albedo, a hot medium sigma_a n^2 B(T) per unit length); pbrt-v4 by emitters:

- Area lights and media `Le` given as `"blackbody" T` are normalised by pbrt-v4 to unit
  luminance before `scale` / `Lescale`. The factor that turns them into B(T) (W m^-2 sr^-1
  nm^-1, kiln's units) is measured, not computed: `photometric(T)` (bench/pairbench.py renders
  a hot black quad with kiln and a blackbody area light of scale 1 with pbrt-v4 and divides
  the image means). It comes out as sum over 1-nm steps of ybar(lambda) B(lambda, T) / 106.86
  (CIE Y's integral) within 1 % at 1000-1800 K, as pbrt-v4's conventions predict.

Exact where the emitter is a diffuse surface (emissivity 1 - rho, the same in every direction)
or a medium; a hot conductor's emissivity depends on angle and wavelength, which no pbrt-v4
emitter can express: that scene is compared in time only.
"""
import math
import os
import random
from typing import Callable

from pair_scenes import PairScene, Size, box, density_grid, fmt, header, write

FLOOR = ('Material "diffuse" "rgb reflectance" [0.4 0.4 0.4]\n'
         'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
         '    "point3 P" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n')
AMBIENT = 'LightSource "infinite" "rgb L" [0.02 0.02 0.025]\n'
ETA = 1.5


def hot_glass(out: str, size: Size, photometric: Callable[[float], float]) -> PairScene:
    """Two glass balls (eta 1.5) filled with a hot absorbing medium, 1300 K and 1100 K, on a
    floor: kiln's sigma_a n^2 B(T) is pbrt-v4's medium Le with Lescale n^2 photometric(T)."""
    folder = os.path.join(out, "hot-glass")
    film = '"float iso" 400'
    common = header(size, "0 1.5 -4.5  0 0.5 0  0 1 0", 40, "volpath", 20, film) + AMBIENT + FLOOR
    medium = '"rgb sigma_a" [3 5 9] "rgb sigma_s" [0.3 0.3 0.3]'
    balls = [(-0.7, 0.55, 1300), (0.7, 0.45, 1100)]
    kiln, pbrt = common, common
    for i, (x, r, T) in enumerate(balls):
        kiln += (f'MakeNamedMedium "melt{i}" "string type" "homogeneous" {medium} '
                 f'"float temperature" {T}\n')
        pbrt += (f'MakeNamedMedium "melt{i}" "string type" "homogeneous" {medium} '
                 f'"blackbody Le" {T} "float Lescale" {ETA * ETA * photometric(T):.6g}\n')
        shape = (f'AttributeBegin MediumInterface "melt{i}" "" '
                 f'Material "dielectric" "float eta" {ETA}\n'
                 f'  Translate {x} {r} 0 Shape "sphere" "float radius" {r}\nAttributeEnd\n')
        kiln += shape
        pbrt += shape
    return PairScene("hot-glass", "glass balls filled with hot medium",
                     write(folder, "kiln.pbrt", kiln),
                     write(folder, "pbrt.pbrt", pbrt), size.spp, size.ref_spp)


def hot_smoke(out: str, size: Size, photometric: Callable[[float], float]) -> PairScene:
    """A scattering, absorbing plume (uniformgrid density) at 1400 K: kiln's medium temperature
    is pbrt-v4's blackbody Le with Lescale photometric(T) in every voxel (pbrt-v4 wants one
    value per voxel)."""
    folder = os.path.join(out, "hot-smoke")
    n = 40 if size.scale >= 1 else 10
    T = 1400
    density = density_grid(n, "smoke")
    common = (header(size, "0 1.4 -5  0 1.1 0  0 1 0", 40, "volpath", 20, '"float iso" 400')
              + AMBIENT + FLOOR
              + 'AttributeBegin AreaLightSource "diffuse" "blackbody L" 6500 "float scale" 1\n'
              '  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
              '    "point3 P" [-3 4 -3  -1 4 -3  -1 4 -1  -3 4 -1]\nAttributeEnd\n')
    grid = ('"string type" "uniformgrid" "rgb sigma_a" [3 3 3] "rgb sigma_s" [3 3 3] '
            f'"float g" 0.2 "integer nx" {n} "integer ny" {n} "integer nz" {n}\n'
            '    "point3 p0" [-1.2 0.02 -1.2] "point3 p1" [1.2 2.42 1.2]\n'
            f'    "float density" [{fmt(density)}]\n')
    kiln = common + f'MakeNamedMedium "smoke" {grid}    "float temperature" {T}\n'
    pbrt = (common + f'MakeNamedMedium "smoke" {grid}    "blackbody Le" {T}\n'
            f'    "float Lescale" [{" ".join([f"{photometric(T):.6g}"] * len(density))}]\n')
    box_ = ('AttributeBegin MediumInterface "smoke" "" Material "interface"\n'
            + box(-1.2, 0.02, -1.2, 1.2, 2.42, 1.2) + 'AttributeEnd\n')
    return PairScene("hot-smoke", f"{n}^3 hot smoke grid, 1400 K",
                     write(folder, "kiln.pbrt", kiln + box_),
                     write(folder, "pbrt.pbrt", pbrt + box_), size.spp, size.ref_spp)


TEMPERATURES = (1000, 1200, 1400, 1600, 1800)


def hot_emitters(out: str, size: Size, photometric: Callable[[float], float]) -> PairScene:
    """400 small hot grey spheres (reflectance 0.2, so emissivity 0.8) at 1000-1800 K among
    cool diffuse and metal boxes: pbrt-v4 area lights of scale 0.8 photometric(T)."""
    folder = os.path.join(out, "hot-emitters")
    rng = random.Random("hot-emitters")
    count = max(30, int(400 * size.scale))
    common = header(size, "0 5 -12  0 0 2  0 1 0", 45, film='"float iso" 800') + AMBIENT + FLOOR
    for _ in range(30):
        x, z, h = rng.uniform(-8, 8), rng.uniform(-3, 10), rng.uniform(0.5, 2.5)
        common += (f'AttributeBegin Translate {x:.2f} {h / 2:.2f} {z:.2f} Material '
                   '"conductor" "spectrum eta" "metal-Al-eta" "spectrum k" "metal-Al-k" '
                   '"float roughness" 0.25\n'
                   f'  Shape "sphere" "float radius" {h / 2:.2f}\nAttributeEnd\n')
    kiln, pbrt = common, common
    for _ in range(count):
        p = (rng.uniform(-9, 9), rng.uniform(0.1, 3), rng.uniform(-4, 12))
        r, T = rng.uniform(0.03, 0.1), rng.choice(TEMPERATURES)
        kiln += (f'AttributeBegin Translate {fmt(p)} Material "diffuse" "rgb reflectance" '
                 f'[0.2 0.2 0.2] "float temperature" {T}\n'
                 f'  Shape "sphere" "float radius" {r:.3f}\nAttributeEnd\n')
        pbrt += (f'AttributeBegin Translate {fmt(p)} Material "diffuse" "rgb reflectance" '
                 f'[0.2 0.2 0.2]\n  AreaLightSource "diffuse" "blackbody L" {T} '
                 f'"float scale" {0.8 * photometric(T):.6g}\n'
                 f'  Shape "sphere" "float radius" {r:.3f}\nAttributeEnd\n')
    return PairScene("hot-emitters", f"{count} hot spheres, 1000-1800 K",
                     write(folder, "kiln.pbrt", kiln), write(folder, "pbrt.pbrt", pbrt),
                     size.spp, size.ref_spp)


def hot_metal_glass(out: str, size: Size, photometric: Callable[[float], float]) -> PairScene:
    """A hot copper ball (1300 K, roughness 0.2) behind a thick glass pane. kiln: Kirchhoff
    emission B(T) (1 - albedo(direction, lambda)). pbrt-v4 has no such emitter: its file uses a
    diffuse blackbody area light on the ball with about copper's normal-incidence emissivity
    (0.1; 0.08 at 600 nm), an approximation, so only times are compared."""
    folder = os.path.join(out, "hot-metal-glass")
    T = 1300
    common = (header(size, "0 1.2 -4.5  0 0.6 0  0 1 0", 40, maxdepth=12, film='"float iso" 400')
              + 'LightSource "infinite" "rgb L" [0.05 0.05 0.06]\n' + FLOOR
              + 'AttributeBegin Material "dielectric" "float eta" 1.5\n'
              + box(-1.5, 0.01, -1.6, 1.5, 2, -1.4) + 'AttributeEnd\n')
    metal = ('Material "conductor" "spectrum eta" "metal-Cu-eta" "spectrum k" "metal-Cu-k" '
             '"float roughness" 0.2')
    kiln = common + (f'AttributeBegin {metal} "float temperature" {T}\n'
                     '  Translate 0 0.6 0 Shape "sphere" "float radius" 0.6\nAttributeEnd\n')
    pbrt = common + (f'AttributeBegin {metal}\n  AreaLightSource "diffuse" "blackbody L" {T} '
                     f'"float scale" {0.1 * photometric(T):.6g}\n'
                     '  Translate 0 0.6 0 Shape "sphere" "float radius" 0.6\nAttributeEnd\n')
    return PairScene("hot-metal-glass", "hot copper ball behind a glass pane",
                     write(folder, "kiln.pbrt", kiln), write(folder, "pbrt.pbrt", pbrt),
                     size.spp, size.ref_spp, equivalent=False,
                     note="pbrt-v4 cannot express Kirchhoff emission of a conductor: time only")


def flame_room(size: Size) -> str:
    """A room (floor, back and left walls, ceiling; the camera's side and the right open) with
    a table, lit only by a faint sky: the setting of hot-flame and hot-gob."""
    return (header(size, "0 1.3 -3.8  0 0.9 0  0 1 0", 50, "volpath", 8, '"float iso" 400')
            + 'LightSource "infinite" "rgb L" [0.0002 0.0002 0.0003]\n'
            'Material "diffuse" "rgb reflectance" [0.6 0.55 0.5]\n'
            # floor, back wall, left wall, ceiling (the camera's side and the right are open)
            'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
            '    "point3 P" [-3 0 -4  3 0 -4  3 0 3  -3 0 3]\n'
            'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
            '    "point3 P" [-3 0 3  3 0 3  3 3 3  -3 3 3]\n'
            'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
            '    "point3 P" [-3 0 -4  -3 0 3  -3 3 3  -3 3 -4]\n'
            'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
            '    "point3 P" [-3 3 -4  -3 3 3  3 3 3  3 3 -4]\n'
            'Material "diffuse" "rgb reflectance" [0.4 0.25 0.15]\n'
            + box(-0.8, 0.0, -0.5, 0.8, 0.6, 0.5))


def hot_flame(out: str, size: Size, photometric: Callable[[float], float]) -> PairScene:
    """A small flame (a 24^3 absorbing, emitting grid, 1800 K, 10 cm across) the
    only light of a room with a table and a faint sky through a window: the walls and table
    are lit by a small hot medium, which tracking finds only by chance (kiln's "mediumemission"
    "sampled" samples it as a light source). pbrt-v4: blackbody Le times Lescale
    photometric(T) in every voxel."""
    folder = os.path.join(out, "hot-flame")
    n = 24 if size.scale >= 1 else 8
    T = 1800
    common = flame_room(size)
    # A teardrop of density above the table, zero on the grid's faces
    d = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                x, y, z = (i + 0.5) / n - 0.5, (j + 0.5) / n, (k + 0.5) / n - 0.5
                r = 0.35 * math.sin(math.pi * min(y, 1.0)) ** 0.8 * (1 - 0.5 * y)
                v = 0.0 if 0 in (i, j, k) or n - 1 in (i, j, k) else \
                    max(0.0, 1 - (x * x + z * z) / max(r * r, 1e-6))
                d.append(round(v, 4))
    lo, hi = (-0.05, 0.62, -0.05), (0.05, 0.82, 0.05)
    grid = ('"string type" "uniformgrid" "rgb sigma_a" [60 60 60] "rgb sigma_s" [0 0 0] '
            f'"integer nx" {n} "integer ny" {n} "integer nz" {n}\n'
            f'    "point3 p0" [{fmt(lo)}] "point3 p1" [{fmt(hi)}]\n'
            f'    "float density" [{fmt(d)}]\n')
    kiln = common + f'MakeNamedMedium "flame" {grid}    "float temperature" {T}\n'
    pbrt = (common + f'MakeNamedMedium "flame" {grid}    "blackbody Le" {T}\n'
            f'    "float Lescale" [{" ".join([f"{photometric(T):.6g}"] * len(d))}]\n')
    box_ = ('AttributeBegin MediumInterface "flame" "" Material "interface"\n'
            + box(*lo, *hi) + 'AttributeEnd\n')
    return PairScene("hot-flame", f"a small flame lighting a room ({n}^3 grid, 1800 K)",
                     write(folder, "kiln.pbrt", kiln + box_),
                     write(folder, "pbrt.pbrt", pbrt + box_), size.spp, size.ref_spp)


def hot_gob(out: str, size: Size, photometric: Callable[[float], float]) -> PairScene:
    """A molten glass gob (a glass ball of radius 0.12 filled with a hot absorbing, scattering
    melt at 1400 K) above the table of hot-flame's room: the room is lit through the glass,
    which shadow rays cannot cross (kiln samples the melt through its glass, "glasswindows").
    pbrt-v4: medium Le with Lescale n^2 photometric(T), as hot-glass."""
    folder = os.path.join(out, "hot-gob")
    T = 1400
    medium = '"rgb sigma_a" [3 5 9] "rgb sigma_s" [0.3 0.3 0.3]'
    ball = ('AttributeBegin MediumInterface "melt" "" '
            f'Material "dielectric" "float eta" {ETA}\n'
            '  Translate 0 0.72 0 Shape "sphere" "float radius" 0.12\nAttributeEnd\n')
    common = flame_room(size)
    kiln = (common + f'MakeNamedMedium "melt" "string type" "homogeneous" {medium} '
            f'"float temperature" {T}\n' + ball)
    pbrt = (common + f'MakeNamedMedium "melt" "string type" "homogeneous" {medium} '
            f'"blackbody Le" {T} "float Lescale" {ETA * ETA * photometric(T):.6g}\n' + ball)
    return PairScene("hot-gob", "a molten glass gob lighting a room, 1400 K",
                     write(folder, "kiln.pbrt", kiln),
                     write(folder, "pbrt.pbrt", pbrt), size.spp, size.ref_spp)


GENERATORS = [hot_glass, hot_smoke, hot_flame, hot_gob, hot_emitters, hot_metal_glass]
