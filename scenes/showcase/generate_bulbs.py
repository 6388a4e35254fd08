#!/usr/bin/env python3
"""Writes bulbs.pbrt.gz: three clear filament bulbs hanging in front of a plaster wall, on a
dimmer: tungsten filaments at 2500 K, 2000 K and 1650 K. Each bulb is a thin glass envelope
(thindielectric) around a squirrel-cage filament (a coiled tungsten wire zig-zagging between
support hooks, cooler where the hooks draw heat away: per-vertex temperatures), a glass stem,
nickel support wires, a brass screw base, a bakelite cap and a cord. The bulbs are the only
light. All geometry is generated here (no downloaded assets), deterministically.
Units: metres.

Usage: generate_bulbs.py (no arguments; writes bulbs.pbrt.gz next to this script)
"""
import gzip
import math
import os

from scene_text import SceneText, add, cross, mul, norm, sub

HERE = os.path.dirname(os.path.abspath(__file__))
scene = SceneText(temperature_digits=4)
emit, mesh = scene.emit, scene.mesh


def frame(d):
    """Two unit vectors perpendicular to the unit vector d."""
    helper = (0, 1, 0) if abs(d[1]) < 0.9 else (1, 0, 0)
    u = norm(cross(d, helper))
    return u, cross(d, u)


def tube(path, radius, sides=8, temperatures=None, normals=True):
    """A tube of one radius along a path (flat-shaded without normals: wires too thin to show
    facets)."""
    scene.tube(path, [radius] * len(path), sides, temperatures, normals=normals, twist_free=False)


def lathe(profile, segments=64):
    scene.lathe(profile, segments)


def smoothstep(s):
    s = min(max(s, 0), 1)
    return s * s * (3 - 2 * s)


# A pendant bulb hangs base up; y is measured downwards from the bottom of the screw base (t)
NECK, R, CENTRE = 0.0125, 0.032, 0.073  # neck radius, globe radius, globe centre depth


def glass_radius(t):
    if t <= CENTRE:
        return NECK + (R - NECK) * smoothstep(t / CENTRE)
    return math.sqrt(max(R * R - (t - CENTRE) ** 2, 0))


def coil(a, b, temperature_of, helix=0.0007, wire=0.00025, pitch=0.001, sag=0.002):
    """A coiled wire from a to b (a helix about a slightly sagging span), its temperature a
    function of the position s in [0, 1] along the span."""
    span = sub(b, a)
    length = math.sqrt(sum(c * c for c in span))
    d = norm(span)
    u, v = frame(d)
    turns = int(length / pitch)
    steps = turns * 6
    path, temps = [], []
    for i in range(steps + 1):
        s = i / steps
        centre = add(a, mul(span, s))
        centre = add(centre, (0, -sag * 4 * s * (1 - s), 0))  # sags under gravity (y down is -)
        ang = 2 * math.pi * turns * s
        offset = add(mul(u, helix * math.cos(ang)), mul(v, helix * math.sin(ang)))
        path.append(add(centre, offset))
        temps.append(temperature_of(s))
    tube(path, wire, sides=4, temperatures=temps, normals=False)


SPANS = 6
HOOKS_TOP = [(0.008 * math.cos(2 * math.pi * i / SPANS), 0.05,
              0.008 * math.sin(2 * math.pi * i / SPANS)) for i in range(SPANS)]
HOOKS_BOTTOM = [(0.0145 * math.cos(2 * math.pi * (i + 0.5) / SPANS), 0.086,
                 0.0145 * math.sin(2 * math.pi * (i + 0.5) / SPANS)) for i in range(SPANS)]


def bulb_parts():
    """Everything of a bulb but its filament (cold; one object, instanced per bulb), in the
    lathe's frame: the bottom of the screw base at the origin, the glass along +y."""
    emit('ObjectBegin "bulb"')
    # Glass envelope: thin glass, closed at the neck by the base
    emit('  Material "thindielectric" "float eta" 1.5')
    n = 64
    profile = [(glass_radius((CENTRE + R) * j / n), (CENTRE + R) * j / n) for j in range(n + 1)]
    profile[-1] = (0, CENTRE + R)
    lathe(profile, segments=64)
    # Glass stem up the axis, its flare into the neck, and the rod holding the lower hooks
    lathe([(0.0085, 0.0), (0.005, 0.008), (0.0022, 0.02), (0.0022, 0.047), (0.0032, 0.049),
           (0.0, 0.05)], segments=24)
    lathe([(0.0016, 0.05), (0.0016, 0.088), (0.0, 0.0885)], segments=16)
    # Support wires from the stem to each hook (nickel)
    emit('  Material "conductor" "spectrum eta" "metal-Ni-eta" "spectrum k" "metal-Ni-k"'
         ' "float roughness" 0.2')
    for h in HOOKS_TOP:
        tube([(0, 0.047, 0), (h[0] * 0.5, 0.049, h[2] * 0.5), h], 0.00018, sides=5)
    for h in HOOKS_BOTTOM:
        tube([(0, 0.087, 0), (h[0] * 0.6, 0.0875, h[2] * 0.6), h], 0.00018, sides=5)
    # Screw base (brass, a threaded surface of revolution), above the glass
    emit('  Material "conductor" "spectrum eta" "metal-CuZn-eta" "spectrum k" "metal-CuZn-k"'
         ' "float roughness" 0.25')
    pts, nrm, tris = [], [], []
    seg, rows, height, pitch, r0, amp = 48, 96, 0.024, 0.0036, 0.0133, 0.0008
    for j in range(rows + 1):
        yy = -height * j / rows
        for k in range(seg):
            a = 2 * math.pi * k / seg
            phase = 2 * math.pi * (-yy / pitch - a / (2 * math.pi))
            r = r0 + amp * math.sin(phase)
            dr_dy = amp * math.cos(phase) * 2 * math.pi / pitch  # d r / d(-y)
            length = math.hypot(1.0, dr_dy)
            pts.append((r * math.cos(a), yy, r * math.sin(a)))
            nrm.append((math.cos(a) / length, dr_dy / length, math.sin(a) / length))
    for j in range(rows):
        for k in range(seg):
            a, b = j * seg + k, j * seg + (k + 1) % seg
            c, d = a + seg, b + seg
            tris += [(a, c, b), (b, c, d)]
    mesh(pts, tris, nrm)
    # Bakelite cap and cord
    emit('  Material "coateddiffuse" "rgb reflectance" [0.02 0.018 0.016] "float roughness" 0.12')
    lathe([(0.0, -0.024), (0.0165, -0.024), (0.018, -0.028), (0.018, -0.06), (0.012, -0.068),
           (0.004, -0.072), (0.004, -0.08), (0.0, -0.08)], segments=48)
    emit('  Material "diffuse" "rgb reflectance" [0.03 0.03 0.03]')
    tube([(0, -0.08, 0), (0, -0.8, 0)], 0.0032, sides=12)
    emit("ObjectEnd")


