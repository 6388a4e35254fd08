"""kiln's settings on materials, objects and scenes (``material.kiln``, ``object.kiln``,
``scene.kiln``) and the add-on preferences."""

import os

import bpy
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, FloatVectorProperty,
                       IntProperty, PointerProperty, StringProperty)

from . import metals

TEMPERATURE_SOURCES = [
    ("CONSTANT", "Constant", "One temperature (0 = not hot)"),
    ("GRADIENT", "Gradient", "Linear between two points (kiln's \"gradient\" texture)"),
    ("IMAGE", "Image", "A heat map over the UV map (kiln's \"heatmap\" texture): 8-bit images "
     "are mapped to Min..Max, float images are read as kelvin"),
    ("NOISE", "Noise", "fBm noise in object space mapped to Min..Max (kiln's \"noise\" texture)"),
    ("ATTRIBUTE", "Attribute", "A float mesh attribute on the point domain, in kelvin "
     "(exported as the PLY vertex property \"temperature\")"),
]

EMISSION_MODELS = [
    ("KIRCHHOFF", "Kirchhoff",
     "Emission B(T) (1 - R): good reflectors emit little (kiln's default)"),
    ("ADDITIVE", "Additive", "Emission B(T) added to the reflection"),
    ("DIFFUSE", "Diffuse", "A blackbody: emission B(T), the surface is black"),
    ("NONE", "None", "No thermal emission"),
]

METAL_CHOICES = [("AUTO", "Guess from Base Color",
                  "The named metal nearest the Base Color (gold-yellow: Au, copper-red: Cu, "
                  "light grey: Ag or Al, grey: Fe, ...)")] + metals.METALS


def _tag_owner(self, context):
    """Tag the material or object owning the changed setting for re-evaluation, so that
    evaluated copies (what the exporter reads) see the new value."""
    self.id_data.update_tag()


def _with_update(props):
    """The same properties, each calling _tag_owner when it changes."""
    out = {}
    for name, prop in props.items():
        function, keywords = prop.function, dict(prop.keywords)
        keywords["update"] = _tag_owner
        out[name] = function(**keywords)
    return out


def _temperature_properties():
    """The properties shared by materials and objects: the temperature and its source."""
    return {
        "temperature": FloatProperty(
            name="Temperature", description="Temperature in kelvin (0 = not hot)",
            default=0.0, min=0.0, soft_max=6000.0, step=1000, precision=0),
        "source": EnumProperty(name="Source", items=TEMPERATURE_SOURCES, default="CONSTANT",
                               description="Where the temperature comes from"),
        "gradient_p0": FloatVectorProperty(name="Point 0", size=3, subtype="XYZ",
                                           default=(0.0, 0.0, -1.0),
                                           description="Where the gradient has T0"),
        "gradient_p1": FloatVectorProperty(name="Point 1", size=3, subtype="XYZ",
                                           default=(0.0, 0.0, 1.0),
                                           description="Where the gradient has T1"),
        "gradient_t0": FloatProperty(name="T0", default=800.0, min=0.0, precision=0,
                                     step=1000, description="Temperature at Point 0 (K)"),
        "gradient_t1": FloatProperty(name="T1", default=1400.0, min=0.0, precision=0,
                                     step=1000, description="Temperature at Point 1 (K)"),
        "gradient_space": EnumProperty(
            name="Space", default="OBJECT",
            items=[("OBJECT", "Object", "Points in the object's own coordinates"),
                   ("WORLD", "World", "Points in world coordinates")]),
        "gradient_extrapolate": EnumProperty(
            name="Beyond the points", default="CLAMP",
            items=[("CLAMP", "Clamp", "T0 before Point 0, T1 after Point 1"),
                   ("LINEAR", "Linear", "The line continues")]),
        "image": PointerProperty(name="Heat map", type=bpy.types.Image,
                                 description="Image looked up through the UV map"),
        "image_tmin": FloatProperty(name="Min", default=500.0, min=0.0, precision=0, step=1000,
                                    description="Temperature of black in an 8-bit image (K)"),
        "image_tmax": FloatProperty(name="Max", default=1500.0, min=0.0, precision=0, step=1000,
                                    description="Temperature of white in an 8-bit image (K)"),
        "noise_frequency": FloatProperty(name="Frequency", default=1.0, min=0.0,
                                         description="Cycles per object-space unit"),
        "noise_octaves": IntProperty(name="Octaves", default=6, min=1, max=16),
        "noise_lacunarity": FloatProperty(name="Lacunarity", default=2.0, min=0.0),
        "noise_gain": FloatProperty(name="Gain", default=0.5, min=0.0),
        "noise_seed": IntProperty(name="Seed", default=0, min=0),
        "noise_min": FloatProperty(name="Min", default=800.0, min=0.0, precision=0, step=1000,
                                   description="Lowest temperature (K)"),
        "noise_max": FloatProperty(name="Max", default=1400.0, min=0.0, precision=0, step=1000,
                                   description="Highest temperature (K)"),
        "attribute_name": StringProperty(
            name="Attribute", default="temperature",
            description="Float attribute on the point domain holding kelvin"),
    }


