#!/usr/bin/env python3
"""Writes forge.pbrt: a blacksmith's forge. A square steel bar drawn out to a point lies across
an anvil, its tip at a yellow heat (about 1600 K) fading to black along the bar (per-vertex
temperatures); beside it a polished copper bar at 1300 K glows only faintly, as good
reflectors do; flakes of hot scale lie on the anvil face and the floor, sparks fly from the
tip, a hammer rests on the anvil, and coals glow in a brick hearth behind. All geometry is
generated here (no downloaded assets), deterministically (fixed seeds).

Usage: generate_forge.py (no arguments; writes forge.pbrt next to this script)
"""
import math
import os
import random

from scene_text import SceneText

HERE = os.path.dirname(os.path.abspath(__file__))
scene = SceneText()
emit, mesh, box = scene.emit, scene.mesh, scene.box


def frustum(xb, zb, xt, zt, y0, y1):
    """A box whose bottom is xb x zb and top xt x zt (half sizes), centred on x = z = 0."""
    p = []
    for y, hx, hz in ((y0, xb, zb), (y1, xt, zt)):
        p += [(-hx, y, -hz), (hx, y, -hz), (hx, y, hz), (-hx, y, hz)]
    tris = [(0, 1, 2), (0, 2, 3), (4, 6, 5), (4, 7, 6)]
    for i in range(4):
        j = (i + 1) % 4
        tris += [(i, 4 + i, 4 + j), (i, 4 + j, j)]
    mesh(p, tris)


def loft(path, radius, segments=24, temperature=None):
    """A tube along path [(x, y, z)] with radius(s), s in [0, 1]; closed at the thin end."""
    pts, nrm, temps, tris = [], [], [], []
    n = len(path)
    for i, c in enumerate(path):
        a = path[max(i - 1, 0)]
        b = path[min(i + 1, n - 1)]
        t = [b[k] - a[k] for k in range(3)]
        lt = math.sqrt(sum(v * v for v in t))
        t = [v / lt for v in t]
        # a frame around t
        up = (0, 1, 0) if abs(t[1]) < 0.9 else (1, 0, 0)
        u = [up[1] * t[2] - up[2] * t[1], up[2] * t[0] - up[0] * t[2], up[0] * t[1] - up[1] * t[0]]
        lu = math.sqrt(sum(v * v for v in u))
        u = [v / lu for v in u]
        v = [t[1] * u[2] - t[2] * u[1], t[2] * u[0] - t[0] * u[2], t[0] * u[1] - t[1] * u[0]]
        r = radius(i / (n - 1))
        for j in range(segments):
            ph = 2 * math.pi * j / segments
            d = [math.cos(ph) * u[k] + math.sin(ph) * v[k] for k in range(3)]
            pts.append(tuple(c[k] + r * d[k] for k in range(3)))
            nrm.append(tuple(d))
            if temperature:
                temps.append(temperature(i / (n - 1)))
    for i in range(n - 1):
        for j in range(segments):
            a, b = i * segments + j, i * segments + (j + 1) % segments
            tris += [(a, b + segments, b), (a, a + segments, b + segments)]
    mesh(pts, tris, normals=nrm, temperatures=temps or None)


def bar(length, half, taper, temperature, steps=60):
    """A square bar along +x from 0 to length, half-width `half`, drawn out to a point over the
    last `taper` of its length; per-vertex temperatures from temperature(x / length)."""
    pts, temps, tris = [], [], []
    for i in range(steps + 1):
        s = i / steps
        x = s * length
        w = half * (1 - 0.85 * max(0.0, (s - (1 - taper)) / taper) ** 1.5)
        droop = -0.012 * max(0.0, (s - (1 - taper)) / taper) ** 2  # the point bends down
        for (y, z) in ((-w, -w), (w, -w), (w, w), (-w, w)):
            pts.append((x, y + droop, z))
            temps.append(temperature(s))
    for i in range(steps):
        for j in range(4):
            a, b = 4 * i + j, 4 * i + (j + 1) % 4
            tris += [(a, b, b + 4), (a, b + 4, a + 4)]
    tris += [(0, 2, 1), (0, 3, 2)]
    e = 4 * steps
    tris += [(e, e + 1, e + 2), (e, e + 2, e + 3)]
    mesh(pts, tris, temperatures=temps)