def bulb(x, y, z, T, turn):
    """A bulb whose screw base's bottom is at (x, y, z), hanging down, its filament at T
    (kelvin), turned by `turn` degrees about its axis."""
    emit("AttributeBegin")
    emit("  Translate %g %g %g" % (x, y, z))
    emit("  Rotate 180 1 0 0  # the lathe's +y becomes down")
    emit("  Rotate %g 0 1 0" % turn)
    emit('  ObjectInstance "bulb"')

    def temperature(s):
        # the hooks draw heat: about 35 % cooler within the last few percent of a span
        cool = (1 - math.exp(-s / 0.05)) * (1 - math.exp(-(1 - s) / 0.05))
        return T * (0.65 + 0.35 * cool)

    # Filament: spans zig-zag between an upper and a lower ring of hooks; hot tungsten wire is
    # drawn and recrystallised, not polished (roughness 0.4)
    emit('  Material "conductor" "spectrum eta" "metal-W-eta" "spectrum k" "metal-W-k"'
         ' "float roughness" 0.4')
    for i in range(SPANS):
        coil(HOOKS_TOP[i], HOOKS_BOTTOM[i], temperature)
        coil(HOOKS_BOTTOM[i], HOOKS_TOP[(i + 1) % SPANS], temperature)
    emit("AttributeEnd")


def main():
    emit("# Three clear filament bulbs on a dimmer (generated by generate_bulbs.py; do not edit):")
    emit("# tungsten filaments at 2500 K, 2000 K and 1650 K behind thin glass, lighting a plaster")
    emit("# wall. Every light in the picture is thermal emission from the filaments.")
    emit("LookAt 0.0 -0.04 -0.29   0.0 -0.05 0.1   0 1 0")
    emit('Camera "perspective" "float fov" 30 "float lensradius" 0.003 '
         '"float focaldistance" 0.305')
    emit('Sampler "zsobol" "integer pixelsamples" 64')
    emit('Integrator "path" "integer maxdepth" 10')
    emit('Film "rgb" "integer xresolution" 1280 "integer yresolution" 720')
    emit('    "string view" "Filmic" "float exposure" 1 "string filename" "bulbs.exr"')
    emit()
    emit("WorldBegin")
    emit()
    emit("# The wall: plaster, its colour and relief from noise")
    emit("AttributeBegin")
    emit("  Scale 8 8 8")
    emit('  Texture "grain" "float" "fbm" "integer octaves" 6')
    emit('  Texture "plaster" "spectrum" "mix" "rgb tex1" [0.30 0.27 0.24]'
         ' "rgb tex2" [0.52 0.47 0.41] "texture amount" "grain"')
    emit("  Scale 6 6 6")
    emit('  Texture "relief" "float" "wrinkled" "integer octaves" 5')
    emit("AttributeEnd")
    emit('Texture "bumps" "float" "scale" "texture tex" "relief" "float scale" 0.0004')
    emit('Material "diffuse" "texture reflectance" "plaster" "texture displacement" "bumps"')
    emit('Shape "trianglemesh" "point3 P" [-2 -2 0.45  2 -2 0.45  2 2 0.45  -2 2 0.45]'
         ' "integer indices" [0 1 2 0 2 3] "point2 uv" [0 0 1 0 1 1 0 1]')
    emit()
    bulb_parts()
    bulb(0.0, 0.0, 0.0, 2500, 0)
    bulb(-0.15, 0.05, 0.15, 2000, 25)
    bulb(0.2, -0.01, 0.28, 1650, 50)
    # gzip-compressed (2.6 MB of text, 0.6 MB compressed; kiln and pbrt-v4 read .pbrt.gz),
    # with no time stamp, so the file is the same on every run
    with gzip.GzipFile(os.path.join(HERE, "bulbs.pbrt.gz"), "wb", mtime=0) as f:
        f.write(scene.text().encode())


if __name__ == "__main__":
    main()
