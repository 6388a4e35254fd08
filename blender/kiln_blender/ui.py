"""Panels: kiln in Material and Object properties, and kiln's render settings."""

import bpy

from . import materials, metals


def draw_temperature(layout, settings, data_owner=None):
    """The temperature source and its settings. ``data_owner``: the mesh (for the attribute
    list), or None."""
    layout.prop(settings, "source")
    source = settings.source
    if source == "CONSTANT":
        layout.prop(settings, "temperature", text="Temperature (K)")
    elif source == "GRADIENT":
        col = layout.column(align=True)
        col.prop(settings, "gradient_p0")
        col.prop(settings, "gradient_t0", text="T0 (K)")
        col = layout.column(align=True)
        col.prop(settings, "gradient_p1")
        col.prop(settings, "gradient_t1", text="T1 (K)")
        layout.prop(settings, "gradient_space")
        layout.prop(settings, "gradient_extrapolate")
    elif source == "IMAGE":
        layout.template_ID(settings, "image", open="image.open")
        image = settings.image
        if image is None or not image.is_float:
            row = layout.row(align=True)
            row.prop(settings, "image_tmin", text="Black (K)")
            row.prop(settings, "image_tmax", text="White (K)")
        else:
            layout.label(text="Float image: values are kelvin")
    elif source == "NOISE":
        col = layout.column(align=True)
        col.prop(settings, "noise_frequency")
        col.prop(settings, "noise_octaves")
        col.prop(settings, "noise_lacunarity")
        col.prop(settings, "noise_gain")
        col.prop(settings, "noise_seed")
        row = layout.row(align=True)
        row.prop(settings, "noise_min", text="Min (K)")
        row.prop(settings, "noise_max", text="Max (K)")
    elif source == "ATTRIBUTE":
        if data_owner is not None and hasattr(data_owner, "attributes"):
            layout.prop_search(settings, "attribute_name", data_owner, "attributes")
        else:
            layout.prop(settings, "attribute_name")


class MATERIAL_PT_kiln(bpy.types.Panel):
    """kiln's temperature, emission model and metal of the active material."""

    bl_label = "kiln"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "material"

    @classmethod
    def poll(cls, context):
        return context.material is not None

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        material = context.material
        settings = material.kiln
        obj = context.object
        draw_temperature(layout, settings, obj.data if obj is not None else None)
        layout.prop(settings, "emission")
        node = materials.output_surface_node(material)
        if node is not None and node.bl_idname == "ShaderNodeBsdfPrincipled":
            metallic = node.inputs.get("Metallic")
            if metallic is not None and metallic.default_value >= 0.5:
                layout.prop(settings, "metal")
                if settings.metal == "AUTO":
                    guess = metals.guess_metal(node.inputs["Base Color"].default_value)
                    layout.label(text="Exported as metal-%s" % guess)


class OBJECT_PT_kiln(bpy.types.Panel):
    """kiln's object temperature (wins over the materials')."""

    bl_label = "kiln"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "object"

    @classmethod
    def poll(cls, context):
        obj = context.object
        return obj is not None and obj.type in {"MESH", "CURVE", "SURFACE", "FONT", "META"}

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        obj = context.object
        settings = obj.kiln
        draw_temperature(layout, settings, obj.data if obj.type == "MESH" else None)
        if settings.source == "CONSTANT" and settings.temperature <= 0:
            layout.label(text="0 K: the materials' temperatures apply")
        if settings.source == "ATTRIBUTE" and obj.type == "MESH" and \
                obj.data.attributes.get(settings.attribute_name) is None:
            layout.operator("kiln.add_temperature_attribute")


class RENDER_PT_kiln(bpy.types.Panel):
    """kiln's render settings (shown when the render engine is kiln)."""

    bl_label = "kiln"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "render"
    COMPAT_ENGINES = {"KILN"}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        settings = context.scene.kiln
        col = layout.column()
        col.prop(settings, "samples")
        col.prop(settings, "seed")
        col.prop(settings, "threads")
        col.prop(settings, "max_depth")
        col.prop(settings, "emission_override")
        col.prop(settings, "executable")
        col.prop(settings, "keep_files")


classes = (MATERIAL_PT_kiln, OBJECT_PT_kiln, RENDER_PT_kiln)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)


def unregister():
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
