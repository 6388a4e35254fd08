#!/usr/bin/env python3
"""Writes pour.pbrt: molten iron poured from a tilted ladle into a sand mould. The melt in the
ladle (up to 1820 K, with cooler floating slag from a noise field), its free-falling stream (1810 K,
thinning as it accelerates, rippled), the pool in the mould's pouring cup, the glowing
refractory lining of the ladle, splashes and sparks, a mould poured earlier whose risers have
crusted over (about 1250 K), spilled drops cooling on the floor, and hot fumes rising from the
pour (a uniformgrid medium with a temperature per voxel: it glows where it is hot and scatters
the metal's light). The only other light is a faint cold ambient. All geometry is generated
here (no downloaded assets), deterministically (fixed seeds). Units: metres.

Usage: generate_pour.py (no arguments; writes pour.pbrt next to this script)
"""
import math
import os
import random

from scene_text import SceneText, fmt

HERE = os.path.dirname(os.path.abspath(__file__))
G = 9.81
scene = SceneText(normal_digits=4, temperature_digits=4)
emit, mesh, box, lathe, tube, disc = (scene.emit, scene.mesh, scene.box, scene.lathe, scene.tube,
                                      scene.disc)


# The ladle: a bucket of radius R_LADLE and height H_LADLE, tilted by TILT about z so that
# its lip at local (R, H, 0) sits at LIP in the world
R_LADLE, H_LADLE, TILT = 0.14, 0.26, math.radians(62)
LIP = (0.22, 0.74, 0.0)


def ladle_to_world(p):
    """Local ladle coordinates (axis +y, lip towards +x) to world coordinates."""
    x, y, z = p
    c, s = math.cos(TILT), math.sin(TILT)
    # rotation by -TILT about z: the axis leans towards +x
    wx, wy = x * c + y * s, -x * s + y * c
    lx, ly = R_LADLE * c + H_LADLE * s, -R_LADLE * s + H_LADLE * c
    return (wx - lx + LIP[0], wy - ly + LIP[1], z + LIP[2])


def ladle():
    c, s = math.cos(TILT), math.sin(TILT)
    lx, ly = R_LADLE * c + H_LADLE * s, -R_LADLE * s + H_LADLE * c
    emit("AttributeBegin")
    emit("  Translate %g %g %g" % (LIP[0] - lx, LIP[1] - ly, LIP[2]))
    emit("  Rotate %g 0 0 1" % -math.degrees(TILT))
    # Steel shell, dark and scaled; a thick rim
    emit('  Material "diffuse" "rgb reflectance" [0.05 0.045 0.04]')
    lathe([(0.0, -0.02), (R_LADLE + 0.02, -0.02), (R_LADLE + 0.025, 0.0),
           (R_LADLE + 0.02, H_LADLE - 0.01), (R_LADLE + 0.03, H_LADLE - 0.005),
           (R_LADLE + 0.03, H_LADLE + 0.005), (R_LADLE + 0.005, H_LADLE + 0.012)])
    # Refractory lining, hot from the melt (cooler than it)
    emit('  Material "diffuse" "rgb reflectance" [0.35 0.3 0.25] "float temperature" 1350')
    lathe([(R_LADLE + 0.005, H_LADLE + 0.012), (R_LADLE, H_LADLE), (R_LADLE, 0.03),
           (R_LADLE - 0.02, 0.01), (0.0, 0.01)][::-1])
    # Trunnions and a shank to tilt it by
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"'
         ' "float roughness" 0.4')
    for side in (-1, 1):
        tube([(0, 0.15, side * (R_LADLE + 0.02)), (0, 0.15, side * 0.3)], [0.014, 0.014],
             sides=12)
    emit("AttributeEnd")
    # The shank: from a trunnion back towards -x (world)
    a = ladle_to_world((0, 0.15, -0.3))
    tube([a, (a[0] - 0.5, a[1] + 0.05, a[2] - 0.1), (a[0] - 1.4, a[1] + 0.1, a[2] - 0.25)],
         [0.016] * 3, sides=10)
    b = ladle_to_world((0, 0.15, 0.3))
    tube([b, (b[0] - 0.5, b[1] + 0.05, b[2] + 0.1), (b[0] - 1.4, b[1] + 0.1, b[2] + 0.3)],
         [0.016] * 3, sides=10)


