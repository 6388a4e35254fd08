"""Blender materials to pbrt-v4 materials, with kiln's temperature and emission parameters.

Mapping of a Principled BSDF (the node linked to the active Material Output's Surface):
  - Metallic >= 0.5: ``conductor`` with kiln's named metal (``metal-XX-eta``/``-k``), the
    material's kiln metal or, if "Guess from Base Color", metals.guess_metal(Base Color);
  - else Transmission >= 0.5: ``dielectric`` with ``eta`` = IOR;
  - else Coat (Clearcoat) >= 0.1, or Specular > 0 with Roughness < 0.3: ``coateddiffuse``
    (``reflectance`` = Base Color, ``eta`` = IOR in Blender 4, from Specular in Blender 3:
    F0 = 0.08 Specular, eta = (1 + sqrt F0) / (1 - sqrt F0));
  - else ``diffuse`` with ``reflectance`` = Base Color.
Roughness: Blender's GGX uses alpha = Roughness^2, pbrt-v4's Trowbridge-Reitz the same alpha;
every material is written with ``"float roughness" Roughness^2`` and
``"bool remaproughness" false``, so the microfacet alpha is Blender's (the coat's roughness
for coateddiffuse with a coat).
Base Color linked to an Image Texture node becomes an ``imagemap`` spectrum texture (not for
metals). A Diffuse BSDF maps to ``diffuse``. Anything else is ``diffuse`` with the material's
viewport colour, reported.
"""

import math

from . import metals, pbrt_text, temperature

DEFAULT_MATERIAL = "kiln-default"


def follow_link(socket):
    """The node linked into ``socket`` (passing through Reroute nodes), or None."""
    while socket is not None and socket.is_linked:
        node = socket.links[0].from_node
        if node.bl_idname == "NodeReroute":
            socket = node.inputs[0]
            continue
        return node
    return None


def _input(node, *names):
    """The first of the named input sockets ``node`` has (names differ between Blender 3 and
    4, e.g. 'Clearcoat' and 'Coat Weight'), or None."""
    for name in names:
        socket = node.inputs.get(name)
        if socket is not None:
            return socket
    return None


def _value(node, *names, default=0.0):
    socket = _input(node, *names)
    return default if socket is None else socket.default_value


def output_surface_node(material):
    """The shader node linked to the Surface of the material's active output, or None."""
    tree = material.node_tree
    if not material.use_nodes or tree is None:
        return None
    output = None
    if hasattr(tree, "get_output_node"):
        output = tree.get_output_node("CYCLES") or tree.get_output_node("ALL")
    if output is None:
        outputs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputMaterial"]
        active = [n for n in outputs if n.is_active_output]
        output = (active or outputs or [None])[0]
    if output is None:
        return None
    return follow_link(output.inputs.get("Surface"))


class MaterialSpec:
    """One exported material: ``kind`` (pbrt-v4 material type), the standard ``params``,
    ``textures`` (lines of spectrum Texture directives the params name), and the kiln-only
    ``temperature`` (temperature.TemperatureSpec or None) and ``emission`` (kiln model name
    or None for the default, kirchhoff)."""

    def __init__(self, kind, params, textures=(), temperature_spec=None, emission=None):
        self.kind = kind
        self.params = list(params)
        self.textures = list(textures)
        self.temperature = temperature_spec
        self.emission = emission

    def kiln_params(self):
        """The kiln-only parameters: temperature, then emission."""
        out = []
        if self.temperature is not None:
            out.append(self.temperature.param)
        if self.emission is not None:
            out.append(("string", "emission", self.emission))
        return out

    def named_lines(self, name):
        """``MakeNamedMaterial`` lines defining the material as ``name``."""
        return pbrt_text.directive("MakeNamedMaterial", name,
                                   params=[("string", "type", self.kind)] + self.params,
                                   kiln_params=self.kiln_params())

    def inline_lines(self, indent=""):
        """``Material`` lines setting the material in the current attribute block."""
        return pbrt_text.directive("Material", self.kind, params=self.params,
                                   kiln_params=self.kiln_params(), indent=indent)


def _roughness_params(roughness):
    return [("float", "roughness", float(roughness) ** 2), ("bool", "remaproughness", False)]


def _image_texture(node, name, images, reports, owner):
    """The lines of an ``imagemap`` spectrum texture called ``name`` for an Image Texture
    node, or None if its image cannot be written (reported)."""
    image = node.image
    if image is None:
        return None
    path = images.path_of(image)
    if path is None:
        reports.add("image-missing", image.name)
        return None
    params = [("string", "filename", path)]
    colourspace = image.colorspace_settings.name
    if not image.is_float and colourspace in ("Non-Color", "Linear", "Raw"):
        params.append(("string", "encoding", "linear"))
    if node.interpolation == "Closest":
        params.append(("string", "filter", "point"))
    wrap = {"EXTEND": "clamp", "CLIP": "black"}.get(node.extension)
    if wrap:
        params.append(("string", "wrap", wrap))
    vector = node.inputs.get("Vector")
    if vector is not None and vector.is_linked:
        reports.add("image-mapping", image.name)
    return pbrt_text.directive("Texture", name, "spectrum", "imagemap", params=params)


