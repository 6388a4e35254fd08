"""Export an evaluated Blender scene as a pbrt-v4 scene file for kiln.

``export_scene(depsgraph, filepath)`` writes FILE.pbrt, the meshes as binary PLY files in
FILE_meshes/ and images in FILE_textures/, and returns an ExportResult whose ``warnings`` list
what could not be mapped, one message per kind (reports.Reports).

Objects come from the depsgraph's object instances (modifiers applied, collection and
geometry-node instances included), less those disabled for rendering (or whose instancer
is). The viewport's depsgraph (File > Export) holds only what the viewport shows; the render
engine's holds what renders. Each mesh-like object (mesh, curve, surface, text, metaball) is
turned into triangles (``to_mesh``) and written as one PLY per material slot in object
space; a shape is an ``AttributeBegin`` block with the object's ``Transform``. A geometry
(same evaluated data and materials) used by two or more objects that are not hot becomes an
``ObjectBegin`` definition and ``ObjectInstance``s; hot ones are always plain shapes (kiln
samples hot shapes as lights only outside instances), though they share the PLY file.
"""

import os

from . import camera as camera_export
from . import lights, materials, pbrt_text, ply, temperature
from .image_files import ImageWriter, safe_name
from .mesh_data import triangle_arrays
from .reports import Reports

MESH_TYPES = {"MESH", "CURVE", "SURFACE", "FONT", "META"}
SILENT_TYPES = {"EMPTY", "CAMERA", "LIGHT_PROBE", "SPEAKER", "ARMATURE", "LATTICE", "LIGHT"}


class ExportError(Exception):
    """The scene cannot be exported (no camera, a folder that cannot be written)."""


class ExportResult:
    """What ``export_scene`` wrote: ``filepath`` (the scene file), ``film_filename`` (the
    image name in its Film), ``width``/``height``, ``warnings`` (one message per kind of
    unmapped feature), ``reports`` (the Reports object, for its kinds and items) and the
    counts ``shapes``, ``instances`` and ``meshes`` (PLY files)."""

    def __init__(self, filepath, film_filename, width, height, reports, shapes, instances,
                 meshes):
        self.filepath = filepath
        self.film_filename = film_filename
        self.width = width
        self.height = height
        self.reports = reports
        self.warnings = reports.messages()
        self.shapes = shapes
        self.instances = instances
        self.meshes = meshes


class _Names:
    """Unique names in the scene file, one per (namespace, key)."""

    def __init__(self):
        self._by_key = {}
        self._taken = set()

    def get(self, namespace, key, wanted):
        if (namespace, key) in self._by_key:
            return self._by_key[(namespace, key)]
        name, n = wanted, 1
        while (namespace, name) in self._taken:
            n += 1
            name = "%s.%d" % (wanted, n)
        self._taken.add((namespace, name))
        self._by_key[(namespace, key)] = name
        return name


class _Use:
    """One placement of a geometry: object name, world matrix, object temperature settings,
    whether it is hot."""

    def __init__(self, name, matrix, object_settings, object_spec, hot):
        self.name = name
        self.matrix = matrix
        self.object_settings = object_settings
        self.object_spec = object_spec
        self.hot = hot


def _carries_geometry_of_parent(instance):
    """Whether a depsgraph instance is the temporary mesh holding the evaluated geometry of
    its parent (a curve, text, surface or metaball object): an instance whose object is a
    mesh derived from the same original object as its parent's, which is not a mesh."""
    parent = instance.parent
    return (instance.is_instance and parent is not None and instance.object.type == "MESH"
            and parent.type != "MESH" and instance.object.original == parent.original)


def resolution(scene):
    """The rendered image size: Blender's resolution times its percentage."""
    render = scene.render
    scale = render.resolution_percentage / 100.0
    return max(1, int(render.resolution_x * scale)), max(1, int(render.resolution_y * scale))


