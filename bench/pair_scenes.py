"""Scene generators for bench/pairbench.py: the kinds of scene real pbrt-v4 scenes are made of.

Every generator writes its scene (and any PLY meshes and PNG textures) into a folder of
bench/out/pairs/ and returns a PairScene. The files are generated, not versioned: a generator
is deterministic (its own random.Random seeded by the scene name), so the same sizes give the
same bytes. Sizes come from a Size: full (the benchmark) or quick (smoke runs).

Only features that kiln and pbrt-v4 render identically are used (docs/pbrt-v4-support.md);
kiln's thermal scenes, with a pbrt-v4 counterpart, are in bench/pair_glow.py.
"""
import math
import os
import random
import struct
import zlib
from dataclasses import dataclass, field
from typing import Dict, List


@dataclass
class Size:
    width: int  # image resolution
    height: int
    spp: int  # samples per pixel of the timed renders
    ref_spp: int  # samples per pixel of the reference
    scale: float  # 1 = full geometry counts; quick runs use less


@dataclass
class PairScene:
    name: str
    kind: str  # what real scenes it stands for (the table's second column)
    kiln_file: str  # the file kiln renders
    pbrt_file: str  # the file pbrt-v4 renders (the same file unless kiln uses its thermal syntax)
    spp: int
    ref_spp: int
    equivalent: bool = True  # False: pbrt-v4 cannot express the same radiance; compare time only
    note: str = ""
    kiln_flags: List[str] = field(default_factory=list)


def header(size: Size, look: str, fov: float, integrator: str = "path", maxdepth: int = 5,
           film: str = "") -> str:
    return (f"LookAt {look}\nCamera \"perspective\" \"float fov\" {fov}\n"
            f"Sampler \"zsobol\" \"integer pixelsamples\" {size.spp}\n"
            f"Integrator \"{integrator}\" \"integer maxdepth\" {maxdepth}\n"
            f"Film \"rgb\" \"integer xresolution\" {size.width} \"integer yresolution\" "
            f"{size.height} {film}\n    \"string filename\" \"out.exr\"\n"
            "PixelFilter \"gaussian\"\n\nWorldBegin\n")


def fmt(values) -> str:
    return " ".join(f"{v:.5g}" for v in values)


def box(x0, y0, z0, x1, y1, z1) -> str:
    """A closed box as a trianglemesh, normals outward (pbrt-v4: n = (p0 - p2) x (p1 - p2))."""
    P = [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1),
         (x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)]
    return ('Shape "trianglemesh" "integer indices" [0 1 2 0 2 3 4 6 5 4 7 6 0 5 1 0 4 5 '
            '2 7 3 2 6 7 1 6 2 1 5 6 0 7 4 0 3 7]\n'
            f'    "point3 P" [{fmt(c for p in P for c in p)}]\n')


