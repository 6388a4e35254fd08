"""Operators: File > Export > kiln / pbrt-v4 (.pbrt), and adding a temperature attribute."""

import bpy
from bpy.props import StringProperty
from bpy_extras.io_utils import ExportHelper

from . import exporter


class KILN_OT_export_pbrt(bpy.types.Operator, ExportHelper):
    """Export the scene as a pbrt-v4 scene file with kiln's temperatures, PLY meshes and
    images next to it"""

    bl_idname = "export_scene.kiln_pbrt"
    bl_label = "Export kiln / pbrt-v4"
    bl_options = {"PRESET"}

    filename_ext = ".pbrt"
    filter_glob: StringProperty(default="*.pbrt", options={"HIDDEN"})

    def execute(self, context):
        depsgraph = context.evaluated_depsgraph_get()
        try:
            result = exporter.export_scene(depsgraph, self.filepath)
        except exporter.ExportError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        for warning in result.warnings:
            self.report({"WARNING"}, warning)
        self.report({"INFO"}, "Exported %s (%d shapes, %d instances, %d meshes)"
                    % (result.filepath, result.shapes, result.instances, result.meshes))
        return {"FINISHED"}


class KILN_OT_add_temperature_attribute(bpy.types.Operator):
    """Add the float point attribute the object's Attribute temperature source names to its
    mesh, every vertex at the object's Temperature (change the values with Geometry Nodes or
    Python)"""

    bl_idname = "kiln.add_temperature_attribute"
    bl_label = "Add Temperature Attribute"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        obj = context.object
        return obj is not None and obj.type == "MESH" and obj.mode == "OBJECT"

    def execute(self, context):
        obj = context.object
        name = obj.kiln.attribute_name or "temperature"
        mesh = obj.data
        if mesh.attributes.get(name) is not None:
            self.report({"WARNING"}, "%s already has an attribute %r" % (mesh.name, name))
            return {"CANCELLED"}
        attribute = mesh.attributes.new(name, "FLOAT", "POINT")
        value = obj.kiln.temperature
        attribute.data.foreach_set("value", [value] * len(mesh.vertices))
        mesh.update()
        return {"FINISHED"}


def menu_export(self, context):
    self.layout.operator(KILN_OT_export_pbrt.bl_idname, text="kiln / pbrt-v4 (.pbrt)")


classes = (KILN_OT_export_pbrt, KILN_OT_add_temperature_attribute)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.TOPBAR_MT_file_export.append(menu_export)


def unregister():
    bpy.types.TOPBAR_MT_file_export.remove(menu_export)
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
