#!/usr/bin/env python3
"""The quantities that show kiln reproducing Wilkie & Weidlich 2011's figures, measured on the
repository's scenes with the Python module (docs/paper.md; test/python/test_paper.py asserts
them).

    PYTHONPATH=build/python scripts/paper_figures.py [SPP]      # prints every measurement

Each measure_* function renders what it needs at `spp` samples per pixel (seed 1) and returns
a dict of numbers. Pixels of a sphere or coin are found by projecting its centre through the
scene's pbrt-v4 LookAt camera (a disc of 0.85 of its projected radius: "sphere"; 0.45:
"centre"; from 0.75 to 0.95: "limb"), so no pixel of the floor is counted.
"""
import importlib.util
import math
import os
import re
import sys

import numpy as np

import kiln

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# The ring of the paper's test scene, as scenes/wilkie2011/generate.py places it: twelve spheres
# from 1050 K (11 o'clock) to 1600 K (12 o'clock) in 50 K steps
_spec = importlib.util.spec_from_file_location(
    "wilkie2011", os.path.join(ROOT, "scenes", "wilkie2011", "generate.py"))
wilkie2011 = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(wilkie2011)
CLOCK, SPHERE_RADIUS = wilkie2011.CLOCK, wilkie2011.SPHERE_RADIUS
# sRGB (linear, D65) to CIE XYZ
XYZ_FROM_SRGB = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722],
                          [0.0193, 0.1192, 0.9505]])


def camera_of(name):
    """The LookAt eye and target, fov and resolution of a scene file (up must be +y)."""
    with open(os.path.join(ROOT, "scenes", name)) as f:
        text = f.read()
    look = [float(v) for v in re.search(r"^LookAt\s+([-\d.\s]+?)\s*$", text, re.M).group(1).split()]
    assert look[6:] == [0, 1, 0], name
    fov = float(re.search(r'"float fov"\s+\[?\s*([\d.]+)', text).group(1))
    size = tuple(int(re.search(rf'"integer {a}resolution"\s+\[?\s*(\d+)', text).group(1))
                 for a in "xy")
    return dict(eye=look[0:3], look=look[3:6], fov=fov, size=size)


RING_CAMERA = camera_of("wilkie2011/silver-kirchhoff.pbrt")
COINS_CAMERA = camera_of("coins/coins.pbrt")


def scene(name):
    return kiln.load(os.path.join(ROOT, "scenes", name))


def sphere_centre(clock):
    return np.array(wilkie2011.sphere_position(clock))


def project(camera, p):
    """Raster position (x right, y down) of world point p, and pixels per world unit there,
    for pbrt-v4's LookAt camera (up +y; fov across the shorter image side)."""
    eye, look = np.array(camera["eye"], float), np.array(camera["look"], float)
    d = (look - eye) / np.linalg.norm(look - eye)
    right = np.cross([0.0, 1.0, 0.0], d)
    right /= np.linalg.norm(right)
    up = np.cross(d, right)
    v = np.asarray(p, float) - eye
    cx, cy, cz = v @ right, v @ up, v @ d
    w, h = camera["size"]
    half = min(w, h) / 2 / math.tan(math.radians(camera["fov"]) / 2)  # pixels per unit slope
    return (w / 2 + half * cx / cz, h / 2 - half * cy / cz), half / np.linalg.norm(v)


def disc(camera, centre, radius, inner, outer):
    """Pixels whose centres lie between inner and outer times the projected radius."""
    (px, py), scale = project(camera, centre)
    w, h = camera["size"]
    y, x = np.mgrid[0:h, 0:w] + 0.5
    r = np.hypot(x - px, y - py) / (radius * scale)
    return (r >= inner) & (r < outer)


def ring_masks(part="sphere"):
    inner, outer = {"sphere": (0, 0.85), "centre": (0, 0.45), "limb": (0.75, 0.95)}[part]
    return [disc(RING_CAMERA, sphere_centre(c), SPHERE_RADIUS, inner, outer) for c in CLOCK]


