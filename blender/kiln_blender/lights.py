"""Blender lights and the world background as pbrt-v4 lights.

Blender's light units are Cycles' (linear RGB, a white surface emitting radiance 1 looks
white 1.0 in the render); pbrt-v4's ``rgb`` light spectra are scaled the same way (``rgb L
[1 1 1]`` seen directly renders as 1), so the conversions reproduce Cycles' pixel values:
  - point and spot of power P watts and colour c: ``rgb I`` = c P / (4 pi) (the radiant
    intensity Cycles gives them; a spot keeps the intensity of the point light it is cut
    from); a spot's cone half-angle is half its Size, and its Blend b becomes
    ``conedeltaangle`` so that the smooth step in cos theta spans the same cosines as
    Cycles' (from cos(Size / 2) to cos(Size / 2) + b (1 - cos(Size / 2))), at least
    MIN_CONE_DELTA degrees;
  - sun of strength S: ``distant`` with ``rgb L`` = c S (the irradiance on a surface facing
    it);
  - area light of power P and area A: a one-sided ``diffuse`` area light on the same square,
    rectangle, disc or ellipse (a 32-segment polygon), ``rgb L`` = c P AREA_FACTOR / A: the
    radiance Cycles gives it (see AREA_FACTOR);
  - world: a Background colour c of strength S as ``infinite`` ``rgb L`` = c S; an
    equirectangular Environment Texture converted to pbrt-v4's equal-area square map
    (envmap.py), values times S, as ``infinite`` ``filename``.
"""

import math
import os

import numpy as np

from . import envmap, image_files, pbrt_text
from .materials import follow_link

# Radiance of a Cycles area light per watt, times its area: Cycles gives an area light of
# power P and area A the radiance P / (4 A) (so it emits pi P / 4 in all); measured against
# Cycles in Blender 3.4, see docs/blender.md ("Lights").
AREA_FACTOR = 0.25
DISC_SEGMENTS = 32
MIN_CONE_DELTA = 0.2  # degrees


def _rgb(light, factor):
    return [c * factor for c in light.color]


def _area_mesh(light):
    """Points, normals and indices of an area light's surface in its own space (z = 0,
    facing -z, the side Blender's area lights emit from), and its area."""
    sx = light.size
    sy = light.size_y if light.shape in ("RECTANGLE", "ELLIPSE") else light.size
    if light.shape in ("SQUARE", "RECTANGLE"):
        points = [(-sx / 2, -sy / 2, 0), (sx / 2, -sy / 2, 0), (sx / 2, sy / 2, 0),
                  (-sx / 2, sy / 2, 0)]
        indices = [0, 2, 1, 0, 3, 2]
        area = sx * sy
    else:
        points = [(0.0, 0.0, 0.0)]
        for i in range(DISC_SEGMENTS):
            angle = 2 * math.pi * i / DISC_SEGMENTS
            points.append((sx / 2 * math.cos(angle), sy / 2 * math.sin(angle), 0.0))
        indices = []
        for i in range(DISC_SEGMENTS):
            indices += [0, 1 + (i + 1) % DISC_SEGMENTS, 1 + i]
        # the polygon's area, so that the power matches the shape actually written
        area = 0.5 * DISC_SEGMENTS * (sx / 2) * (sy / 2) * math.sin(2 * math.pi / DISC_SEGMENTS)
    normals = [(0.0, 0.0, -1.0)] * len(points)
    return points, normals, indices, area