def _make_group(name, doc, extra):
    annotations = _with_update({**_temperature_properties(), **extra})
    return type(name, (bpy.types.PropertyGroup,),
                {"__doc__": doc, "__annotations__": annotations})


KilnMaterialSettings = _make_group(
    "KilnMaterialSettings",
    "kiln's settings of a material: temperature source, emission model, named metal.",
    {
        "emission": EnumProperty(name="Emission", items=EMISSION_MODELS, default="KIRCHHOFF",
                                 description="How a hot surface of this material emits"),
        "metal": EnumProperty(name="Metal", items=METAL_CHOICES, default="AUTO",
                              description="kiln's named metal for metallic materials"),
    })

KilnObjectSettings = _make_group(
    "KilnObjectSettings",
    "kiln's settings of an object: a temperature that wins over its materials' "
    "(Constant 0 = use the materials').",
    {})


class KilnSceneSettings(bpy.types.PropertyGroup):
    """kiln's render settings of a scene."""

    samples: IntProperty(name="Samples", default=64, min=1, max=1 << 20,
                         description="Samples per pixel (kiln --spp)")
    seed: IntProperty(name="Seed", default=0, min=0, description="Sampler seed (kiln --seed)")
    threads: IntProperty(name="Threads", default=0, min=0,
                         description="Worker threads (kiln --threads); 0 = all cores")
    max_depth: IntProperty(name="Max Depth", default=5, min=1, max=100,
                           description="Longest path (Integrator \"path\" maxdepth)")
    emission_override: EnumProperty(
        name="Emission", default="SCENE",
        items=[("SCENE", "Per Material", "Each material's own emission model")] + EMISSION_MODELS,
        description="Emission model for every hot surface (kiln --emission), or each "
                    "material's own")
    executable: StringProperty(
        name="kiln Executable", subtype="FILE_PATH", default="",
        description="The kiln program; empty: the add-on preference, else the environment "
                    "variable KILN_EXECUTABLE, else kiln on PATH")
    keep_files: BoolProperty(name="Keep Files", default=False,
                             description="Keep the exported scene and kiln's image in the "
                                         "temporary folder after rendering")


class KilnPreferences(bpy.types.AddonPreferences):
    """The add-on's preferences: where the kiln program is."""

    bl_idname = __package__

    executable: StringProperty(
        name="kiln Executable", subtype="FILE_PATH", default="",
        description="The kiln program (used when the scene does not name one)")

    def draw(self, context):
        self.layout.prop(self, "executable")


def find_executable(scene):
    """The kiln program to run: the scene's setting if not empty, else the add-on preference
    if not empty, else the environment variable KILN_EXECUTABLE, else, when the add-on is
    loaded from a kiln source tree (also through a symbolic link to blender/kiln_blender), that
    tree's build/kiln if it was built, else ``kiln`` on PATH. Returns None if none is found.
    Paths are made absolute (Blender's // prefix resolved)."""
    import shutil
    candidates = [scene.kiln.executable]
    try:
        addon = bpy.context.preferences.addons.get(__package__)
    except AttributeError:  # no context (a thread without one): skip the preference
        addon = None
    if addon is not None and addon.preferences is not None:
        candidates.append(addon.preferences.executable)
    candidates.append(os.environ.get("KILN_EXECUTABLE", ""))
    for candidate in candidates:
        if candidate:
            return os.path.abspath(bpy.path.abspath(candidate))
    tree = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
    built = os.path.join(tree, "build", "kiln")
    if os.path.isfile(os.path.join(tree, "src", "app", "main.cpp")) and os.access(built, os.X_OK):
        return built
    return shutil.which("kiln")


classes = (KilnMaterialSettings, KilnObjectSettings, KilnSceneSettings, KilnPreferences)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.Material.kiln = PointerProperty(type=KilnMaterialSettings)
    bpy.types.Object.kiln = PointerProperty(type=KilnObjectSettings)
    bpy.types.Scene.kiln = PointerProperty(type=KilnSceneSettings)


def unregister():
    del bpy.types.Scene.kiln
    del bpy.types.Object.kiln
    del bpy.types.Material.kiln
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