def melt_surface():
    """The free surface of the melt in the ladle: horizontal at the lip's height, bounded by
    the lining (a fan over the ellipse where that plane cuts the tilted cylinder)."""
    r = R_LADLE - 0.002
    ring = []
    for k in range(64):
        th = 2 * math.pi * k / 64
        # local height h where the world height equals the lip's (bisection)
        lo, hi = 0.0, H_LADLE + 0.3
        for _ in range(50):
            mid = (lo + hi) / 2
            if ladle_to_world((r * math.cos(th), mid, r * math.sin(th)))[1] < LIP[1]:
                lo = mid
            else:
                hi = mid
        h = min(lo, H_LADLE)
        p = ladle_to_world((r * math.cos(th), h, r * math.sin(th)))
        ring.append((p[0], LIP[1] - 0.001, p[2]))
    cx = sum(p[0] for p in ring) / len(ring)
    cz = sum(p[2] for p in ring) / len(ring)
    pts = [(cx, LIP[1] - 0.001, cz)] + ring
    tris = [(0, 1 + (k + 1) % 64, 1 + k) for k in range(64)]
    mesh(pts, tris, [(0, 1, 0)] * len(pts))


def stream(v0=0.75, r0=0.02, steps=90):
    """The falling stream from the lip to the pouring cup; returns its end point."""
    rng = random.Random(3)
    phases = [rng.uniform(0, 2 * math.pi) for _ in range(4)]
    y_end = 0.345
    t_end = math.sqrt(2 * (LIP[1] - y_end) / G)
    path, radii, temps = [], [], []
    for i in range(steps + 1):
        t = t_end * i / steps
        x = LIP[0] + 0.012 + v0 * t
        y = LIP[1] + 0.008 - 0.5 * G * t * t
        z = 0.004 * math.sin(9 * t + phases[0])
        v = math.hypot(v0, G * t)
        path.append((x, y, z))
        radii.append(r0 * math.sqrt(v0 / v))
        temps.append(1810 - 15 * t / t_end)

    def ripple(i, k):
        s = i / steps
        return (1 + 0.12 * math.sin(55 * s + phases[1] + 2 * math.pi * k / 14)
                * math.sin(23 * s + phases[2]) + 0.05 * math.sin(140 * s + phases[3]))

    emit("AttributeBegin")
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"'
         ' "float roughness" 0.02')
    tube(path, radii, sides=14, temperatures=temps, ripple=ripple)
    emit("AttributeEnd")
    return path[-1]


def mould(cup):
    """A sand mould under the cup, the cup's pool and its splash and sparks."""
    emit("AttributeBegin")
    emit('  Material "diffuse" "texture reflectance" "sand"')
    box(cup[0] - 0.16, cup[0] + 0.32, 0.0, 0.3, -0.24, 0.24)
    emit("  AttributeBegin")
    emit("    Translate %g 0.3 %g" % (cup[0], cup[2]))
    lathe([(0.05, 0.0), (0.048, 0.035), (0.052, 0.05), (0.085, 0.05), (0.095, 0.0)])
    emit("  AttributeEnd")
    # The pool in the cup, its rim rippling
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"'
         ' "float roughness" 0.05')
    disc(cup[0], 0.343, cup[2], 0.049, temperature=1790,
         wobble=lambda k: 1 + 0.02 * math.sin(5 * k))
    # A raised crown of splash where the stream lands
    rng = random.Random(11)
    for k in range(10):
        a = 2 * math.pi * (k + rng.uniform(-0.3, 0.3)) / 10
        r = rng.uniform(0.016, 0.03)
        h = rng.uniform(0.008, 0.022)
        base = (cup[0] + r * math.cos(a), 0.343, cup[2] + r * math.sin(a))
        top = (base[0] + 0.4 * h * math.cos(a), base[1] + h, base[2] + 0.4 * h * math.sin(a))
        tube([base, top], [0.004, 0.0025], sides=6, temperatures=[1790, 1780])
    emit("AttributeEnd")
    # Sparks: short streaks (the distance each travels during the exposure) on ballistic arcs
    rng = random.Random(5)
    emit("AttributeBegin")
    emit('  Material "diffuse" "rgb reflectance" [0.1 0.1 0.1] "float temperature" 1850')
    for _ in range(70):
        a = rng.uniform(0, 2 * math.pi)
        speed = rng.uniform(0.8, 2.2)
        up = rng.uniform(0.6, 1.6)
        t = rng.uniform(0.04, 0.32)
        vx, vz = speed * math.cos(a), speed * math.sin(a)
        p0 = (cup[0] + vx * t, 0.35 + up * t - 0.5 * G * t * t, cup[2] + vz * t)
        if p0[1] < 0.31:
            continue
        dt = 0.012
        p1 = (p0[0] + vx * dt, p0[1] + (up - G * t) * dt, p0[2] + vz * dt)
        tube([p0, p1], [0.0011, 0.0011], sides=4)
    emit("AttributeEnd")


