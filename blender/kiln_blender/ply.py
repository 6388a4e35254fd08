"""Binary little-endian PLY files of triangle meshes, as pbrt-v4's ``plymesh`` reads them.

Vertices carry ``x y z``, optionally ``nx ny nz``, ``u v`` and a float ``temperature``
(kiln's per-vertex temperature in kelvin); faces are ``vertex_indices`` lists of three
32-bit indices. Needs only numpy.
"""

import numpy as np


def write_ply(path, positions, faces, normals=None, uvs=None, temperatures=None,
              comment="written by kiln_blender"):
    """Write a triangle mesh to ``path``.

    positions: (n, 3) floats; faces: (m, 3) vertex indices; normals: (n, 3) or None;
    uvs: (n, 2) or None; temperatures: (n,) or None. Values are stored as float32 and int32.
    """
    positions = np.asarray(positions, dtype=np.float32).reshape(-1, 3)
    faces = np.asarray(faces, dtype=np.int32).reshape(-1, 3)
    n = len(positions)
    fields = [("x", "<f4"), ("y", "<f4"), ("z", "<f4")]
    columns = [positions[:, 0], positions[:, 1], positions[:, 2]]
    if normals is not None:
        normals = np.asarray(normals, dtype=np.float32).reshape(-1, 3)
        fields += [("nx", "<f4"), ("ny", "<f4"), ("nz", "<f4")]
        columns += [normals[:, 0], normals[:, 1], normals[:, 2]]
    if uvs is not None:
        uvs = np.asarray(uvs, dtype=np.float32).reshape(-1, 2)
        fields += [("u", "<f4"), ("v", "<f4")]
        columns += [uvs[:, 0], uvs[:, 1]]
    if temperatures is not None:
        temperatures = np.asarray(temperatures, dtype=np.float32).reshape(-1)
        fields += [("temperature", "<f4")]
        columns += [temperatures]
    vertices = np.empty(n, dtype=fields)
    for (name, _), column in zip(fields, columns):
        vertices[name] = column
    face_records = np.empty(len(faces), dtype=[("count", "u1"), ("indices", "<i4", (3,))])
    face_records["count"] = 3
    face_records["indices"] = faces

    header = ["ply", "format binary_little_endian 1.0", "comment " + comment,
              "element vertex %d" % n]
    header += ["property float %s" % name for name, _ in fields]
    header += ["element face %d" % len(faces), "property list uchar int vertex_indices",
               "end_header"]
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\n").encode("ascii"))
        f.write(vertices.tobytes())
        f.write(face_records.tobytes())


def read_ply_header(path):
    """The header lines of a PLY file (up to and including ``end_header``), as strings."""
    lines = []
    with open(path, "rb") as f:
        while True:
            line = f.readline()
            if not line:
                break
            lines.append(line.decode("ascii", "replace").rstrip("\r\n"))
            if lines[-1] == "end_header":
                break
    return lines
