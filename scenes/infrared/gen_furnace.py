#!/usr/bin/env python3
"""Writes scenes/infrared/furnace-mwir.pbrt: a furnace seen through two windows by an MWIR
camera (run by hand: gen_furnace.py > furnace-mwir.pbrt).

The scene's text is SCENE below; then the furnace, generated here (metres, y up, the camera on
-z looking at +z): a painted steel front plate at z = 0 with three view ports, a refractory
chamber behind it (its front wall at z = 0.3, the ports' tunnels joining the two), steel billets
on its hearth, and in the outer ports a glass window 25 mm thick: fused silica on the left,
soda-lime on the right; the middle port is open. Every box is a closed triangle mesh wound
outwards (the windows' media need it).
"""

SCENE = r"""# Written by gen_furnace.py (edit that and run it: gen_furnace.py > furnace-mwir.pbrt)
# A reheating furnace seen by a mid-wave infrared camera (3-5 um, a cooled InSb camera) through
# three view ports: the outer two closed by a window 25 mm thick at 600 K, fused silica on the
# left, soda-lime window glass on the right; the middle one open. Inside, steel billets at
# 1450 K on the hearth of a refractory chamber at 1250 K; outside, the painted front plate at
# 340 K in a 300 K hall.
#
# What the camera reports (emissivity setting 1; medians over each region at 64 spp):
#   - the open port: the billets 1411 K and the chamber wall 1262 K, close to their own
#     temperatures (emissivities 0.8 and 0.65, and each reflects the other's glow);
#   - fused silica, which passes part of the band (k 7e-6 at 3 um, 6e-5 at 4 um: the 25 mm
#     window passes 48 % and 1 %; opaque beyond 4.5 um) and reflects about 6 % at its two
#     faces: the billets 935 K, the wall 861 K, some 500 K too cold;
#   - soda-lime glass, which absorbs across the band (k 7e-5 to 3e-4: the pane passes under
#     0.1 %): only the window, 597 K, its own 600 K glow and a little of the hall;
#   - the painted plate, 340 K: 337 K.
# An MWIR view port needs a window clear across the band (sapphire), or the camera must be told
# the window's transmission.
#
# kiln furnace-mwir.pbrt -o furnace.exr -o furnace.png     (L, T; the PNG maps T)
Option "float ambienttemperature" 300
Film "thermal" "string sensor" "mwir" "float scalemin" 300 "float scalemax" 1500
    "integer xresolution" 480 "integer yresolution" 240 "string filename" "furnace-mwir.exr"
Sampler "zsobol" "integer pixelsamples" 64
Integrator "volpath" "integer maxdepth" 8
LookAt 0 1.75 -3.0  0 1.1 0  0 1 0
Camera "perspective" "float fov" 30
WorldBegin

# The hall's floor (concrete)
AttributeBegin
  Material "diffuse" "spectrum reflectance" [300 0.1 20000 0.1]
  Shape "bilinearmesh" "point3 P" [-20 0 -20  20 0 -20  -20 0 20  20 0 20]
AttributeEnd

MakeNamedMaterial "plate" "string type" "diffuse" "spectrum reflectance" [300 0.15 20000 0.15]
    "float temperature" 340
MakeNamedMaterial "refractory" "string type" "diffuse"
    "spectrum reflectance" [300 0.35 20000 0.35] "float temperature" 1250
MakeNamedMaterial "billet" "string type" "diffuse" "spectrum reflectance" [300 0.2 20000 0.2]
    "float temperature" 1450
MakeNamedMaterial "fused-silica" "string type" "dielectric" "spectrum eta"
    "glass-fused-silica-eta" "spectrum k" "glass-fused-silica-k" "float temperature" 600
MakeNamedMaterial "soda-lime" "string type" "dielectric" "spectrum eta" "glass-soda-lime-eta"
    "spectrum k" "glass-soda-lime-k" "float temperature" 600
"""

