#!/usr/bin/env python3
"""Writes scenes/infrared/car-lwir.pbrt: a car at night through an LWIR camera (run by hand).

The scene's text is SCENE below (its materials carry the parts' temperatures: "float
temperature" on a material); then the car, generated here. A hatchback of 4.3 x 1.8 x 1.45 m
(length along x, front at -x, y up, width along z, wheels on the ground y = 0), as pbrt-v4
shapes, each part with its own named material:
  - body: the side profile extruded across the width, both sides closed (fans from the
    profile's centroid; the profile is star-shaped about it); its panels as three meshes:
    "hood" (the warm bonnet over the engine), "cabin" (roof, pillars, tailgate, sides) and
    "bumpers";
  - glass: windscreen, rear window and the two side windows, each a closed slab 6 mm thick set
    1 cm outside the body (absorbing glass needs closed bodies: kiln fills them with a medium
    absorbing what k says);
  - wheels: tyres (cylinders) and hubs (disks).
Materials the shapes name: "paint-hood", "paint", "bumper", "glass", "rubber", "hub".
Usage: gen_car.py > car-lwir.pbrt
"""
import math

SCENE = r"""# Written by gen_car.py (edit that and run it: gen_car.py > car-lwir.pbrt)
# A car at night through a long-wave infrared camera (8-14 um, an uncooled microbolometer's
# band). The air, the street and everything without its own temperature are at 283 K (10 C);
# the clear night sky is a 230 K blackbody (an infinite light at a temperature). The car has
# just been parked: its bonnet is at 320 K over the engine, the tyres at 305 K, the aluminium
# wheel hubs (warmed by the brakes) at 330 K.
#
# What the camera reports (the T channel, the temperature of a blackbody of the same in-band
# radiance; the camera's emissivity setting 1, as cameras come):
#   - the roof and the tailgate read colder than the air: their glossy clear coat reflects
#     the cold sky (more at grazing angles), and the paint beneath emits 1 minus what the coat
#     and the paint reflect (Kirchhoff from the same coated BSDF);
#   - the windows are opaque at 8-14 um (soda-lime glass absorbs there: "spectrum k"
#     "glass-soda-lime-k"), so the camera sees neither into the car nor through the glass, but
#     the glass's own emission and what it reflects of the sky (up to 25 % near 9.5 um);
#   - the warm parts stand out by their temperature, the rubber (emissivity about 0.95) reading
#     close to its own; the aluminium wheel hubs, hotter, read far below theirs (their
#     emissivity at 10 um is about 0.02: they mostly reflect the tyres and the ground);
#   - the asphalt under the engine, warmed by the drive, shows the car's heat shadow.
# The picture's palette spans 255-325 K ("scalemin", "scalemax"), as a camera set to a fixed
# span.
#
# kiln car-lwir.pbrt -o car.exr -o car.png     (L: in-band radiance, T; the PNG maps T)
Option "float ambienttemperature" 283
Film "thermal" "string sensor" "lwir" "float scalemin" 255 "float scalemax" 325
    "integer xresolution" 480 "integer yresolution" 270 "string filename" "car-lwir.exr"
Sampler "zsobol" "integer pixelsamples" 64
Integrator "volpath" "integer maxdepth" 6
LookAt -6.6 3.0 -5.4  0.1 0.5 0  0 1 0
Camera "perspective" "float fov" 32
WorldBegin

LightSource "infinite" "float temperature" 230

# An open car park: asphalt (emissivity about 0.93), warmed to 293 K under the engine by the
# drive (a disk just above the ground)
AttributeBegin
  Material "diffuse" "spectrum reflectance" [300 0.07 20000 0.07]
  Shape "bilinearmesh" "point3 P" [-60 0 -60  60 0 -60  -60 0 60  60 0 60]
  AttributeBegin
    Translate -1.2 0.002 0
    Rotate -90 1 0 0
    Scale 1.4 1 1
    Shape "disk" "float radius" 0.8 "float temperature" 293
  AttributeEnd
AttributeEnd

# The car's materials and temperatures
MakeNamedMaterial "paint" "string type" "coateddiffuse"
    "spectrum reflectance" [300 0.1 20000 0.1] "float roughness" 0.02
MakeNamedMaterial "paint-hood" "string type" "coateddiffuse"
    "spectrum reflectance" [300 0.1 20000 0.1] "float roughness" 0.02 "float temperature" 320
MakeNamedMaterial "bumper" "string type" "diffuse" "spectrum reflectance" [300 0.08 20000 0.08]
MakeNamedMaterial "glass" "string type" "dielectric"
    "spectrum eta" "glass-soda-lime-eta" "spectrum k" "glass-soda-lime-k"
MakeNamedMaterial "rubber" "string type" "diffuse" "spectrum reflectance" [300 0.05 20000 0.05]
    "float temperature" 305
MakeNamedMaterial "hub" "string type" "conductor" "spectrum eta" "metal-Al-eta"
    "spectrum k" "metal-Al-k" "float roughness" 0.01 "float temperature" 330
"""

