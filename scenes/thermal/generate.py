#!/usr/bin/env python3
"""Writes the meshes and images of the temperature-field scenes in this folder.

lava.ply    a 96 x 96 grid (18,432 triangles) of slightly bumpy ground, 10 m x 10 m, with a
            per-vertex "temperature" property: a cool crust (~600-800 K) broken by narrow hot
            cracks (~1300-1450 K), from a seeded value-noise field (deterministic).
heat.png    an 8-bit grey heat map (0 = tmin, 255 = tmax) with a hot ring and a hot spot, for
            heat-map.pbrt.
Usage: generate.py (no arguments; writes next to this script)
"""
import math
import os
import random
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def value_noise(seed, n):
    rng = random.Random(seed)
    grid = [[rng.random() for _ in range(n + 1)] for _ in range(n + 1)]

    def f(x, y):  # x, y in [0, 1]
        gx, gy = x * n, y * n
        i, j = min(int(gx), n - 1), min(int(gy), n - 1)
        fx, fy = gx - i, gy - j
        sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
        a = grid[j][i] + sx * (grid[j][i + 1] - grid[j][i])
        b = grid[j + 1][i] + sx * (grid[j + 1][i + 1] - grid[j + 1][i])
        return a + sy * (b - a)
    return f


def lava():
    n, size = 96, 10.0
    base, detail = value_noise(7, 6), value_noise(11, 24)
    verts = []
    for j in range(n + 1):
        for i in range(n + 1):
            u, v = i / n, j / n
            # Cracks where the large-scale noise crosses 0.5: a narrow hot band.
            d = abs(base(u, v) - 0.5) + 0.08 * (detail(u, v) - 0.5)
            crack = math.exp(-(d / 0.035) ** 2)
            t = 620 + 180 * detail(u, v) + 700 * crack
            h = 0.12 * (1 - crack) * detail(u, v)  # crust stands proud of the cracks
            verts.append(((u - 0.5) * size, h, (v - 0.5) * size, u, v, t))
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c, d = a + 1, a + n + 2, a + n + 1
            faces += [(a, c, b), (a, d, c)]
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        "comment kiln scenes/thermal/generate.py: lava field, temperature in K\n"
        f"element vertex {len(verts)}\n"
        "property float x\nproperty float y\nproperty float z\n"
        "property float u\nproperty float v\nproperty float temperature\n"
        f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    with open(os.path.join(HERE, "lava.ply"), "wb") as f:
        f.write(header.encode())
        for v in verts:
            f.write(struct.pack("<6f", *v))
        for tri in faces:
            f.write(struct.pack("<B3i", 3, *tri))


def write_png_gray(path, width, height, pixels):
    raw = b"".join(b"\x00" + bytes(pixels[y * width:(y + 1) * width]) for y in range(height))

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data +
                struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0,
                                                              0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def heat_map():
    w = h = 128
    px = []
    for y in range(h):
        for x in range(w):
            u, v = (x + 0.5) / w - 0.5, (y + 0.5) / h - 0.5
            r = math.hypot(u, v)
            ring = math.exp(-((r - 0.3) / 0.04) ** 2)
            spot = math.exp(-((u - 0.1) ** 2 + (v + 0.05) ** 2) / 0.004)
            px.append(int(round(255 * min(1.0, 0.15 + 0.85 * max(ring, spot)))))
    write_png_gray(os.path.join(HERE, "heat.png"), w, h, px)


if __name__ == "__main__":
    lava()
    heat_map()