PORTS = [(-1.3, -0.72), (-0.29, 0.29), (0.72, 1.3)]  # x ranges of the three ports
PORT_Y = (0.9, 1.5)
PLATE = (-2.0, 2.0, 0.0, 2.6)  # x0 x1 y0 y1 at z = 0
CHAMBER = (-1.8, 1.8, 0.6, 2.4, 0.3, 3.0)  # the hearth 0.6 m above the floor  # x0 x1 y0 y1 z0 z1


def mesh(pts, tris):
    p = " ".join(f"{c:.4f}" for pt in pts for c in pt)
    i = " ".join(str(v) for t in tris for v in t)
    return f'Shape "trianglemesh" "point3 P" [ {p} ]\n    "integer indices" [ {i} ]\n'


def quad(a, b, c, d):
    """A quad as two triangles, counter-clockwise as given."""
    return [a, b, c, d], [(0, 1, 2), (0, 2, 3)]


def merge(parts):
    pts, tris = [], []
    for p, t in parts:
        b = len(pts)
        pts += p
        tris += [(i + b, j + b, k + b) for i, j, k in t]
    return pts, tris


def box(x0, x1, y0, y1, z0, z1, inward=False):
    """A closed box, its faces' normals (p1 - p0) x (p2 - p0) outwards (inwards if asked)."""
    pts = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    # indices: bit 0 x, bit 1 y, bit 2 z
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = []
    for a, b, c, d in faces:
        t = [(a, b, c), (a, c, d)]
        tris += [(i, k, j) for i, j, k in t] if inward else t
    return pts, tris


def wall_with_ports(z, x0, x1, y0, y1):
    """The plane z with the rectangle x0..x1, y0..y1 less the ports, as rectangles."""
    py0, py1 = PORT_Y
    rects = [(x0, x1, y0, py0), (x0, x1, py1, y1)]
    xs = [x0] + [v for p in PORTS for v in p] + [x1]
    for i in range(0, len(xs), 2):
        rects.append((xs[i], xs[i + 1], py0, py1))
    parts = [quad((a, c, z), (b, c, z), (b, d, z), (a, d, z)) for a, b, c, d in rects]
    return merge(parts)


def tunnels(z0, z1):
    parts = []
    py0, py1 = PORT_Y
    for a, b in PORTS:
        parts += [quad((a, py0, z0), (b, py0, z0), (b, py0, z1), (a, py0, z1)),
                  quad((a, py1, z0), (a, py1, z1), (b, py1, z1), (b, py1, z0)),
                  quad((a, py0, z0), (a, py0, z1), (a, py1, z1), (a, py1, z0)),
                  quad((b, py0, z0), (b, py1, z0), (b, py1, z1), (b, py0, z1))]
    return merge(parts)


def main():
    out = [SCENE]
    out.append('AttributeBegin\nNamedMaterial "plate"\n')
    out.append(mesh(*wall_with_ports(0.0, *PLATE)) + "AttributeEnd\n")
    x0, x1, y0, y1, z0, z1 = CHAMBER
    # The chamber: back, sides, roof and hearth as an open box, its front wall with the ports
    back = quad((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1))
    sides = [quad((x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)),
             quad((x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)),
             quad((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)),
             quad((x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0))]
    chamber = merge([back] + sides + [wall_with_ports(z0, x0, x1, y0, y1), tunnels(0.0, z0)])
    out.append('AttributeBegin\nNamedMaterial "refractory"\n' + mesh(*chamber) + "AttributeEnd\n")
    out.append('AttributeBegin\nNamedMaterial "billet"\n')
    for i, x in enumerate((-1.2, -0.1, 1.0)):
        out.append(mesh(*box(x - 0.3, x + 0.3, y0, y0 + 0.3, 0.9 + 0.2 * i, 2.6 - 0.1 * i)))
    out.append("AttributeEnd\n")
    py0, py1 = PORT_Y
    for (a, b), glass in zip((PORTS[0], PORTS[2]), ("fused-silica", "soda-lime")):
        out.append(f'AttributeBegin\nNamedMaterial "{glass}"\n')
        out.append(mesh(*box(a + 0.002, b - 0.002, py0 + 0.002, py1 - 0.002, 0.02, 0.045)))
        out.append("AttributeEnd\n")
    print("".join(out), end="")


if __name__ == "__main__":
    main()
