"""Scene generators for bench/scale_study.py: large meshes, instances and many hot emitters.

Every generator writes a scene file (and its binary PLY meshes) into a folder under
bench/out/scale/ and returns the scene's path. Generation is deterministic and cached: a file
that exists with the expected name is not written again. Python's standard library only.
"""
import math
import os
import struct


def header(width, height, spp, look, fov, maxdepth=5):
    return (f"LookAt {look}\nCamera \"perspective\" \"float fov\" {fov}\n"
            f"Sampler \"zsobol\" \"integer pixelsamples\" {spp}\n"
            f"Integrator \"path\" \"integer maxdepth\" {maxdepth}\n"
            f"Film \"rgb\" \"integer xresolution\" {width} \"integer yresolution\" {height}\n"
            "    \"string filename\" \"out.exr\"\n\nWorldBegin\n")


def grid_shape(triangles):
    """(a, b) quads with 2 a b = triangles and a <= b as close to square as divisors allow."""
    if triangles % 2:
        raise ValueError("a grid has an even number of triangles")
    half = triangles // 2
    a = int(math.isqrt(half))
    while half % a:
        a -= 1
    return a, half // a


def write_grid_ply(path, triangles, amplitude=0.05, waves=7.0):
    """A wavy height field over [0, 1]^2 of `triangles` triangles, binary little-endian PLY.

    Vertices (a + 1) x (b + 1), z = amplitude sin(waves 2 pi x) sin(waves 2 pi y) (separable,
    so each row is one multiplication per vertex). Faces are written row by row: row r's bytes
    are row 0's plus r (a + 1) added to every index, done as one big-integer addition (the
    fields never carry into each other), so 5e7 triangles take seconds in pure Python."""
    if os.path.exists(path):
        return path
    a, b = grid_shape(triangles)
    nx, ny = a + 1, b + 1
    tmp = path + ".part"
    with open(tmp, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {nx * ny}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 f"element face {2 * a * b}\nproperty list uchar int vertex_indices\n"
                 "end_header\n").encode())
        xs = [i / a for i in range(nx)]
        wave_x = [amplitude * math.sin(waves * 2 * math.pi * x) for x in xs]
        import array
        row = array.array("f", bytes(12 * nx))
        row[0::3] = array.array("f", xs)
        for j in range(ny):
            y = j / b
            s = math.sin(waves * 2 * math.pi * y)
            row[1::3] = array.array("f", [y]) * nx
            row[2::3] = array.array("f", map(s.__mul__, wave_x))
            f.write(row.tobytes())
        face = struct.Struct("<Biii")
        row0 = bytearray()
        delta = bytearray()
        one = face.pack(0, 1, 1, 1)
        for i in range(a):  # quad (i, row 0): v0 v1 v2 and v0 v2 v3, counter-clockwise
            v0, v1, v2, v3 = i, i + 1, i + 1 + nx, i + nx
            row0 += face.pack(3, v0, v1, v2) + face.pack(3, v0, v2, v3)
            delta += one + one
        size = len(row0)
        base = int.from_bytes(row0, "little")
        step = int.from_bytes(delta, "little") * nx
        value = base
        for _ in range(b):
            f.write(value.to_bytes(size, "little"))
            value += step
    os.replace(tmp, path)
    return path


def mesh_scene(folder, triangles, width, height, spp):
    """One mesh of `triangles` triangles (a diffuse height field, 4 x 4 units) under a sky."""
    os.makedirs(folder, exist_ok=True)
    ply = write_grid_ply(os.path.join(folder, f"grid-{triangles}.ply"), triangles)
    path = os.path.join(folder, f"mesh-{triangles}.pbrt")
    with open(path, "w") as f:
        f.write(header(width, height, spp, "2 -0.5 2.2  2 2.2 0  0 0 1", 70))
        f.write('LightSource "infinite" "rgb L" [0.8 0.85 1]\n'
                'Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]\n'
                'AttributeBegin\nScale 4 4 4\n'
                f'Shape "plymesh" "string filename" "{os.path.basename(ply)}"\nAttributeEnd\n')
    return path


