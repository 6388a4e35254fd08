"""kiln temperatures of materials and objects: the parameter and, for a temperature field,
the float texture that defines it (kiln's ``gradient``, ``heatmap``, ``noise`` and
``vertexattribute`` textures; docs/guide/temperature-fields-and-animation.md)."""

import os

from . import pbrt_text

VERTEX_TEXTURE = "kiln-vertex-temperature"
FLOAT_IMAGE_EXTENSIONS = (".exr", ".hdr", ".pfm")


class TemperatureSpec:
    """How one material's or object's temperature is written.

    ``param``: the parameter tuple (``("float", "temperature", T)`` or
    ``("texture", "temperature", name)``).
    ``texture``: the lines of the ``Texture`` directive the parameter names, or [].
    ``object_dependent``: the texture is evaluated in the space of the ``Texture`` directive
    (object-space gradient, noise) and must be declared under each object's transform.
    ``attribute``: for the ATTRIBUTE source, the mesh attribute whose values go into the PLY
    vertex property ``temperature``; else None.
    """

    def __init__(self, param, texture=(), object_dependent=False, attribute=None):
        self.param = param
        self.texture = list(texture)
        self.object_dependent = object_dependent
        self.attribute = attribute


def _texture(name, kind, params):
    lines = pbrt_text.directive("Texture", name, "float", kind, kiln_params=params)
    lines[0] += "  " + pbrt_text.KILN_MARK
    return lines


def _is_float_image(image, path):
    return bool(getattr(image, "is_float", False)) or \
        os.path.splitext(path)[1].lower() in FLOAT_IMAGE_EXTENSIONS


def temperature_spec(settings, texture_name, images, reports, owner):
    """The TemperatureSpec of ``settings`` (a material's or object's ``kiln``), or None when
    it makes nothing hot: source CONSTANT with temperature 0, IMAGE without an image (or one
    that cannot be written: reported as "image-missing" for ``owner``).

    ``texture_name`` names the texture of a field (ATTRIBUTE always uses the shared texture
    ``kiln-vertex-temperature``); ``images`` is an image_files.ImageWriter.
    GRADIENT writes p0, p1, t0, t1, space and extrapolate; IMAGE the file name and, for 8-bit
    images, tmin and tmax (float images -- .exr, .hdr, .pfm, or float in Blender -- hold
    kelvin); NOISE frequency, octaves, lacunarity, gain, seed, min and max.
    """
    source = settings.source
    if source == "CONSTANT":
        if settings.temperature <= 0:
            return None
        return TemperatureSpec(("float", "temperature", float(settings.temperature)))
    if source == "GRADIENT":
        params = [("point3", "p0", list(settings.gradient_p0)),
                  ("point3", "p1", list(settings.gradient_p1)),
                  ("float", "t0", settings.gradient_t0), ("float", "t1", settings.gradient_t1),
                  ("string", "space", settings.gradient_space.lower()),
                  ("string", "extrapolate", settings.gradient_extrapolate.lower())]
        return TemperatureSpec(("texture", "temperature", texture_name),
                               _texture(texture_name, "gradient", params),
                               object_dependent=settings.gradient_space == "OBJECT")
    if source == "IMAGE":
        if settings.image is None:
            return None
        path = images.path_of(settings.image)
        if path is None:
            reports.add("image-missing", settings.image.name)
            return None
        params = [("string", "filename", path)]
        if not _is_float_image(settings.image, path):
            params += [("float", "tmin", settings.image_tmin),
                       ("float", "tmax", settings.image_tmax)]
        return TemperatureSpec(("texture", "temperature", texture_name),
                               _texture(texture_name, "heatmap", params))
    if source == "NOISE":
        params = [("float", "frequency", settings.noise_frequency),
                  ("integer", "octaves", int(settings.noise_octaves)),
                  ("float", "lacunarity", settings.noise_lacunarity),
                  ("float", "gain", settings.noise_gain),
                  ("integer", "seed", int(settings.noise_seed)),
                  ("float", "min", settings.noise_min), ("float", "max", settings.noise_max)]
        return TemperatureSpec(("texture", "temperature", texture_name),
                               _texture(texture_name, "noise", params), object_dependent=True)
    if source == "ATTRIBUTE":
        return TemperatureSpec(("texture", "temperature", VERTEX_TEXTURE),
                               _texture(VERTEX_TEXTURE, "vertexattribute",
                                        [("string", "name", "temperature")]),
                               attribute=settings.attribute_name or "temperature")
    raise ValueError("unknown temperature source %r" % source)