def light_lines(light, name, matrix, reports):
    """The lines of one Blender light (its data ``light``) called ``name`` with the world
    matrix ``matrix``."""
    if getattr(light, "use_nodes", False):
        reports.add("light-nodes", name)
    position = list(matrix.translation)
    direction = (matrix.to_3x3() @ _vector(0, 0, -1)).normalized()
    lines = ["# light " + name.replace("\n", " ")]
    if light.type == "POINT":
        lines += pbrt_text.directive("LightSource", "point", params=[
            ("point3", "from", position), ("rgb", "I", _rgb(light, light.energy / (4 * math.pi)))])
    elif light.type == "SPOT":
        half = light.spot_size / 2
        cos_end = math.cos(half)
        cos_start = min(1.0, cos_end + (1 - cos_end) * light.spot_blend)
        # at least MIN_CONE_DELTA: pbrt-v4's light BVH gives a hard-edged spot
        # (conedeltaangle 0) no importance inside its cone, so pbrt-v4 renders it dark (kiln
        # picks it: lights/light_bounds.cpp)
        delta = max(MIN_CONE_DELTA, math.degrees(half - math.acos(cos_start)))
        target = [p + d for p, d in zip(position, direction)]
        lines += pbrt_text.directive("LightSource", "spot", params=[
            ("point3", "from", position), ("point3", "to", target),
            ("float", "coneangle", math.degrees(half)), ("float", "conedeltaangle", delta),
            ("rgb", "I", _rgb(light, light.energy / (4 * math.pi)))])
    elif light.type == "SUN":
        lines += pbrt_text.directive("LightSource", "distant", params=[
            ("point3", "from", [0, 0, 0]), ("point3", "to", list(direction)),
            ("rgb", "L", _rgb(light, light.energy))])
    elif light.type == "AREA":
        if getattr(light, "spread", math.pi) < math.pi - 1e-6:
            reports.add("area-spread", name)
        points, normals, indices, area = _area_mesh(light)
        radiance = _rgb(light, light.energy * AREA_FACTOR / max(area, 1e-12))
        lines.append("AttributeBegin")
        lines.append("  Transform [" + " ".join(pbrt_text.fmt_number(v) for v in
                                               pbrt_text.matrix_values(matrix)) + "]")
        lines += pbrt_text.directive("AreaLightSource", "diffuse",
                                     params=[("rgb", "L", radiance)], indent="  ")
        lines += pbrt_text.directive("Material", "diffuse",
                                     params=[("rgb", "reflectance", [0, 0, 0])], indent="  ")
        lines += pbrt_text.directive("Shape", "trianglemesh", params=[
            ("point3", "P", [c for p in points for c in p]),
            ("normal", "N", [c for n in normals for c in n]),
            ("integer", "indices", indices)], indent="  ")
        lines.append("AttributeEnd")
    return lines


def _vector(x, y, z):
    from mathutils import Vector
    return Vector((x, y, z))


def _environment_file(node, strength, folder, relative, reports):
    """Write the equal-area map of an Environment Texture node; its scene-relative path, or
    None (reported) if the image is missing or not equirectangular."""
    image = node.image
    if image is None:
        return None
    if node.projection != "EQUIRECTANGULAR":
        reports.add("env-projection", image.name)
        return None
    vector = node.inputs.get("Vector")
    if vector is not None and vector.is_linked:
        reports.add("env-mapping", image.name)
    try:
        pixels = image_files.image_pixels(image)
    except (RuntimeError, ValueError):
        pixels = np.zeros((0, 0, 4))
    if pixels.size == 0:
        reports.add("image-missing", image.name)
        return None
    rgb = pixels[:, :, :3].astype(np.float64)
    if not image.is_float and image.colorspace_settings.name == "sRGB":
        rgb = image_files.srgb_to_linear(rgb)
    square = envmap.equirectangular_to_equal_area(rgb * strength)
    os.makedirs(folder, exist_ok=True)
    name = image_files.safe_name(os.path.splitext(image.name)[0]) + "-equalarea.pfm"
    image_files.write_pfm(os.path.join(folder, name), square)
    return relative + "/" + name


def world_lines(world, folder, relative, reports):
    """The ``infinite`` light of a Blender world (see the module), or [] for none/black.
    ``folder`` (absolute) and ``relative`` (as the scene names it) say where a converted
    environment map goes. Worlds whose Surface is not a Background node, or whose Background
    colour is linked to anything but an Environment Texture, are exported as the world's
    viewport colour and reported ("world-nodes")."""
    if world is None:
        return []
    colour = list(world.color)[:3]
    tree = world.node_tree if world.use_nodes else None
    if tree is not None:
        outputs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputWorld"]
        active = [n for n in outputs if n.is_active_output] or outputs
        background = follow_link(active[0].inputs.get("Surface")) if active else None
        if background is None:
            colour = [0.0, 0.0, 0.0]
        elif background.bl_idname != "ShaderNodeBackground":
            reports.add("world-nodes", world.name)
        else:
            strength_socket = background.inputs.get("Strength")
            if strength_socket.is_linked:
                reports.add("world-nodes", world.name)
            strength = strength_socket.default_value
            colour_socket = background.inputs.get("Color")
            source = follow_link(colour_socket)
            if source is None:
                colour = [c * strength for c in list(colour_socket.default_value)[:3]]
            elif source.bl_idname == "ShaderNodeTexEnvironment":
                path = _environment_file(source, strength, folder, relative, reports)
                if path is not None:
                    return ["# world " + world.name.replace("\n", " ")] + pbrt_text.directive(
                        "LightSource", "infinite", params=[("string", "filename", path)])
            else:
                reports.add("world-nodes", world.name)
    if max(colour) <= 0:
        return []
    return ["# world " + world.name.replace("\n", " ")] + pbrt_text.directive(
        "LightSource", "infinite", params=[("rgb", "L", colour)])