def instance_scene(folder, instances, object_triangles, width, height, spp):
    """`instances` copies of one height field of `object_triangles` triangles (ObjectInstance),
    on a cubic lattice filling the view, each copy turned differently."""
    os.makedirs(folder, exist_ok=True)
    ply = write_grid_ply(os.path.join(folder, f"grid-{object_triangles}.ply"), object_triangles)
    side = max(1, round(instances ** (1.0 / 3.0)))
    while side ** 3 < instances:
        side += 1
    cell = 4.0 / side
    path = os.path.join(folder, f"instances-{instances}x{object_triangles}.pbrt")
    with open(path, "w") as f:
        f.write(header(width, height, spp, "7 -5 6  2 2 2  0 0 1", 40))
        f.write('LightSource "infinite" "rgb L" [0.8 0.85 1]\n'
                'Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]\n'
                f'ObjectBegin "patch"\nShape "plymesh" "string filename" '
                f'"{os.path.basename(ply)}"\nObjectEnd\n')
        for k in range(instances):
            i, j, l = k % side, (k // side) % side, k // (side * side)
            angle = (k * 137.5) % 360.0
            f.write(f"AttributeBegin\nTranslate {i * cell:.6g} {j * cell:.6g} {l * cell:.6g}\n"
                    f"Scale {0.8 * cell:.6g} {0.8 * cell:.6g} {0.8 * cell:.6g}\n"
                    f"Rotate {angle:.4g} 1 1 1\nObjectInstance \"patch\"\nAttributeEnd\n")
    return path


def floor():
    return ('Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]\n'
            'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] '
            '"point3 P" [-1 -1 0  11 -1 0  11 11 0  -1 11 0]\n')


def sphere_emitter_scene(folder, emitters, width, height, spp):
    """`emitters` small hot spheres (800-1600 K) on a square lattice 10 x 10 units above a
    diffuse floor; no other light."""
    os.makedirs(folder, exist_ok=True)
    side = math.isqrt(emitters)
    if side * side < emitters:
        side += 1
    spacing = 10.0 / side
    path = os.path.join(folder, f"spheres-{emitters}.pbrt")
    with open(path, "w") as f:
        f.write(header(width, height, spp, "5 -6 8  5 5 0  0 0 1", 50))
        f.write(floor())
        f.write('Material "diffuse" "rgb reflectance" [0.3 0.3 0.3]\n')
        lines = []
        for k in range(emitters):
            i, j = k % side, k // side
            T = 800 + (k * 7919) % 800
            lines.append(f"AttributeBegin\nTranslate {(i + 0.5) * spacing:.6g} "
                         f"{(j + 0.5) * spacing:.6g} {spacing:.6g}\nShape \"sphere\" "
                         f"\"float radius\" {0.25 * spacing:.6g} \"float temperature\" {T}\n"
                         "AttributeEnd\n")
            if len(lines) == 10000:
                f.write("".join(lines))
                lines = []
        f.write("".join(lines))
    return path


def hot_mesh_scene(folder, triangles, width, height, spp):
    """A height field of `triangles` triangles at 1400 K ("float temperature" on the shape:
    one light per triangle) hanging 1 unit above a diffuse floor, seen from above."""
    os.makedirs(folder, exist_ok=True)
    ply = write_grid_ply(os.path.join(folder, f"grid-{triangles}.ply"), triangles)
    path = os.path.join(folder, f"hotmesh-{triangles}.pbrt")
    with open(path, "w") as f:
        f.write(header(width, height, spp, "5 -6 8  5 5 0  0 0 1", 50))
        f.write(floor())
        f.write('AttributeBegin\nTranslate 2 2 1\nScale 6 6 6\n'
                'Material "diffuse" "rgb reflectance" [0.3 0.3 0.3]\n'
                f'Shape "plymesh" "string filename" "{os.path.basename(ply)}" '
                '"float temperature" 1400\nAttributeEnd\n')
    return path
