"""The kiln render engine: F12 (and ``blender -b ... -E KILN -f N``) exports the evaluated
scene to a temporary folder, runs kiln on it and shows its image.

While kiln renders, every partial image it writes (after each wave of samples) is loaded
into the render result, and the progress bar shows the samples per pixel done. Esc stops
kiln (SIGINT): kiln writes the image so far, which is shown. If kiln fails, the end of its
standard error is reported as an error.
"""

import os
import shutil
import signal
import tempfile

import bpy

from . import exporter, properties, runner


class KilnRenderEngine(bpy.types.RenderEngine):
    """Renders the scene with the kiln executable (see the module)."""

    bl_idname = "KILN"
    bl_label = "kiln"
    bl_use_preview = False
    bl_use_eevee_viewport = True
    bl_use_postprocess = True

    def render(self, depsgraph):
        scene = depsgraph.scene
        width, height = self.resolution_x, self.resolution_y
        executable = properties.find_executable(scene)
        if not executable:
            self.report({"ERROR"}, "kiln: no kiln executable (set it in the kiln render "
                                   "settings, the add-on preferences or KILN_EXECUTABLE)")
            return
        folder = tempfile.mkdtemp(prefix="kiln-blender-")
        keep = scene.kiln.keep_files
        try:
            keep = self._render(depsgraph, scene, executable, folder, width, height) or keep
        finally:
            if keep:
                print("kiln: files kept in %s" % folder)
            else:
                shutil.rmtree(folder, ignore_errors=True)

    def _render(self, depsgraph, scene, executable, folder, width, height):
        """Export, run and load; returns True if the folder should be kept (a failure)."""
        self.update_stats("", "kiln: exporting the scene")
        scene_path = os.path.join(folder, "scene.pbrt")
        camera = self.camera_override or scene.camera
        try:
            result = exporter.export_scene(depsgraph, scene_path, camera_object=camera,
                                           size=(width, height))
        except exporter.ExportError as error:
            self.report({"ERROR"}, "kiln: %s" % error)
            return False
        for warning in result.warnings:
            self.report({"WARNING"}, "kiln: " + warning)
        image_path = os.path.join(folder, "render.exr")
        samples = scene.kiln.samples
        override = scene.kiln.emission_override
        command = runner.kiln_command(executable, scene_path, image_path, samples,
                                      scene.kiln.seed, scene.kiln.threads,
                                      None if override == "SCENE" else override.lower())
        try:
            run = runner.KilnRun(command, cwd=folder)
        except OSError as error:
            self.report({"ERROR"}, "kiln: cannot run %s: %s" % (executable, error))
            return False
        render_result = self.begin_result(0, 0, width, height)
        stopping = False
        self.update_stats("", "kiln: rendering")
        while True:
            finished = run.returncode is not None
            changed, spp = run.poll()
            if changed:
                try:
                    render_result.layers[0].load_from_file(image_path)
                    self.update_result(render_result)
                except RuntimeError:
                    pass  # e.g. an image of another size: keep the last one
                if spp is not None:
                    self.update_progress(min(1.0, spp / float(samples)))
                    self.update_stats("", "kiln: %d / %d samples per pixel" % (spp, samples))
            if finished:
                break
            if not stopping and self.test_break():
                run.stop()
                stopping = True
                self.update_stats("", "kiln: stopping")
            runner.sleep_briefly()
        code = run.wait(timeout=60)
        changed, _ = run.poll()
        if changed:
            try:
                render_result.layers[0].load_from_file(image_path)
            except RuntimeError:
                pass
        self.end_result(render_result)
        if code == 0 or (stopping and code in (130, -signal.SIGINT)):
            return False  # finished, or stopped by Esc (with the image so far if kiln had one)
        tail = run.stderr_text().strip().splitlines()[-10:]
        self.report({"ERROR"}, "kiln exited with status %s: %s" % (code, " | ".join(tail)))
        return True


EEVEE_IDS = ("BLENDER_EEVEE", "BLENDER_EEVEE_NEXT")  # EEVEE's id, and its id in some 4.x releases


def _compat_panels():
    """Blender's own panels of camera, light, material, world, mesh, object and output
    properties that EEVEE shows; the kiln engine shows them too."""
    modules = ("properties_data_camera", "properties_data_light", "properties_material",
               "properties_world", "properties_output", "properties_data_mesh",
               "properties_object")
    panels = []
    for panel in bpy.types.Panel.__subclasses__():
        engines = getattr(panel, "COMPAT_ENGINES", None)
        if engines is None or not any(e in engines for e in EEVEE_IDS):
            continue
        if panel.__module__.split(".")[-1] in modules:
            panels.append(panel)
    return panels


def register():
    bpy.utils.register_class(KilnRenderEngine)
    for panel in _compat_panels():
        panel.COMPAT_ENGINES.add(KilnRenderEngine.bl_idname)


def unregister():
    for panel in _compat_panels():
        panel.COMPAT_ENGINES.discard(KilnRenderEngine.bl_idname)
    bpy.utils.unregister_class(KilnRenderEngine)
