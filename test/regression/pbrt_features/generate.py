#!/usr/bin/env python3
"""Writes the binary and compressed inputs of the pbrt-v4 feature scenes in this folder:
gzip-geometry.pbrt (a gzip-compressed include, named without .gz: detected by content),
gzip-mesh.ply.gz (a gzip-compressed binary PLY icosphere), displacement-grid.ply (an ASCII
PLY grid with uv), normalmap.pfm (a tangent-space normal map of ripples), checker.tga (an 8-bit
uncompressed TGA, rows bottom to top as TGA files usually store them), alpha.png (an 8-bit RGBA
PNG whose colours are not premultiplied), sky.pfm (a 16x16 equal-area environment map),
goniometric.pfm (a 32x32 equal-area intensity map, R, G, B) and slide.png (a 24x12 8-bit RGB
slide for the projection light).
Deterministic: re-running it rewrites the same bytes."""
import gzip
import math
import struct
import zlib


def icosphere():
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
         (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return v, f


def write_gzip(name, data):
    # mtime 0 and no file name in the header: the same bytes every time
    with open(name, "wb") as raw:
        with gzip.GzipFile(filename="", mode="wb", fileobj=raw, mtime=0) as out:
            out.write(data)


def write_pfm(name, w, h, data):
    # Little-endian RGB floats, rows bottom to top
    with open(name, "wb") as out:
        out.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        out.write(struct.pack("<%df" % len(data), *data))


def main():
    v, f = icosphere()
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
              "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
              "property float nz\nelement face %d\nproperty list uchar int vertex_indices\n"
              "end_header\n" % (len(v), len(f))).encode()
    body = b"".join(struct.pack("<6f", *p, *p) for p in v)
    body += b"".join(struct.pack("<B3i", 3, *tri) for tri in f)
    write_gzip("gzip-mesh.ply.gz", header + body)

    include = ('Material "coateddiffuse" "rgb reflectance" [0.7 0.2 0.1] "float roughness" 0.1\n'
               'AttributeBegin\n  Translate 0 0.6 0\n  Scale 0.6 0.6 0.6\n'
               '  Shape "plymesh" "string filename" "gzip-mesh.ply.gz"\nAttributeEnd\n'
               'Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]\n'
               'Shape "bilinearmesh" "point3 P" [-3 0 -3 3 0 -3 -3 0 3 3 0 3]\n')
    write_gzip("gzip-geometry.pbrt", include.encode())

    n = 9
    lines = ["ply", "format ascii 1.0", "element vertex %d" % (n * n), "property float x",
             "property float y", "property float z", "property float u", "property float v",
             "element face %d" % ((n - 1) * (n - 1)), "property list uchar int vertex_indices",
             "end_header"]
    for j in range(n):
        for i in range(n):
            u, w = i / (n - 1), j / (n - 1)
            lines.append("%g 0 %g %g %g" % (2 * u - 1, 1 - 2 * w, u, w))
    for j in range(n - 1):
        for i in range(n - 1):
            a = j * n + i
            lines.append("4 %d %d %d %d" % (a, a + 1, a + n, a + n + 1))
    open("displacement-grid.ply", "w").write("\n".join(lines) + "\n")

    # Ripples: the normal of the height field 0.05 sin(2 pi 4 r) about the centre
    w = h = 32
    data = []
    for y in range(h):  # PFM rows run bottom to top
        for x in range(w):
            u, v2 = (x + 0.5) / w - 0.5, (y + 0.5) / h - 0.5
            r = math.hypot(u, v2) + 1e-9
            dh = 0.05 * 2 * math.pi * 4 * math.cos(2 * math.pi * 4 * r)
            nx, ny, nz = -dh * u / r, -dh * v2 / r, 1.0
            l = math.sqrt(nx * nx + ny * ny + nz * nz)
            data += [0.5 + 0.5 * nx / l, 0.5 + 0.5 * ny / l, 0.5 + 0.5 * nz / l]
    write_pfm("normalmap.pfm", w, h, data)

    # An 8 x 8 checker of two colours with a gradient, 24-bit BGR, bottom-left origin
    w = h = 8
    tga = bytearray(struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, w, h, 24, 0))
    for y in range(h):
        for x in range(w):
            r, g, b = (200, 90 + 12 * x, 40) if (x // 2 + y // 2) % 2 else (60, 140, 180 + 8 * y)
            tga += bytes((b, g, r))
    open("checker.tga", "wb").write(bytes(tga))

    # RGBA: colour (230, 150, 60) everywhere, alpha 255 in the left half and 64 in the right
    rows = b""
    for y in range(4):
        rows += b"\0" + b"".join(bytes((230, 150, 60, 255 if x < 2 else 64)) for x in range(4))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 4, 4, 8, 6, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
    open("alpha.png", "wb").write(png)

    # Slide: red at the top left, green at the top right, blue at the bottom, a checker of
    # 4-pixel squares over it, and one white pixel at the top left corner (RGB, no alpha)
    w, h = 24, 12
    rows = b""
    for y in range(h):
        row = b"\0"
        for x in range(w):
            u, v2 = (x + 0.5) / w, (y + 0.5) / h
            c = 1.0 if (x // 4 + y // 4) % 2 == 0 else 0.25
            rgb = (c * (1 - u) * (1 - v2), c * u * (1 - v2), c * v2)
            if x == 0 and y == 0:
                rgb = (1, 1, 1)
            row += bytes(int(round(255 * k)) for k in rgb)
        rows += row
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
    open("slide.png", "wb").write(png)

    # Sky: bright and warm towards +z of the map, blue towards -z, a brighter +x half
    w = h = 16
    data = []
    for y in range(h):
        for x in range(w):
            u, v2 = (x + 0.5) / w, (y + 0.5) / h
            dx, dy = 2 * u - 1, 2 * v2 - 1
            z = 1 - (abs(dx) + abs(dy))  # the octahedral map's height (sign of z)
            data += [0.3 + 0.9 * max(z, 0) + 0.3 * (dx > 0), 0.4 + 0.5 * max(z, 0),
                     0.8 + 0.2 * max(-z, 0)]
    write_pfm("sky.pfm", w, h, data)

    # Goniometric map: bright towards +z of the map (the light's +y), dark towards -z, a
    # checker of 4-pixel squares, and the channels differ (the light uses their mean)
    w = h = 32
    data = []
    for y in range(h):
        for x in range(w):
            u, v2 = (x + 0.5) / w, (y + 0.5) / h
            dx, dy = 2 * u - 1, 2 * v2 - 1
            z = 1 - (abs(dx) + abs(dy))
            c = 1.0 if (x // 4 + y // 4) % 2 == 0 else 0.3
            base = c * (0.2 + 1.5 * max(z, 0) + 0.4 * (dx > 0))
            data += [1.2 * base, base, 0.8 * base]
    write_pfm("goniometric.pfm", w, h, data)


if __name__ == "__main__":
    main()