def write(folder: str, name: str, text: str) -> str:
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, name)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def write_png(path: str, width: int, height: int, pixel) -> None:
    """An 8-bit RGB PNG; pixel(x, y) -> (r, g, b) in 0..255 (zlib and struct only)."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter: none
        for x in range(width):
            rows.extend(bytes(pixel(x, y)))

    def chunk(tag: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(bytes(rows), 6)))
        f.write(chunk(b"IEND", b""))


def write_ply(path: str, points: List[tuple], uvs: List[tuple], triangles: List[tuple]) -> None:
    """A binary little-endian PLY with x y z u v per vertex and triangles."""
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "property float u\nproperty float v\n"
                 f"element face {len(triangles)}\nproperty list uchar int vertex_indices\n"
                 "end_header\n").encode())
        buf = bytearray()
        for p, uv in zip(points, uvs):
            buf += struct.pack("<5f", *p, *uv)
        for t in triangles:
            buf += struct.pack("<B3i", 3, *t)
        f.write(buf)


def textured_mesh(out: str, size: Size) -> PairScene:
    """A height-field terrain of n x n quads (2 n^2 triangles, 320k at full size) in four PLY
    pieces, each with its own procedural 512 x 512 PNG texture (imagemap, pbrt-v4's default
    bilinear filter), under a sun and a sky."""
    folder = os.path.join(out, "textured-mesh")
    n = max(8, int(400 * math.sqrt(size.scale)))
    tex = 512 if size.scale >= 1 else 64
    patterns = [
        lambda x, y: (200, 60 + 120 * (((x // 32) + (y // 32)) % 2), 40),
        lambda x, y: (int(127 + 120 * math.sin(x * 0.09)), 150,
                      int(127 + 120 * math.cos(y * 0.05))),
        lambda x, y: ((x * 7 + y * 3) % 256, (x * y) % 256, 180),
        lambda x, y: (90, y // 2, x // 2),
    ]
    os.makedirs(folder, exist_ok=True)
    text = header(size, "0 9 -14  0 0 0  0 1 0", 45)
    text += ('LightSource "distant" "point3 from" [2 5 -3] "point3 to" [0 0 0] '
             '"blackbody L" 5500 "float scale" 2.5\n'
             'LightSource "infinite" "rgb L" [0.25 0.3 0.4]\n')
    half = n // 2

    def height(i, j):
        x, z = i / n, j / n
        return 1.2 * math.sin(6 * x) * math.cos(5 * z) + 0.4 * math.sin(23 * x + 17 * z)

    for piece, (i0, j0) in enumerate([(0, 0), (half, 0), (0, half), (half, half)]):
        png = f"tex{piece}.png"
        write_png(os.path.join(folder, png), tex, tex,
                  lambda x, y, f=patterns[piece]: f(x * 512 // tex, y * 512 // tex))
        points, uvs, tris = [], [], []
        m = half + 1
        for j in range(m):
            for i in range(m):
                gi, gj = i0 + i, j0 + j
                points.append((16 * gi / n - 8, height(gi, gj), 16 * gj / n - 8))
                uvs.append((4 * i / half, 4 * j / half))
        for j in range(half):
            for i in range(half):
                a = j * m + i
                tris += [(a, a + 1, a + m + 1), (a, a + m + 1, a + m)]
        write_ply(os.path.join(folder, f"piece{piece}.ply"), points, uvs, tris)
        text += (f'Texture "t{piece}" "spectrum" "imagemap" "string filename" "{png}"\n'
                 f'Material "diffuse" "texture reflectance" "t{piece}"\n'
                 f'Shape "plymesh" "string filename" "piece{piece}.ply"\n')
    path = write(folder, "scene.pbrt", text)
    return PairScene("textured-mesh", f"{2 * n * n} triangles, 4 image textures", path, path,
                     size.spp, size.ref_spp)


def icosphere(levels: int):
    t = (1 + math.sqrt(5)) / 2
    pts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
           (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    pts = [tuple(c / math.sqrt(1 + t * t) for c in p) for p in pts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        cache: Dict[tuple, int] = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                p = [(pts[a][k] + pts[b][k]) / 2 for k in range(3)]
                r = math.sqrt(sum(c * c for c in p))
                pts.append(tuple(c / r for c in p))
                cache[key] = len(pts) - 1
            return cache[key]

        new = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    return pts, faces


def instances(out: str, size: Size) -> PairScene:
    """A lumpy rock (an icosphere of 1280 triangles) instanced 5000 times over a plane."""
    folder = os.path.join(out, "instances")
    rng = random.Random("instances")
    count = max(50, int(5000 * size.scale))
    pts, faces = icosphere(3)
    bumped = []
    for p in pts:
        r = 1 + 0.15 * math.sin(7 * p[0]) * math.sin(5 * p[1] + 2 * p[2])
        bumped.append(tuple(r * c for c in p))
    text = header(size, "0 6 -18  0 0 4  0 1 0", 40)
    text += ('LightSource "distant" "point3 from" [-3 6 -2] "point3 to" [0 0 0] '
             '"blackbody L" 5000 "float scale" 2\n'
             'LightSource "infinite" "rgb L" [0.2 0.25 0.35]\n'
             'Material "diffuse" "rgb reflectance" [0.5 0.5 0.45]\n'
             'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
             '    "point3 P" [-60 0 -20  60 0 -20  60 0 100  -60 0 100]\n'
             'ObjectBegin "rock"\n'
             'Material "conductor" "spectrum eta" "metal-Cu-eta" "spectrum k" "metal-Cu-k" '
             '"float roughness" 0.3\n'
             f'Shape "trianglemesh" "point3 P" [{fmt(c for p in bumped for c in p)}]\n'
             f'    "integer indices" [{" ".join(str(i) for f in faces for i in f)}]\n'
             'ObjectEnd\n')
    side = int(math.ceil(math.sqrt(count)))
    for k in range(count):
        x = -30 + 60 * ((k % side) + rng.random()) / side
        z = -5 + 90 * ((k // side) + rng.random()) / side
        s = 0.2 + 0.5 * rng.random()
        text += (f"AttributeBegin Translate {x:.3f} {s * 0.8:.3f} {z:.3f} "
                 f"Rotate {rng.uniform(0, 360):.1f} {rng.random():.2f} 1 {rng.random():.2f} "
                 f"Scale {s:.3f} {s:.3f} {s:.3f} ObjectInstance \"rock\" AttributeEnd\n")
    path = write(folder, "scene.pbrt", text)
    return PairScene("instances", f"{count} instances of {len(faces)} triangles", path, path,
                     size.spp, size.ref_spp)


def curves(out: str, size: Size) -> PairScene:
    """Hair: 30000 flat cubic Bezier curves with pbrt-v4's hair material."""
    folder = os.path.join(out, "curves")
    rng = random.Random("curves")
    count = max(200, int(30000 * size.scale))
    text = header(size, "0 0.6 -3.2  0 0.4 0  0 1 0", 35, maxdepth=8)
    text += ('LightSource "distant" "point3 from" [1 3 -2] "point3 to" [0 0 0] '
             '"blackbody L" 4500 "float scale" 3\n'
             'LightSource "infinite" "rgb L" [0.3 0.3 0.35]\n'
             'Material "diffuse" "rgb reflectance" [0.3 0.3 0.3]\n'
             'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
             '    "point3 P" [-5 -0.5 -5  5 -0.5 -5  5 -0.5 5  -5 -0.5 5]\n'
             'Material "hair" "float eumelanin" 1.3 "float pheomelanin" 0.4\n')
    for _ in range(count):
        u, v = rng.uniform(-1, 1), rng.uniform(0, 1)
        x0, z0 = 0.8 * u, 0.4 * v
        p = [(x0, -0.5 + 1.6 * k / 3 + 0.02 * k * rng.uniform(-1, 1),
              z0 + 0.15 * math.sin(3 * x0 + k) + 0.05 * k * rng.uniform(-1, 1))
             for k in range(4)]
        p = [(q[0] + 0.1 * k * u * rng.random(), q[1], q[2]) for k, q in enumerate(p)]
        text += (f'Shape "curve" "point3 P" [{fmt(c for q in p for c in q)}] '
                 f'"float width0" 0.004 "float width1" 0.001\n')
    path = write(folder, "scene.pbrt", text)
    return PairScene("curves", f"{count} hair curves", path, path, size.spp, size.ref_spp)