def _colour(node, socket_names, texture_name, images, reports, owner):
    """The reflectance parameter and texture lines for a colour socket: an ``rgb`` value, or
    the ``imagemap`` texture of a linked Image Texture node; other links are reported
    ("base-color-nodes") and use the socket's own colour."""
    socket = _input(node, *socket_names)
    rgb = list(socket.default_value)[:3] if socket is not None else [0.8, 0.8, 0.8]
    linked = follow_link(socket) if socket is not None else None
    if linked is not None:
        if linked.bl_idname == "ShaderNodeTexImage":
            lines = _image_texture(linked, texture_name, images, reports, owner)
            if lines is not None:
                return ("texture", "reflectance", texture_name), [lines]
        else:
            reports.add("base-color-nodes", owner)
    return ("rgb", "reflectance", rgb), []


def _principled(material, node, name, images, reports):
    owner = material.name
    base_socket = _input(node, "Base Color")
    base = list(base_socket.default_value)[:3]
    metallic = _value(node, "Metallic")
    roughness = _value(node, "Roughness", default=0.5)
    transmission = _value(node, "Transmission Weight", "Transmission")
    ior = _value(node, "IOR", default=1.45)
    coat = _value(node, "Coat Weight", "Clearcoat")
    coat_roughness = _value(node, "Coat Roughness", "Clearcoat Roughness", default=0.03)
    specular = _value(node, "Specular IOR Level", "Specular", default=0.5)

    unmapped = (_value(node, "Subsurface Weight", "Subsurface") > 0 or
                _value(node, "Sheen Weight", "Sheen") > 0 or
                _value(node, "Anisotropic") > 0 or
                _value(node, "Alpha", default=1.0) < 1)
    emission_colour = _input(node, "Emission Color", "Emission")
    if emission_colour is not None and _value(node, "Emission Strength", default=1.0) > 0 and \
            (emission_colour.is_linked or max(list(emission_colour.default_value)[:3]) > 0):
        unmapped = True
    for socket in node.inputs:
        if socket.is_linked and socket.name != "Base Color":
            unmapped = True
    if unmapped:
        reports.add("principled-input", owner)

    if metallic >= 0.5:
        metal = material.kiln.metal
        if metal == "AUTO":
            metal = metals.guess_metal(base)
        if base_socket.is_linked:
            reports.add("metal-texture", owner)
        eta, k = metals.spectrum_names(metal)
        return MaterialSpec("conductor", [("spectrum", "eta", eta), ("spectrum", "k", k)] +
                            _roughness_params(roughness))
    if transmission >= 0.5:
        return MaterialSpec("dielectric", [("float", "eta", ior)] + _roughness_params(roughness))
    reflectance, textures = _colour(node, ("Base Color",), name + "-basecolor", images,
                                    reports, owner)
    has_coat = coat >= 0.1
    if has_coat or (specular > 0 and roughness < 0.3):
        if node.inputs.get("Specular IOR Level") is None and node.inputs.get("Specular"):
            f0 = min(0.08 * specular, 0.99)
            eta = (1 + math.sqrt(f0)) / (1 - math.sqrt(f0))
        else:
            eta = ior
        return MaterialSpec("coateddiffuse", [reflectance, ("float", "eta", eta)] +
                            _roughness_params(coat_roughness if has_coat else roughness),
                            textures)
    return MaterialSpec("diffuse", [reflectance], textures)


def material_spec(material, name, images, reports, temperature_name=None):
    """The MaterialSpec of a Blender material (None: Blender's default grey diffuse).

    ``name`` is the material's name in the scene file (its textures are named after it);
    ``temperature_name`` names its temperature texture (default ``name + "-temperature"``).
    The temperature comes from ``material.kiln`` (temperature.temperature_spec); the emission
    model is written unless it is kiln's default (kirchhoff).
    """
    if material is None:
        return MaterialSpec("diffuse", [("rgb", "reflectance", [0.8, 0.8, 0.8])])
    node = output_surface_node(material)
    if node is None and not material.use_nodes:
        spec = MaterialSpec("diffuse", [("rgb", "reflectance", list(material.diffuse_color)[:3])])
    elif node is not None and node.bl_idname == "ShaderNodeBsdfPrincipled":
        spec = _principled(material, node, name, images, reports)
    elif node is not None and node.bl_idname == "ShaderNodeBsdfDiffuse":
        reflectance, textures = _colour(node, ("Color",), name + "-basecolor", images, reports,
                                        material.name)
        spec = MaterialSpec("diffuse", [reflectance], textures)
    else:
        reports.add("material-nodes", material.name)
        spec = MaterialSpec("diffuse", [("rgb", "reflectance", list(material.diffuse_color)[:3])])
    settings = material.kiln
    spec.temperature = temperature.temperature_spec(
        settings, temperature_name or name + "-temperature", images, reports, material.name)
    if settings.emission != "KIRCHHOFF":
        spec.emission = settings.emission.lower()
    return spec