def flake(rng, cx, y, cz, size, t):
    """An irregular flat flake of scale (a fan of triangles) at a uniform temperature."""
    k = rng.randint(5, 8)
    pts = [(cx, y, cz)]
    for i in range(k):
        a = 2 * math.pi * (i + rng.uniform(-0.3, 0.3)) / k
        r = size * rng.uniform(0.5, 1.0)
        pts.append((cx + r * math.cos(a), y + rng.uniform(0, 0.002), cz + r * math.sin(a)))
    tris = [(0, 1 + i, 1 + (i + 1) % k) for i in range(k)]
    # both sides face up after the fan: order so the normal points up
    tris = [(a, c, b) for (a, b, c) in tris]
    mesh(pts, tris, temperatures=[t] * len(pts))


def main():
    rng = random.Random(1843)
    emit("# A blacksmith's forge (scenes/showcase/generate_forge.py writes this file; edit that).")
    emit("# A steel bar at a yellow heat on an anvil, hot scale, sparks, a hammer and a coal")
    emit("# hearth. Every glow is thermal emission by Kirchhoff's law (kiln's default).")
    emit('LookAt 0.75 0.78 1.85   -0.2 0.6 -0.3   0 1 0')
    emit('Camera "perspective" "float fov" 38 "float lensradius" 0.012 "float focaldistance" 1.95')
    emit('Sampler "zsobol" "integer pixelsamples" 64')
    emit('Integrator "volpath" "integer maxdepth" 8')
    emit('Film "rgb" "integer xresolution" 1280 "integer yresolution" 720')
    emit('    "string view" "Filmic" "float exposure" 5 "string filename" "forge.exr"')
    emit('PixelFilter "gaussian"')
    emit()
    emit("WorldBegin")
    emit()
    emit("# Night: a faint blue light from the door behind the camera")
    emit('LightSource "infinite" "rgb L" [0.00025 0.0003 0.0005]')
    emit("# Moonlight through the door on the left")
    emit('LightSource "distant" "point3 from" [3 4 2.5] "point3 to" [0 0 0] "rgb L" [0.006 0.008 0.014]')
    emit()
    emit("AttributeBegin  # the smithy's stone walls")
    emit('  Texture "stone" "float" "wrinkled" "integer octaves" 5 "float roughness" 0.7')
    emit('  Texture "wall" "spectrum" "mix" "texture amount" "stone"')
    emit('      "rgb tex1" [0.1 0.085 0.07] "rgb tex2" [0.22 0.19 0.16]')
    emit('  Material "diffuse" "texture reflectance" "wall"')
    emit('  Shape "trianglemesh" "point3 P" [-6 0 -2.2  6 0 -2.2  6 4 -2.2  -6 4 -2.2]')
    emit('      "integer indices" [0 1 2 0 2 3] "point2 uv" [0 0 12 0 12 4 0 4]')
    emit('  Shape "trianglemesh" "point3 P" [-2.4 0 -6  -2.4 0 4  -2.4 4 4  -2.4 4 -6]')
    emit('      "integer indices" [0 1 2 0 2 3] "point2 uv" [0 0 10 0 10 4 0 4]')
    emit("AttributeEnd")
    emit()
    emit("AttributeBegin  # packed earth floor")
    emit('  Texture "dirt" "float" "fbm" "integer octaves" 6 "float roughness" 0.6')
    emit('  Texture "floor" "spectrum" "mix" "texture amount" "dirt"')
    emit('      "rgb tex1" [0.05 0.045 0.04] "rgb tex2" [0.16 0.13 0.1]')
    emit('  Material "diffuse" "texture reflectance" "floor"')
    emit('  Shape "trianglemesh" "point3 P" [-8 0 -8  8 0 -8  8 0 8  -8 0 8]')
    emit('      "integer indices" [0 2 1 0 3 2] "point2 uv" [0 0 40 0 40 40 0 40]')
    emit("AttributeEnd")
    emit()
    # Anvil: feet, waist, body, horn and heel; face top at y = 0.55
    emit("AttributeBegin  # the anvil, wrought iron, its face worn bright")
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"')
    emit('      "float roughness" 0.32')
    emit("  AttributeBegin")
    frustum(0.24, 0.17, 0.19, 0.13, 0.0, 0.1)  # feet
    frustum(0.15, 0.1, 0.11, 0.085, 0.1, 0.36)  # waist
    emit("  AttributeEnd")
    emit("  AttributeBegin")
    emit("    Translate 0.02 0 0")
    frustum(0.2, 0.11, 0.26, 0.12, 0.36, 0.47)  # body flaring to the face
    emit("  AttributeEnd")
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"')
    emit('      "float roughness" 0.2')
    box(-0.24, 0.33, 0.47, 0.55, -0.12, 0.12)  # the face, polished by use
    # The horn: a tapering cone from the body's end, curving slightly down
    path = [(-0.24 - 0.42 * s, 0.5 - 0.05 * s * s, 0.0) for s in [i / 30 for i in range(31)]]
    loft(path, lambda s: 0.075 * (1 - s) ** 0.9 + 0.004, segments=28)
    emit("AttributeEnd")
    emit()
    # The bar: 0.9 m of 25 mm square steel; its drawn-out tip on the anvil face at x ~ -0.1
    emit("AttributeBegin  # the bar, at a yellow heat where it is drawn out")
    emit("  Translate -0.22 0.5635 0.02  Rotate -18 0 1 0  Rotate 4 0 0 1")
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"')
    emit('      "float roughness" 0.15')

    def bar_t(s):  # s = 0: far end, s = 1: the tip
        return 520 + 1080 / (1 + math.exp(-(s - 0.55) * 10))
    emit("  Scale -1 1 1")
    emit("  Translate -0.9 0 0")
    bar(0.9, 0.0125, 0.16, bar_t)
    emit("AttributeEnd")
    emit()
    emit("AttributeBegin  # a polished copper bar at the same heat as the steel's middle:")
    emit("  # a good reflector, so a poor emitter (Kirchhoff); additive emission makes it blaze")
    emit("  Translate 0.12 0.5705 0.075  Rotate 75 0 1 0")
    emit('  Material "conductor" "spectrum eta" "metal-Cu-eta" "spectrum k" "metal-Cu-k"')
    emit('      "float roughness" 0.06 "float temperature" 1300')
    emit('  Shape "cylinder" "float radius" 0.0205 "float zmin" -0.15 "float zmax" 0.15')
    emit('  Translate 0 0 -0.15 Shape "disk" "float radius" 0.0205')
    emit('  Translate 0 0 0.3 Shape "disk" "float radius" 0.0205')
    emit("AttributeEnd")
    emit()
    emit("AttributeBegin  # hot scale knocked off the bar: black iron oxide")
    emit('  Material "diffuse" "rgb reflectance" [0.06 0.055 0.05]')
    for _ in range(26):  # on the face, around the tip
        x, z = rng.uniform(-0.22, 0.1), rng.uniform(-0.1, 0.11)
        flake(rng, x, 0.5505, z, rng.uniform(0.004, 0.011), rng.uniform(780, 1180))
    for _ in range(70):  # on the floor at the anvil's foot, cooler the farther
        r, a = 0.26 + rng.expovariate(6.0), rng.uniform(0, 2 * math.pi)
        x, z = -0.1 + r * math.cos(a), 0.05 + r * math.sin(a)
        flake(rng, x, 0.0008, z, rng.uniform(0.004, 0.012), max(500, 1150 - 900 * (r - 0.26)))
    emit("AttributeEnd")
    emit()
    emit("AttributeBegin  # sparks: burning droplets of iron, streaked by the shutter")
    emit('  Material "diffuse" "rgb reflectance" [0.1 0.1 0.1] "float temperature" 1750')
    tip = (-0.08, 0.575, 0.0)
    for _ in range(22):
        a = rng.uniform(0, 2 * math.pi)
        up = rng.uniform(0.25, 0.9)
        d = (math.cos(a) * math.sqrt(1 - up * up), up, math.sin(a) * math.sqrt(1 - up * up))
        dist = rng.uniform(0.03, 0.35)
        length = rng.uniform(0.015, 0.06)
        p0 = [tip[k] + dist * d[k] for k in range(3)]
        p0[1] -= 1.5 * dist * dist  # falling
        path = [(p0[0] + s * length * d[0], p0[1] + s * length * d[1], p0[2] + s * length * d[2])
                for s in (0, 0.5, 1)]
        loft(path, lambda s: 0.0008 * (1 - 0.7 * s), segments=6)
    emit("AttributeEnd")
    emit()
    emit("AttributeBegin  # the hammer, resting on the heel")
    emit("  Translate 0.27 0.55 -0.07  Rotate 64 0 1 0")
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"')
    emit('      "float roughness" 0.25')
    box(-0.05, 0.05, 0.0, 0.036, -0.018, 0.018)
    emit('  Texture "grain" "float" "wrinkled" "integer octaves" 4')
    emit('  Texture "wood" "spectrum" "mix" "texture amount" "grain"')
    emit('      "rgb tex1" [0.22 0.12 0.06] "rgb tex2" [0.1 0.05 0.025]')
    emit('  Material "coateddiffuse" "texture reflectance" "wood" "float roughness" 0.3')
    emit('  Translate 0 0.018 0  Rotate 90 0 1 0  Rotate 4 1 0 0')
    emit('  Shape "cylinder" "float radius" 0.012 "float zmin" 0.018 "float zmax" 0.36')
    emit("AttributeEnd")
    emit()
    emit("AttributeBegin  # the hearth: firebrick, with a bed of coals")
    emit("  Translate -0.55 0 -1.78  Rotate 6 0 1 0")
    emit('  Material "diffuse" "rgb reflectance" [0.28 0.12 0.07]')
    box(-0.55, 0.55, 0.0, 0.72, -0.4, 0.4)   # the hearth block
    box(-0.55, -0.45, 0.72, 1.05, -0.4, 0.4)  # side walls
    box(0.45, 0.55, 0.72, 1.05, -0.4, 0.4)
    box(-0.55, 0.55, 0.72, 1.05, -0.4, -0.3)  # back wall
    box(-0.6, 0.6, 1.05, 1.12, -0.45, 0.45)   # the hood's lip
    emit("  AttributeBegin Translate 0 1.12 -0.05")
    frustum(0.6, 0.4, 0.22, 0.18, 0.0, 0.7)  # the hood narrowing to the chimney
    emit("  AttributeEnd")
    box(-0.22, 0.22, 1.82, 3.5, -0.23, 0.13)   # the chimney
    emit('  Material "diffuse" "rgb reflectance" [0.05 0.05 0.05]')
    emit('  Texture "embers" "float" "noise" "float frequency" 9 "float min" 950 "float max" 1550')
    emit('  Material "diffuse" "rgb reflectance" [0.05 0.05 0.05] "texture temperature" "embers"')
    for _ in range(260):
        x, z = rng.uniform(-0.43, 0.43), rng.uniform(-0.28, 0.38)
        r = rng.uniform(0.018, 0.04)
        y = 0.72 + r * 0.6 + rng.uniform(0, 0.06) * (1 - abs(x) / 0.45)
        emit('  AttributeBegin Translate %.4f %.4f %.4f Shape "sphere" "float radius" %.4f'
             ' AttributeEnd' % (x, y, z, r))
    emit("AttributeEnd")
    emit()
    with open(os.path.join(HERE, "forge.pbrt"), "w") as f:
        f.write(scene.text())


if __name__ == "__main__":
    main()