def earlier_mould():
    """A mould poured a few minutes ago: its two risers have crusted over."""
    emit("AttributeBegin")
    emit('  Material "diffuse" "texture reflectance" "sand"')
    box(0.55, 1.1, 0.0, 0.26, 0.45, 0.95)
    emit('  Texture "crust" "float" "noise" "float frequency" 60 "integer octaves" 4'
         ' "float min" 1000 "float max" 1330 "integer seed" 4')
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"'
         ' "float roughness" 0.35 "texture temperature" "crust"')
    for cx, cz, r in ((0.7, 0.6, 0.045), (0.95, 0.8, 0.035)):
        emit("  AttributeBegin")
        emit("    Translate %g 0.26 %g" % (cx, cz))
        lathe([(0.0, 0.03), (r * 0.8, 0.032), (r, 0.025), (r, 0.0)], segments=32)
        emit("  AttributeEnd")
    emit("AttributeEnd")


def floor_drops():
    """Spilled drops cooling on the floor, dull red."""
    rng = random.Random(9)
    emit("AttributeBegin")
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"'
         ' "float roughness" 0.3')
    for _ in range(14):
        x, z = rng.uniform(0.15, 0.95), rng.uniform(-0.55, -0.25)
        r = rng.uniform(0.006, 0.02)
        T = rng.uniform(850, 1150)
        w = [rng.uniform(0.75, 1.2) for _ in range(12)]
        disc(x, 0.002, z, r, segments=12, temperature=T, wobble=lambda k, w=w: w[k])
    emit("AttributeEnd")


def fumes(cup, nx=32, ny=48, nz=32):
    """Densities and temperatures of fumes rising from the pour (x fastest)."""
    x0, x1, y0, y1, z0, z1 = cup[0] - 0.55, cup[0] + 0.55, 0.33, 1.7, -0.45, 0.45
    rng = random.Random(21)
    lobes = [(rng.uniform(0.0, 1.2), rng.uniform(-0.12, 0.12), rng.uniform(-0.12, 0.12),
              rng.uniform(0.05, 0.14)) for _ in range(40)]
    density, temperature = [], []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                x = x0 + (x1 - x0) * (i + 0.5) / nx
                y = y0 + (y1 - y0) * (j + 0.5) / ny
                z = z0 + (z1 - z0) * (k + 0.5) / nz
                h = y - y0
                # the column drifts away from the stream and widens as it rises
                cx = cup[0] + 0.05 * h + 0.12 * h * h + 0.025 * math.sin(6 * h)
                cz = 0.06 * math.sin(4 * h + 1)
                width = 0.035 + 0.18 * h
                r2 = ((x - cx) ** 2 + (z - cz) ** 2) / (width * width)
                d = math.exp(-r2) * (1.0 - 0.45 * h / (y1 - y0))
                for ly, lx, lz, lr in lobes:
                    dd = (h - ly) ** 2 + (x - cx - lx * (0.3 + h)) ** 2 + (z - cz - lz * (0.3 + h)) ** 2
                    d += 0.6 * math.exp(-dd / (lr * lr * (0.5 + h)))
                d *= min(1.0, h / 0.04)
                d *= max(0.0, 1 - max(0.0, r2 - 5) / 3)
                density.append(max(0.0, d))
                temperature.append(420 + 1000 * math.exp(-h / 0.09))
    nums = lambda v, f: "\n        ".join(" ".join(f % x for x in v[i:i + nx])
                                          for i in range(0, len(v), nx))
    emit("AttributeBegin")
    emit('  MakeNamedMedium "fumes" "string type" "uniformgrid"')
    emit('      "integer nx" %d "integer ny" %d "integer nz" %d' % (nx, ny, nz))
    emit('      "point3 p0" [%g %g %g] "point3 p1" [%g %g %g]' % (x0, y0, z0, x1, y1, z1))
    emit('      "rgb sigma_a" [1.2 1.2 1.2] "rgb sigma_s" [7 7 7] "float g" 0.4')
    emit('      "string emission" "kirchhoff"')
    emit('      "float density" [\n        %s]' % nums(density, "%.3g"))
    emit('      "float temperature" [\n        %s]' % nums(temperature, "%.4g"))
    emit('  Material "interface"')
    emit('  MediumInterface "fumes" ""')
    emit('  Shape "trianglemesh" "integer indices" [0 2 1 0 3 2  4 5 6 4 6 7  0 1 5 0 5 4'
         '  3 7 6 3 6 2  0 4 7 0 7 3  1 2 6 1 6 5]')
    emit('      "point3 P" [%s]' % fmt([c for z in (z0, z1) for (x, y) in
                                       ((x0, y0), (x1, y0), (x1, y1), (x0, y1))
                                       for c in (x, y, z)]))
    emit("AttributeEnd")