HALF_WIDTH = 0.9
# Side profile, counter-clockwise seen from +z: (x, y) in metres
PROFILE = [(-2.15, 0.28), (2.15, 0.28), (2.2, 0.62), (2.12, 0.98), (1.95, 1.05),
           (1.55, 1.40), (0.9, 1.45), (-0.25, 1.44), (-0.95, 1.0), (-2.05, 0.86),
           (-2.2, 0.62)]
# Which profile edges (index of the first point) belong to which panel
HOOD_EDGES = {8}
BUMPER_EDGES = {0, 1, 9, 10}  # underbody, rear bumper, grille, front bumper
WINDSCREEN_EDGE = 7
REAR_WINDOW_EDGE = 4


def mesh(points, triangles):
    p = " ".join(f"{c:.4f}" for pt in points for c in pt)
    i = " ".join(str(v) for t in triangles for v in t)
    return f'Shape "trianglemesh" "point3 P" [ {p} ]\n    "integer indices" [ {i} ]\n'


def strip(edges):
    """The extruded faces of the given profile edges."""
    pts, tris = [], []
    for e in sorted(edges):
        (x0, y0), (x1, y1) = PROFILE[e], PROFILE[(e + 1) % len(PROFILE)]
        b = len(pts)
        pts += [(x0, y0, -HALF_WIDTH), (x1, y1, -HALF_WIDTH), (x1, y1, HALF_WIDTH),
                (x0, y0, HALF_WIDTH)]
        # Outward normals: counter-clockwise seen from outside
        tris += [(b, b + 2, b + 1), (b, b + 3, b + 2)]
    return pts, tris


def sides():
    cx = sum(p[0] for p in PROFILE) / len(PROFILE)
    cy = sum(p[1] for p in PROFILE) / len(PROFILE)
    pts, tris = [], []
    for z, flip in ((HALF_WIDTH, False), (-HALF_WIDTH, True)):
        b = len(pts)
        pts.append((cx, cy, z))
        pts += [(x, y, z) for x, y in PROFILE]
        n = len(PROFILE)
        for i in range(n):
            a, c = b + 1 + i, b + 1 + (i + 1) % n
            tris.append((b, c, a) if flip else (b, a, c))
    return pts, tris


def outward(pts, tris):
    """The triangles of a convex closed body wound so that their normals (p1 - p0) x (p2 - p0),
    pbrt-v4's, point away from its centroid: the glass's medium is on the inside."""
    c = [sum(p[k] for p in pts) / len(pts) for k in range(3)]
    out = []
    for t in tris:
        p0, p1, p2 = (pts[i] for i in t)
        e1 = [p1[k] - p0[k] for k in range(3)]
        e2 = [p2[k] - p0[k] for k in range(3)]
        n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0]]
        away = sum(n[k] * (p0[k] - c[k]) for k in range(3))
        out.append(t if away > 0 else (t[0], t[2], t[1]))
    return pts, out


