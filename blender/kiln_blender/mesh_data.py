"""Triangle arrays of a Blender mesh, one set per material slot, ready for a PLY file.

Vertices are split where the faces meeting at a Blender vertex need different normals (flat
faces, sharp edges, custom normals) or UVs: each output vertex is a distinct combination of
Blender vertex, corner normal and UV (and temperature). Corner normals come from
``Mesh.corner_normals`` (Blender 4.1 and later) or, before, ``calc_normals_split`` and the
loops' ``normal``; both follow smooth/flat shading, auto smooth and custom normals.
"""

import numpy as np


class TriangleArrays:
    """One material slot's triangles: ``positions`` (n, 3), ``normals`` (n, 3), ``uvs`` (n, 2)
    or None, ``temperatures`` (n,) or None, ``faces`` (m, 3) indices into them."""

    def __init__(self, positions, normals, uvs, temperatures, faces):
        self.positions = positions
        self.normals = normals
        self.uvs = uvs
        self.temperatures = temperatures
        self.faces = faces


def _corner_normals(mesh, loop_count):
    normals = np.empty(loop_count * 3, dtype=np.float32)
    if hasattr(mesh, "corner_normals"):
        mesh.corner_normals.foreach_get("vector", normals)
    else:
        if hasattr(mesh, "calc_normals_split"):
            mesh.calc_normals_split()
        mesh.loops.foreach_get("normal", normals)
    return normals.reshape(-1, 3)


def point_attribute(mesh, name):
    """The values of a float attribute on the point domain called ``name`` (one per
    vertex), or None if the mesh has no such attribute."""
    attribute = mesh.attributes.get(name) if name else None
    if attribute is None or attribute.domain != "POINT" or attribute.data_type != "FLOAT":
        return None
    values = np.empty(len(mesh.vertices), dtype=np.float32)
    attribute.data.foreach_get("value", values)
    return values


def triangle_arrays(mesh, attribute_names=None):
    """Split a mesh into TriangleArrays by material index.

    ``attribute_names`` maps a material index to the name of the point attribute whose values
    become that slot's per-vertex temperatures (slots not in it get none).
    Returns (dict material index -> TriangleArrays, set of attribute names that were asked
    for but are missing).
    """
    attribute_names = attribute_names or {}
    mesh.calc_loop_triangles()
    triangle_count = len(mesh.loop_triangles)
    if triangle_count == 0:
        return {}, set()
    tri_loops = np.empty(triangle_count * 3, dtype=np.int64)
    mesh.loop_triangles.foreach_get("loops", tri_loops)
    tri_material = np.empty(triangle_count, dtype=np.int64)
    mesh.loop_triangles.foreach_get("material_index", tri_material)

    loop_count = len(mesh.loops)
    loop_vertex = np.empty(loop_count, dtype=np.int64)
    mesh.loops.foreach_get("vertex_index", loop_vertex)
    coordinates = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", coordinates)
    coordinates = coordinates.reshape(-1, 3)
    normals = _corner_normals(mesh, loop_count)
    uv_layer = mesh.uv_layers.active
    uvs = None
    if uv_layer is not None:
        uvs = np.empty(loop_count * 2, dtype=np.float32)
        uv_layer.data.foreach_get("uv", uvs)
        uvs = uvs.reshape(-1, 2)

    missing = set()
    result = {}
    for material_index in np.unique(tri_material):
        loops = tri_loops.reshape(-1, 3)[tri_material == material_index].reshape(-1)
        temperatures = None
        name = attribute_names.get(int(material_index))
        if name:
            values = point_attribute(mesh, name)
            if values is None:
                missing.add(name)
            else:
                temperatures = values[loop_vertex[loops]]
        columns = [loop_vertex[loops].astype(np.float64)[:, None],
                   normals[loops].astype(np.float64)]
        if uvs is not None:
            columns.append(uvs[loops].astype(np.float64))
        if temperatures is not None:
            columns.append(temperatures.astype(np.float64)[:, None])
        keys = np.concatenate(columns, axis=1)
        unique, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
        corner = loops[first]
        result[int(material_index)] = TriangleArrays(
            positions=coordinates[loop_vertex[corner]],
            normals=normals[corner],
            uvs=None if uvs is None else uvs[corner],
            temperatures=None if temperatures is None else temperatures[first],
            faces=inverse.reshape(-1, 3))
    return result, missing
