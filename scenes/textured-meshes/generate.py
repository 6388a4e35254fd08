#!/usr/bin/env python3
"""Writes the PLY meshes of the textured-meshes scene.

torus.ply: binary little-endian triangles with normals and uv.
ground.ply: ASCII quads (pbrt-v4 turns PLY quads into bilinear patches) with uv.
"""
import math
import struct


def torus(path, R=1.0, r=0.38, nu=64, nv=32):
    verts, faces = [], []
    for i in range(nu + 1):
        u = 2 * math.pi * i / nu
        for j in range(nv + 1):
            v = 2 * math.pi * j / nv
            cx, cz = math.cos(u), math.sin(u)
            n = (math.cos(v) * cx, math.sin(v), math.cos(v) * cz)
            p = (R * cx + r * n[0], r * n[1], R * cz + r * n[2])
            verts.append((p, n, (i / nu * 4, j / nv)))
    for i in range(nu):
        for j in range(nv):
            a = i * (nv + 1) + j
            b = (i + 1) * (nv + 1) + j
            faces += [(a, a + 1, b + 1), (a, b + 1, b)]
    with open(path, "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\ncomment kiln textured-meshes torus\n")
        f.write(b"element vertex %d\n" % len(verts))
        for name in ["x", "y", "z", "nx", "ny", "nz", "u", "v"]:
            f.write(b"property float %s\n" % name.encode())
        f.write(b"element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                % len(faces))
        for p, n, uv in verts:
            f.write(struct.pack("<8f", *p, *n, *uv))
        for a, b, c in faces:
            f.write(struct.pack("<B3i", 3, a, b, c))


def ground(path, n=4, size=6.0):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment kiln textured-meshes ground (quads)\n")
        f.write(f"element vertex {(n + 1) ** 2}\n")
        f.write("property float x\nproperty float y\nproperty float z\n")
        f.write("property float u\nproperty float v\n")
        f.write(f"element face {n * n}\nproperty list uchar int vertex_indices\nend_header\n")
        for i in range(n + 1):
            for j in range(n + 1):
                x = -size + 2 * size * j / n
                z = -size + 2 * size * i / n
                f.write(f"{x:g} 0 {z:g} {j / n * 3:g} {i / n * 3:g}\n")
        for i in range(n):
            for j in range(n):
                a = i * (n + 1) + j
                f.write(f"4 {a} {a + 1} {a + n + 2} {a + n + 1}\n")


if __name__ == "__main__":
    torus("torus.ply")
    ground("ground.ply")