def slab(corners, normal, thickness=0.006, offset=0.01):
    """A closed slab on the quad `corners` (in order around it), moved `offset` along the
    outward unit `normal`."""
    outer = [tuple(c[k] + normal[k] * (offset + thickness) for k in range(3)) for c in corners]
    inner = [tuple(c[k] + normal[k] * offset for k in range(3)) for c in corners]
    pts = outer + inner
    tris = [(0, 1, 2), (0, 2, 3), (4, 6, 5), (4, 7, 6)]
    for i in range(4):
        j = (i + 1) % 4
        tris += [(i, i + 4, j + 4), (i, j + 4, j)]
    return outward(pts, tris)


def edge_glass(e, inset_x=0.06, inset_z=0.12):
    (x0, y0), (x1, y1) = PROFILE[e], PROFILE[(e + 1) % len(PROFILE)]
    dx, dy = x1 - x0, y1 - y0
    length = math.hypot(dx, dy)
    ux, uy = dx / length, dy / length
    nx, ny = uy, -ux  # outward for a counter-clockwise profile
    a = (x0 + ux * inset_x, y0 + uy * inset_x)
    b = (x1 - ux * inset_x, y1 - uy * inset_x)
    w = HALF_WIDTH - inset_z
    corners = [(a[0], a[1], w), (b[0], b[1], w), (b[0], b[1], -w), (a[0], a[1], -w)]
    return slab(corners, (nx, ny, 0))


def side_window(z_sign):
    # Between the belt line (y 1.02) and the roof, inside the pillars
    y0, y1 = 1.03, 1.36
    quad = [(-0.78, y0), (1.72, y0), (1.42, y1), (-0.2, y1)]
    z = z_sign * HALF_WIDTH
    return slab([(x, y, z) for x, y in quad], (0, 0, z_sign))


def cylinder_shape(x, y, z, radius, half_length):
    return (f"AttributeBegin\n  Translate {x} {y} {z}\n"
            f'  Shape "cylinder" "float radius" {radius} "float zmin" {-half_length} '
            f'"float zmax" {half_length}\nAttributeEnd\n')


def main():
    out = [SCENE, "# The car: a hatchback 4.3 m long, front towards -x, wheels on y = 0\n"]
    out.append("# [hood]\nAttributeBegin\nNamedMaterial \"paint-hood\"\n")
    out.append(mesh(*strip(HOOD_EDGES)) + "AttributeEnd\n")
    cabin = set(range(len(PROFILE))) - HOOD_EDGES - BUMPER_EDGES
    pts, tris = strip(cabin)
    sp, st = sides()
    b = len(pts)
    pts += sp
    tris += [(i + b, j + b, k + b) for i, j, k in st]
    out.append("# [cabin]\nAttributeBegin\nNamedMaterial \"paint\"\n")
    out.append(mesh(pts, tris) + "AttributeEnd\n")
    out.append("# [bumpers]\nAttributeBegin\nNamedMaterial \"bumper\"\n")
    out.append(mesh(*strip(BUMPER_EDGES)) + "AttributeEnd\n")
    out.append("# [glass]\nAttributeBegin\nNamedMaterial \"glass\"\n")
    for part in (edge_glass(WINDSCREEN_EDGE), edge_glass(REAR_WINDOW_EDGE), side_window(1),
                 side_window(-1)):
        out.append(mesh(*part))
    out.append("AttributeEnd\n")
    out.append("# [tyres]\nAttributeBegin\nNamedMaterial \"rubber\"\n")
    for x in (-1.35, 1.35):
        for z in (-0.8, 0.8):
            out.append(cylinder_shape(x, 0.33, z, 0.33, 0.11))
    out.append("AttributeEnd\n")
    out.append("# [hubs]\nAttributeBegin\nNamedMaterial \"hub\"\n")
    for x in (-1.35, 1.35):
        for z in (-0.915, 0.915):
            flip = "  Rotate 180 0 1 0\n" if z < 0 else ""
            out.append(f"AttributeBegin\n  Translate {x} 0.33 {z}\n{flip}"
                       '  Shape "disk" "float radius" 0.2\nAttributeEnd\n')
    out.append("AttributeEnd\n")
    print("".join(out), end="")


if __name__ == "__main__":
    main()