def many_lights(out: str, size: Size) -> PairScene:
    """300 point lights (0.5 above the tallest box or more) and 100 small quad area lights,
    blackbody 2000-6500 K, over diffuse and rough-metal boxes (the light BVH matters)."""
    folder = os.path.join(out, "many-lights")
    rng = random.Random("many-lights")
    n_point, n_area = max(20, int(300 * size.scale)), max(8, int(100 * size.scale))
    text = header(size, "0 7 -16  0 0 0  0 1 0", 50)
    text += ('Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]\n'
             'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
             '    "point3 P" [-20 0 -20  20 0 -20  20 0 20  -20 0 20]\n')
    for k in range(40):
        x, z, h = rng.uniform(-12, 12), rng.uniform(-6, 14), rng.uniform(0.5, 3)
        mat = ('"diffuse" "rgb reflectance" [0.5 0.4 0.3]' if k % 2 else
               '"conductor" "spectrum eta" "metal-Al-eta" "spectrum k" "metal-Al-k" '
               '"float roughness" 0.2')
        text += (f"AttributeBegin Translate {x:.2f} {h / 2:.2f} {z:.2f} Material {mat}\n"
                 + box(-.5, -h / 2, -.5, .5, h / 2, .5) + 'AttributeEnd\n')
    for _ in range(n_point):
        p = (rng.uniform(-14, 14), rng.uniform(3.5, 6), rng.uniform(-8, 16))
        text += (f'LightSource "point" "point3 from" [{fmt(p)}] "blackbody I" '
                 f'{rng.randint(2000, 6500)} "float scale" {rng.uniform(0.05, 0.5):.3f}\n')
    for _ in range(n_area):
        x, y, z = rng.uniform(-14, 14), rng.uniform(3, 6), rng.uniform(-8, 16)
        text += (f'AttributeBegin AreaLightSource "diffuse" "blackbody L" '
                 f'{rng.randint(2000, 6500)} "float scale" {rng.uniform(2, 10):.2f}\n'
                 f'Translate {x:.2f} {y:.2f} {z:.2f}\n'
                 'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
                 '    "point3 P" [-.2 0 -.2  .2 0 -.2  .2 0 .2  -.2 0 .2]\nAttributeEnd\n')
    path = write(folder, "scene.pbrt", text)
    return PairScene("many-lights", f"{n_point} point + {n_area} area lights", path, path,
                     size.spp, size.ref_spp)


ROOM = ('LightSource "infinite" "rgb L" [0.05 0.05 0.06]\n'
        'Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]\n'
        'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
        '    "point3 P" [-6 0 -6  6 0 -6  6 0 6  -6 0 6]\n'
        'AttributeBegin AreaLightSource "diffuse" "blackbody L" 4000 "float scale" 12\n'
        '  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
        '    "point3 P" [-1 4 -1  1 4 -1  1 4 1  -1 4 1]\nAttributeEnd\n')


