"""kiln for Blender: tag objects and materials with temperatures, export the scene as a
pbrt-v4 file for kiln (File > Export > kiln / pbrt-v4), and render with kiln (render engine
"kiln"). See docs/blender.md in kiln's source tree."""

bl_info = {
    "name": "kiln",
    "author": "kiln developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Render engine \"kiln\"; File > Export > kiln / pbrt-v4 (.pbrt); "
                "Material and Object properties > kiln",
    "description": "Glowing hot matter: temperatures, pbrt-v4 export and rendering with kiln",
    "category": "Render",
}

from . import engine, operators, properties, ui

_modules = (properties, operators, ui, engine)


def register():
    for module in _modules:
        module.register()


def unregister():
    for module in reversed(_modules):
        module.unregister()