def _transform_line(matrix, indent):
    return indent + "Transform [" + " ".join(
        pbrt_text.fmt_number(v) for v in pbrt_text.matrix_values(matrix)) + "]"


class _Exporter:
    def __init__(self, depsgraph, filepath, camera_object, size, samples):
        self.depsgraph = depsgraph
        self.scene = depsgraph.scene
        self.filepath = os.path.abspath(filepath)
        self.folder = os.path.dirname(self.filepath)
        stem = os.path.splitext(os.path.basename(self.filepath))[0]
        self.stem = stem
        self.mesh_relative = safe_name(stem) + "_meshes"
        self.texture_relative = safe_name(stem) + "_textures"
        self.reports = Reports()
        self.images = ImageWriter(os.path.join(self.folder, self.texture_relative),
                                  self.texture_relative)
        self.names = _Names()
        self.camera_object = camera_object
        self.size = size
        self.samples = samples
        self.material_specs = {}   # material key -> (pbrt name, MaterialSpec)
        self.world_textures = {}   # texture name -> lines (ordered)
        self.geometries = {}       # geometry key -> dict (name, parts, uses)
        self.light_lines = []
        self.ply_count = 0

    # -- materials ------------------------------------------------------------------------
    def material(self, material):
        """(pbrt name, MaterialSpec) of a Blender material (None: the default), made once."""
        key = material.original.name_full if material is not None else None
        if key not in self.material_specs:
            wanted = material.name if material is not None else materials.DEFAULT_MATERIAL
            name = self.names.get("material", key, wanted)
            texture_name = self.names.get("texture", ("material", key), name + "-temperature")
            spec = materials.material_spec(material, name, self.images, self.reports,
                                           texture_name)
            for lines in spec.textures:
                self.world_textures.setdefault(lines[0], lines)
            if spec.temperature is not None and not spec.temperature.object_dependent \
                    and spec.temperature.texture:
                self.world_textures.setdefault(spec.temperature.texture[0],
                                               spec.temperature.texture)
            self.material_specs[key] = (name, spec, material)
        return self.material_specs[key]

    # -- geometry ---------------------------------------------------------------------------
    def add_object(self, instance, owner):
        """Add one depsgraph instance of a mesh-like object; ``owner`` is the evaluated
        object whose kiln settings apply (the instance's object, or for the temporary mesh
        that carries a curve's or text's geometry, that curve or text object)."""
        obj = instance.object
        if obj.type not in MESH_TYPES:
            if obj.type not in SILENT_TYPES:
                self.reports.add("object-type", obj.name)
            return
        slots = [slot.material for slot in obj.material_slots] or [None]
        material_entries = [self.material(m) for m in slots]
        object_settings = owner.kiln
        object_spec = temperature.temperature_spec(object_settings, "", self.images,
                                                   self.reports, obj.name)
        if object_spec is not None and object_spec.texture and \
                not object_spec.object_dependent and not object_spec.attribute:
            # a field shared by every use of the object: defined once, at world level
            object_spec = temperature.temperature_spec(
                object_settings,
                self.names.get("texture", ("object", obj.name), obj.name + "-temperature"),
                self.images, self.reports, obj.name)
        hot = object_spec is not None or any(e[1].temperature is not None
                                             for e in material_entries)
        attributes = {}
        for index, (_, spec, _) in enumerate(material_entries):
            source = object_spec if object_spec is not None else spec.temperature
            if source is not None and source.attribute:
                attributes[index] = source.attribute
        data_key = obj.data.original.name_full if obj.data is not None else obj.name
        unique = obj.original.modifiers and not instance.is_instance
        key = (obj.data.as_pointer() if obj.data is not None else 0,
               obj.name if unique else "", data_key,
               tuple(e[0] for e in material_entries), tuple(sorted(attributes.items())))
        geometry = self.geometries.get(key)
        if geometry is None:
            geometry = {"name": self.names.get("geometry", key, obj.data.name if obj.data
                                               else obj.name),
                        "parts": self.write_meshes(obj, attributes), "uses": []}
            self.geometries[key] = geometry
        if object_spec is not None and not object_spec.object_dependent and object_spec.texture:
            self.world_textures.setdefault(object_spec.texture[0], object_spec.texture)
        geometry["uses"].append(_Use(obj.name, instance.matrix_world.copy(), object_settings,
                                     object_spec, hot))
        geometry["materials"] = material_entries

    def write_meshes(self, obj, attributes):
        """Write the PLY files of an evaluated object; [(material slot, relative path)]."""
        mesh = obj.to_mesh()
        try:
            if mesh is None:
                return []
            arrays, missing = triangle_arrays(mesh, attributes)
        finally:
            obj.to_mesh_clear()
        if missing:
            self.reports.add("attribute-missing", obj.name)
        folder = os.path.join(self.folder, self.mesh_relative)
        os.makedirs(folder, exist_ok=True)
        parts = []
        for index, part in sorted(arrays.items()):
            base = safe_name(obj.data.name if obj.data is not None else obj.name)
            filename = self.names.get("ply", self.ply_count, "%s-%d.ply" % (base, index))
            ply.write_ply(os.path.join(folder, filename), part.positions, part.faces,
                          normals=part.normals, uvs=part.uvs, temperatures=part.temperatures)
            self.ply_count += 1
            parts.append((index, self.mesh_relative + "/" + filename))
        return parts

    # -- scene file -------------------------------------------------------------------------
    def shape_lines(self, geometry, use, indent):
        """Material and Shape lines of a geometry's parts (for one use, or None inside an
        object definition)."""
        lines = []
        entries = geometry["materials"]
        for index, path in geometry["parts"]:
            name, spec, material = entries[min(index, len(entries) - 1)]
            if spec.temperature is not None and spec.temperature.object_dependent:
                texture_name = self.names.get("texture", (id(use), name),
                                              "%s-temperature@%s" % (name, use.name))
                per_object = temperature.temperature_spec(
                    material.kiln, texture_name, self.images, self.reports, material.name)
                lines += [indent + line for line in per_object.texture]
                inline = materials.MaterialSpec(spec.kind, spec.params, spec.textures,
                                                per_object, spec.emission)
                lines += inline.inline_lines(indent)
            else:
                lines.append(indent + "NamedMaterial " + pbrt_text.quote(name))
            kiln_params = []
            if use is not None and use.object_spec is not None:
                kiln_params.append(use.object_spec.param)
            lines += pbrt_text.directive("Shape", "plymesh",
                                         params=[("string", "filename", path)],
                                         kiln_params=kiln_params, indent=indent)
        return lines

    def object_texture_lines(self, use, indent):
        spec = use.object_spec
        if spec is None or not spec.object_dependent:
            return []
        name = self.names.get("texture", (id(use), "object"), use.name + "-temperature")
        spec = temperature.temperature_spec(use.object_settings, name, self.images,
                                            self.reports, use.name)
        use.object_spec = spec
        return [indent + line for line in spec.texture]

    def run(self):
        width, height = self.size
        if self.scene.render.use_border:
            self.reports.add("render-border", self.scene.name)
        film_name = safe_name(self.stem) + ".exr"
        header = ["# pbrt-v4 scene exported from Blender by kiln_blender (scene %s)"
                  % pbrt_text.quote(self.scene.name),
                  "# Lines ending in \"%s\" are kiln's own (temperatures, emission models, "
                  "temperature textures);" % pbrt_text.KILN_MARK,
                  "# pbrt-v4 reads the rest. Meshes: %s/, images: %s/."
                  % (self.mesh_relative, self.texture_relative), ""]
        camera_lines = camera_export.camera_lines(self.camera_object, width, height,
                                                  self.reports)
        settings = camera_export.render_settings_lines(width, height, film_name, self.samples,
                                                       self.scene.kiln.max_depth)
        world = lights.world_lines(self.scene.world, os.path.join(self.folder,
                                                                  self.texture_relative),
                                   self.texture_relative, self.reports)
        # Curves, texts and the like may come twice: as themselves and as an instance of a
        # temporary mesh holding their evaluated geometry (Blender 3 and later). Such objects
        # are exported through that mesh only.
        carried = set()
        for instance in self.depsgraph.object_instances:
            if _carries_geometry_of_parent(instance):
                carried.add(instance.parent.original.name_full)
        for instance in self.depsgraph.object_instances:
            obj = instance.object
            hidden = obj if not instance.is_instance else instance.parent
            if hidden is not None and hidden.original.hide_render:
                continue
            if hasattr(instance, "show_self") and not instance.show_self:
                continue
            if obj.type == "LIGHT":
                self.light_lines += lights.light_lines(obj.data, obj.name,
                                                       instance.matrix_world.copy(),
                                                       self.reports)
            elif obj.type != "MESH" and obj.original.name_full in carried:
                continue
            else:
                # kiln settings are read from the evaluated object itself, not from an
                # instance's temporary copy (reading settings there would add properties
                # to a copy Blender frees without them); for a curve's or text's temporary
                # mesh, from the curve or text object
                source = instance.parent if _carries_geometry_of_parent(instance) else obj
                self.add_object(instance, source.original.evaluated_get(self.depsgraph))

        body, definitions, shapes, instances = [], [], 0, 0
        for geometry in self.geometries.values():
            uses = geometry["uses"]
            if not geometry["parts"]:
                continue
            if len(uses) >= 2 and not any(u.hot for u in uses):
                definitions.append("ObjectBegin " + pbrt_text.quote(geometry["name"]))
                definitions += self.shape_lines(geometry, None, "  ")
                definitions.append("ObjectEnd")
                for use in uses:
                    body += ["AttributeBegin  # " + use.name.replace("\n", " "),
                             _transform_line(use.matrix, "  "),
                             "  ObjectInstance " + pbrt_text.quote(geometry["name"]),
                             "AttributeEnd"]
                    instances += 1
            else:
                for use in uses:
                    body += ["AttributeBegin  # " + use.name.replace("\n", " "),
                             _transform_line(use.matrix, "  ")]
                    body += self.object_texture_lines(use, "  ")
                    body += self.shape_lines(geometry, use, "  ")
                    body.append("AttributeEnd")
                    shapes += len(geometry["parts"])

        material_lines = []
        for name, spec, _ in self.material_specs.values():
            if spec.temperature is None or not spec.temperature.object_dependent:
                material_lines += spec.named_lines(name)  # else written in each shape's block
        texture_lines = [line for lines in self.world_textures.values() for line in lines]

        out = header + camera_lines + settings + ["", "WorldBegin", ""]
        for block in (self.light_lines, world, texture_lines, material_lines, definitions, body):
            if block:
                out += block + [""]
        os.makedirs(self.folder, exist_ok=True)
        with open(self.filepath, "w", encoding="utf-8") as f:
            f.write("\n".join(out))
        return ExportResult(self.filepath, film_name, width, height, self.reports, shapes,
                            instances, self.ply_count)


def export_scene(depsgraph, filepath, camera_object=None, size=None, samples=None):
    """Export the evaluated scene of ``depsgraph`` to ``filepath`` (see the module).

    ``camera_object`` defaults to the scene's camera, ``size`` (width, height) to Blender's
    resolution times its percentage, ``samples`` to the scene's kiln samples. Raises
    ExportError if there is no camera. Returns an ExportResult.
    """
    scene = depsgraph.scene
    camera_object = camera_object or scene.camera
    if camera_object is None:
        raise ExportError("the scene has no camera")
    camera_object = camera_object.evaluated_get(depsgraph)
    size = size or resolution(scene)
    samples = samples if samples is not None else scene.kiln.samples
    try:
        return _Exporter(depsgraph, filepath, camera_object, size, samples).run()
    except OSError as error:
        raise ExportError("cannot write %s: %s" % (filepath, error))