def medium_homogeneous(out: str, size: Size) -> PairScene:
    """A scattering ball of homogeneous medium (interface boundary) over a floor."""
    folder = os.path.join(out, "medium-homogeneous")
    text = header(size, "0 2 -6  0 1 0  0 1 0", 40, "volpath", 20) + ROOM
    text += ('MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [0.1 0.2 0.4] '
             '"rgb sigma_s" [2 2 2] "float g" 0.5\n'
             'AttributeBegin MediumInterface "fog" "" Material "interface"\n'
             '  Translate 0 1.1 0 Shape "sphere" "float radius" 1\nAttributeEnd\n')
    path = write(folder, "scene.pbrt", text)
    return PairScene("medium-homogeneous", "scattering ball, volpath", path, path,
                     size.spp, size.ref_spp)


def density_grid(n: int, seed: str) -> List[float]:
    """A cloud of soft blobs on an n^3 grid, zero on the grid's faces (kiln ends the medium at
    its box; pbrt-v4's interpolation reaches half a voxel beyond it)."""
    rng = random.Random(seed)
    blobs = [(rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7),
              rng.uniform(0.08, 0.2)) for _ in range(12)]
    d = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                if 0 in (i, j, k) or n - 1 in (i, j, k):
                    d.append(0.0)
                    continue
                x, y, z = (i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n
                v = sum(math.exp(-((x - a) ** 2 + (y - b) ** 2 + (z - c) ** 2) / (r * r))
                        for a, b, c, r in blobs)
                d.append(round(min(v, 1.5), 4))
    return d


def medium_grid(out: str, size: Size) -> PairScene:
    """A heterogeneous cloud: a 48^3 uniformgrid density (procedural blobs)."""
    folder = os.path.join(out, "medium-grid")
    n = 48 if size.scale >= 1 else 12
    text = header(size, "0 2 -6  0 1 0  0 1 0", 40, "volpath", 20) + ROOM
    text += ('MakeNamedMedium "cloud" "string type" "uniformgrid" "rgb sigma_a" [0.5 0.5 0.5] '
             '"rgb sigma_s" [6 6 6] "float g" 0.3\n'
             f'    "integer nx" {n} "integer ny" {n} "integer nz" {n} '
             '"point3 p0" [-1.2 0.02 -1.2] "point3 p1" [1.2 2.42 1.2]\n'
             f'    "float density" [{fmt(density_grid(n, "cloud"))}]\n'
             'AttributeBegin MediumInterface "cloud" "" Material "interface"\n'
             + box(-1.2, 0.02, -1.2, 1.2, 2.42, 1.2) + 'AttributeEnd\n')
    path = write(folder, "scene.pbrt", text)
    return PairScene("medium-grid", f"{n}^3 density grid, volpath", path, path,
                     size.spp, size.ref_spp)


def coated_glass(out: str, size: Size) -> PairScene:
    """Smooth-coated diffuse and coated gold, smooth and rough glass spheres on a checker floor.
    Coats are smooth: kiln's MIS inside rough coats differs from pbrt-v4's (--layered-mis)."""
    folder = os.path.join(out, "coated-glass")
    text = header(size, "0 2.5 -7  0 0.8 0  0 1 0", 40, maxdepth=10)
    text += ('LightSource "infinite" "rgb L" [0.3 0.32 0.35]\n'
             'AttributeBegin AreaLightSource "diffuse" "blackbody L" 5000 "float scale" 8\n'
             '  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]\n'
             '    "point3 P" [-1.5 5 -2  1.5 5 -2  1.5 5 1  -1.5 5 1]\nAttributeEnd\n'
             'Texture "check" "spectrum" "checkerboard" "float uscale" 16 "float vscale" 16 '
             '"rgb tex1" [0.8 0.8 0.8] "rgb tex2" [0.1 0.1 0.1]\n'
             'Material "diffuse" "texture reflectance" "check"\n'
             'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point2 uv" [0 0 1 0 1 1 0 1]\n'
             '    "point3 P" [-8 0 -8  8 0 -8  8 0 8  -8 0 8]\n')
    spheres = [
        (-2.4, '"coateddiffuse" "rgb reflectance" [0.7 0.1 0.1]'),
        (-0.8, '"coatedconductor" "spectrum conductor.eta" "metal-Au-eta" '
               '"spectrum conductor.k" "metal-Au-k" "float conductor.roughness" 0'),
        (0.8, '"dielectric" "float eta" 1.5'),
        (2.4, '"dielectric" "float eta" 1.5 "float roughness" 0.15'),
    ]
    for x, mat in spheres:
        text += (f"AttributeBegin Material {mat}\n  Translate {x} 0.7 0 "
                 'Shape "sphere" "float radius" 0.7\nAttributeEnd\n')
    path = write(folder, "scene.pbrt", text)
    return PairScene("coated-glass", "coated diffuse/gold, smooth/rough glass", path, path,
                     size.spp, size.ref_spp)


GENERATORS = [textured_mesh, instances, curves, many_lights, medium_homogeneous, medium_grid,
              coated_glass]
