"""The camera, film, sampler and integrator of the exported scene (the lines before
WorldBegin).

pbrt-v4 (and kiln) use a left-handed camera space: x right, y up, z forward. The scene keeps
Blender's right-handed world coordinates, and the camera transform starts with
``Scale -1 1 1`` before a ``LookAt`` from the Blender camera (as pbrt exporters do): the
mirror makes image right Blender's camera right, so the render matches Blender's camera view
(an object on the left of the view stays on the left).
"""

import math

from mathutils import Vector

from . import pbrt_text


def _fit(camera, width, height):
    """Blender's sensor fit resolved: ('HORIZONTAL' or 'VERTICAL', sensor size in mm)."""
    fit = camera.sensor_fit
    if fit == "AUTO":
        return ("HORIZONTAL" if width >= height else "VERTICAL"), camera.sensor_width
    if fit == "HORIZONTAL":
        return fit, camera.sensor_width
    return fit, camera.sensor_height


def field_of_view(camera, width, height):
    """pbrt-v4's ``fov`` (degrees, across the shorter image side) of a perspective Blender
    camera rendering ``width`` x ``height`` pixels: the fitted side spans
    2 atan(sensor / (2 lens)), the other side follows from the pixel counts (square pixels)."""
    fit, sensor = _fit(camera, width, height)
    tan_fitted = sensor / (2.0 * camera.lens)
    if fit == "HORIZONTAL":
        tan_x, tan_y = tan_fitted, tan_fitted * height / width
    else:
        tan_x, tan_y = tan_fitted * width / height, tan_fitted
    return math.degrees(2.0 * math.atan(min(tan_x, tan_y)))


def screen_window(camera, width, height):
    """pbrt-v4's ``screenwindow`` [x0 x1 y0 y1] for the camera's lens shift (perspective:
    the shorter side spans [-1, 1]; orthographic: camera-space units from Ortho Scale, the
    fitted side's full extent). Blender's shift is a fraction of the fitted side's extent.
    Returns None for a perspective camera without shift (pbrt-v4's default window)."""
    fit, _ = _fit(camera, width, height)
    if camera.type == "ORTHO":
        if fit == "HORIZONTAL":
            half_x, half_y = camera.ortho_scale / 2, camera.ortho_scale / 2 * height / width
        else:
            half_x, half_y = camera.ortho_scale / 2 * width / height, camera.ortho_scale / 2
        extent = camera.ortho_scale
    else:
        if camera.shift_x == 0 and camera.shift_y == 0:
            return None
        half_x, half_y = max(1.0, width / height), max(1.0, height / width)
        extent = 2 * (half_x if fit == "HORIZONTAL" else half_y)
    dx, dy = camera.shift_x * extent, camera.shift_y * extent
    return [-half_x + dx, half_x + dx, -half_y + dy, half_y + dy]


def camera_lines(camera_object, width, height, reports):
    """``Scale -1 1 1``, ``LookAt`` and ``Camera`` lines for a Blender camera object (an
    evaluated one: its world matrix is used). Perspective and orthographic cameras map to
    pbrt-v4's; panoramic ones are written as perspective and reported ("camera-type").
    With depth of field on: ``lensradius`` = focal length / (2 f-stop) (the focal length's
    millimetres read as 1/1000 scene unit) and ``focaldistance`` = the focus object's
    distance along the view axis, or the Focus Distance."""
    camera = camera_object.data
    matrix = camera_object.matrix_world
    rotation = matrix.to_3x3()
    eye = matrix.translation
    forward = (rotation @ Vector((0.0, 0.0, -1.0))).normalized()
    up = (rotation @ Vector((0.0, 1.0, 0.0))).normalized()
    target = eye + forward
    lines = ["Scale -1 1 1  # pbrt-v4 is left-handed: mirror x so the image matches "
             "Blender's view",
             "LookAt %s  %s  %s" % tuple(" ".join(pbrt_text.fmt_number(c) for c in v)
                                         for v in (eye, target, up))]
    params = []
    kind = "perspective"
    if camera.type == "ORTHO":
        kind = "orthographic"
    else:
        if camera.type == "PANO":
            reports.add("camera-type", camera_object.name)
        params.append(("float", "fov", field_of_view(camera, width, height)))
    window = screen_window(camera, width, height)
    if window is not None:
        params.append(("float", "screenwindow", window))
    if camera.dof.use_dof and camera.type != "ORTHO":
        if camera.dof.focus_object is not None:
            focus = camera.dof.focus_object.matrix_world.translation
            distance = max(1e-4, (focus - eye).dot(forward))
        else:
            distance = camera.dof.focus_distance
        radius = camera.lens / 1000.0 / (2.0 * max(camera.dof.aperture_fstop, 1e-4))
        params += [("float", "lensradius", radius), ("float", "focaldistance", distance)]
    lines += pbrt_text.directive("Camera", kind, params=params)
    return lines


def render_settings_lines(width, height, film_name, samples, max_depth):
    """``Film`` (rgb, resolution, file name), ``Sampler`` (zsobol, samples) and
    ``Integrator`` (path, maxdepth) lines."""
    lines = pbrt_text.directive("Film", "rgb", params=[
        ("integer", "xresolution", int(width)), ("integer", "yresolution", int(height)),
        ("string", "filename", film_name)])
    lines += pbrt_text.directive("Sampler", "zsobol",
                                 params=[("integer", "pixelsamples", int(samples))])
    lines += pbrt_text.directive("Integrator", "path",
                                 params=[("integer", "maxdepth", int(max_depth))])
    return lines