def xy(rgb_sum):
    X, Y, Z = XYZ_FROM_SRGB @ np.asarray(rgb_sum, float)
    return X / (X + Y + Z), Y / (X + Y + Z)


def luminance(img):
    return img @ XYZ_FROM_SRGB[1]


# Fig. 5: additive (B) against Kirchhoff (C) for black quartz and silver; the additive error at
# the limb and at the centre. The glow alone (no ambient light): the paper's figure has ambient
# light "of roughly similar strength", but the scenes' ambient (rgb L 0.05) outshines the cooler
# spheres' glow, and what silver reflects of it would mask what it emits
def measure_fig5(spp):
    out = {}
    spheres, centre, limb = ring_masks("sphere"), ring_masks("centre"), ring_masks("limb")
    hot = np.any(spheres, axis=0)
    for material in ("black-quartz", "silver"):
        B = luminance(scene(f"wilkie2011/{material}-additive.pbrt").render(spp=spp, seed=1))
        C = luminance(scene(f"wilkie2011/{material}-kirchhoff.pbrt").render(spp=spp, seed=1))
        out[f"{material} B/C"] = B[hot].sum() / C[hot].sum()
        # Relative error of B, (B - C) / C, at the limb and at the centre, over all spheres
        cm, lm = np.any(centre, axis=0), np.any(limb, axis=0)
        out[f"{material} error centre"] = B[cm].sum() / C[cm].sum() - 1
        out[f"{material} error limb"] = B[lm].sum() / C[lm].sum() - 1
    return out


# Fig. 6: the glow of selenium (a dark semiconductor), silver and platinum against black
# quartz's (Kirchhoff; the glow alone, as for Fig. 5)
def measure_fig6(spp):
    hot = np.any(ring_masks("sphere"), axis=0)
    glow = {}
    for material in ("selenium", "black-quartz", "silver", "platinum"):
        img = luminance(scene(f"wilkie2011/{material}-kirchhoff.pbrt").render(spp=spp, seed=1))
        glow[material] = img[hot].sum()
    return {f"{m}/black-quartz": g / glow["black-quartz"] for m, g in glow.items()}


# Fig. 7: the glow colour of gold and copper against the blackbody's (the additive render's
# sphere colour), per sphere, without and with ambient light
def measure_fig7(spp):
    out = {}
    spheres = ring_masks("sphere")
    blackbody = scene("wilkie2011/blackbody-lights.pbrt").render(spp=spp, seed=1)
    for material in ("gold", "copper"):
        for ambient in ("", "-ambient"):
            k = scene(f"wilkie2011/{material}-kirchhoff{ambient}.pbrt").render(spp=spp, seed=1)
            a = scene(f"wilkie2011/{material}-additive{ambient}.pbrt").render(spp=spp, seed=1)
            bb = None if ambient else blackbody
            dx, dy = [], []
            for m in spheres:
                xk, yk = xy(k[m].sum(axis=0))
                xa, ya = xy(a[m].sum(axis=0))
                dx.append(xk - xa)
                dy.append(yk - ya)
            out[f"{material}{ambient} dx"] = np.array(dx)
            out[f"{material}{ambient} dy"] = np.array(dy)
            if bb is not None:
                out[f"{material} xy 1300K"] = xy(k[spheres[5]].sum(axis=0))
                out["blackbody xy 1300K"] = xy(bb[spheres[5]].sum(axis=0))
    return out


# Fig. 1: two coins at 1300 K, gold and nickel
def measure_fig1(spp):
    img = scene("coins/coins.pbrt").render(spp=spp, seed=1)
    out = {}
    for metal, x in (("gold", -1.3), ("nickel", 1.3)):
        m = disc(COINS_CAMERA, (x, 0.16, 0), 1.0, 0, 0.45)
        out[f"{metal} xy"] = xy(img[m].sum(axis=0))
        out[f"{metal} Y"] = luminance(img)[m].mean()
    return out