def main():
    emit("# Molten iron poured from a ladle into a sand mould (generated by generate_pour.py; do")
    emit("# not edit): the melt at 1800 K, its stream, the pool in the pouring cup, the ladle's")
    emit("# glowing lining, sparks, a mould poured earlier, drops cooling on the floor and hot")
    emit("# fumes (a uniformgrid with a temperature per voxel). Thermal emission is the light.")
    emit("LookAt 1.25 0.95 -1.25   0.32 0.5 0.05   0 1 0")
    emit('Camera "perspective" "float fov" 36 "float lensradius" 0.006 "float focaldistance" 1.7')
    emit('Sampler "zsobol" "integer pixelsamples" 64')
    emit('Integrator "volpath" "integer maxdepth" 8')
    emit('Film "rgb" "integer xresolution" 1280 "integer yresolution" 720')
    emit('    "string view" "Filmic" "float exposure" 1 "string filename" "pour.exr"')
    emit()
    emit("WorldBegin")
    emit()
    emit("# A faint cold ambient (a foundry at night)")
    emit('LightSource "infinite" "rgb L" [0.002 0.0026 0.004]')
    emit()
    emit("AttributeBegin")
    emit("  Scale 12 12 12")
    emit('  Texture "grain" "float" "fbm" "integer octaves" 5')
    emit("AttributeEnd")
    emit('Texture "sand" "spectrum" "mix" "rgb tex1" [0.16 0.13 0.1] "rgb tex2" [0.3 0.25 0.19]'
         ' "texture amount" "grain"')
    emit('Texture "slagmelt" "float" "noise" "float frequency" 14 "integer octaves" 4'
         ' "float min" 1500 "float max" 1820 "integer seed" 2')
    emit("# The floor")
    emit('Material "diffuse" "texture reflectance" "sand"')
    emit('Shape "trianglemesh" "point3 P" [-4 0 -4  4 0 -4  4 0 4  -4 0 4]'
         ' "integer indices" [0 1 2 0 2 3]')
    emit()
    ladle()
    emit("AttributeBegin")
    emit("  # The melt: liquid iron at up to 1820 K, darker where cooler slag floats on it")
    emit('  Material "conductor" "spectrum eta" "metal-Fe-eta" "spectrum k" "metal-Fe-k"'
         ' "float roughness" 0.03 "texture temperature" "slagmelt"')
    melt_surface()
    emit("AttributeEnd")
    cup = stream()
    mould(cup)
    earlier_mould()
    floor_drops()
    fumes(cup)
    text = scene.text()
    with open(os.path.join(HERE, "pour.pbrt"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