# Fig. 8: a polished gold disc at 1200 K through a vertical and a horizontal polariser
def measure_fig8(spp):
    v = scene("polarization/fig8-gold-disc-vertical.pbrt").render(spp=spp, seed=1)
    h = scene("polarization/fig8-gold-disc-horizontal.pbrt").render(spp=spp, seed=1)
    return {"vertical/horizontal": luminance(v).sum() / luminance(h).sum()}


def limb_polarisation(image):
    """Over the limbs of the twelve spheres (green channel): the S0-weighted mean degree of
    linear polarisation sqrt(S1^2 + S2^2) / S0 of each pixel, and the radial part
    sum(S1 cos 2phi + S2 sin 2phi) / sum(S0), phi the direction of the pixel from its sphere's
    centre in the image (counter-clockwise from the horizontal; the film's Stokes reference axis
    is the image's horizontal, S2 > 0 from lower left to upper right): positive when the light
    is polarised along the sphere's radius, as emission (1 - F_p > 1 - F_s) is, negative when
    along the circumference, as reflection (F_s > F_p) is."""
    s0, s1, s2 = image["S0.G"], image["S1.G"], image["S2.G"]
    dop = radial = total = 0.0
    h, w = s0.shape
    y, x = np.mgrid[0:h, 0:w] + 0.5
    for clock, mask in zip(CLOCK, ring_masks("limb")):
        (px, py), _ = project(RING_CAMERA, sphere_centre(clock))
        phi = np.arctan2(-(y - py), x - px)[mask]
        dop += np.sqrt(s1[mask] ** 2 + s2[mask] ** 2).sum()
        radial += (s1[mask] * np.cos(2 * phi) + s2[mask] * np.sin(2 * phi)).sum()
        total += s0[mask].sum()
    return dop / total, radial / total


# Fig. 9: polarisation of the glow at the spheres' limbs, silver against black quartz, without
# and with ambient light
def measure_fig9(spp):
    out = {}
    for material in ("silver", "black-quartz"):
        for ambient in ("", "-ambient"):
            s = scene(f"polarization/fig9-{material}{ambient}.pbrt")
            s.render(spp=spp, seed=1)
            dop, radial = limb_polarisation(s.image())
            out[f"{material}{ambient} DoP"] = dop
            out[f"{material}{ambient} radial"] = radial
    return out


# Fig. 10: glowing gold spheres reflected in black glass, with and without polarised transport
def measure_fig10(spp):
    s = scene("polarization/fig10-black-glass.pbrt")
    plain = luminance(s.render(spp=spp, seed=1))
    polarised = luminance(s.render(spp=spp, seed=1, stokes=True))
    spheres = np.any(ring_masks("sphere"), axis=0)
    floor = ~np.any([disc(RING_CAMERA, sphere_centre(c), SPHERE_RADIUS, 0, 1.1) for c in CLOCK],
                    axis=0)
    reflection = floor & (plain > 0.02 * plain[spheres].mean())
    # Paired per-pixel differences (same seed): their mean in standard errors
    d = polarised[reflection] - plain[reflection]
    return {
        "reflections polarised/unpolarised": polarised[reflection].sum() / plain[reflection].sum(),
        "reflections difference z": d.mean() / (d.std(ddof=1) / np.sqrt(d.size)),
        "spheres polarised/unpolarised": polarised[spheres].sum() / plain[spheres].sum(),
        "reflection pixels": int(reflection.sum()),
    }


MEASURES = [measure_fig1, measure_fig5, measure_fig6, measure_fig7, measure_fig8, measure_fig9,
            measure_fig10]

if __name__ == "__main__":
    spp = int(sys.argv[1]) if len(sys.argv) > 1 else 64
    for measure in MEASURES:
        print(f"## {measure.__name__[8:]} ({spp} spp)")
        for key, value in measure(spp).items():
            if isinstance(value, np.ndarray):
                value = " ".join(f"{v:+.4f}" for v in value)
            elif isinstance(value, tuple):
                value = "(" + ", ".join(f"{v:.4f}" for v in value) + ")"
            elif isinstance(value, float):
                value = f"{value:.4g}"
            print(f"{key}: {value}")
