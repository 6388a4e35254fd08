"""Headless tests of kiln's Blender add-on (blender/kiln_blender).

    blender -b --factory-startup --python-exit-code 1 --python test/blender/addon_test.py -- \
        KILN_BINARY PBRT_BINARY_OR_EMPTY WORKDIR

The add-on is enabled from Blender's add-on path (BLENDER_USER_SCRIPTS/addons, where
test/blender/run_tests.sh installs it) or, failing that, from this source tree's blender/
(unless the environment variable KILN_BLENDER_REQUIRE_INSTALLED is set: then that fails).

The test builds a scene in Python -- a hot gold sphere (Principled, metallic, gold base
colour, kiln GRADIENT source: 1100 K for object x <= -0.2, 1500 K for x >= 0.2, linear
between), a floor with a generated checker image, a camera -- plus objects hidden under the
floor that exercise the other paths (two Emission-only materials, linked duplicates, a hot
duplicate of the sphere, NOISE, IMAGE and ATTRIBUTE temperature sources). It exports the
scene, checks the file, renders it with kiln and compares it with hand-written kiln scenes of
analytic gold spheres at constant 1500 K and 1100 K, checks that kiln stops on SIGINT with
a partial image, optionally checks that pbrt-v4 reads the file once kiln's constructs are
removed, and saves WORKDIR/scene.blend (render engine kiln) for run_tests.sh.

Any failed check raises, so Blender exits with status 1 (--python-exit-code 1).
"""

import math
import os
import re
import subprocess
import sys
import time

import bpy
import numpy as np

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if len(ARGS) != 3:
    raise SystemExit("usage: blender -b --factory-startup --python-exit-code 1 --python "
                     "addon_test.py -- KILN_BINARY PBRT_BINARY_OR_EMPTY WORKDIR")
KILN, PBRT, WORKDIR = os.path.abspath(ARGS[0]), ARGS[1], os.path.abspath(ARGS[2])
os.makedirs(WORKDIR, exist_ok=True)

WIDTH, HEIGHT = 96, 72          # even sizes: the image is symmetric about its centre lines
LENS, SENSOR = 50.0, 36.0       # mm; horizontal sensor fit (the image is wider than tall)
CAMERA_DISTANCE = 6.0           # camera at (0, -6, 0) looking along +y, up +z
SPP = 64
T_COLD, T_HOT = 1100.0, 1500.0
FAILURES = []


def check(condition, message):
    """Record a failed check (printed at once; the test fails at the end)."""
    print(("ok:   " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        FAILURES.append(message)


# ---------------------------------------------------------------------------------------------
# Enabling the add-on

def enable_addon():
    import addon_utils
    try:
        module = addon_utils.enable("kiln_blender", default_set=True,
                                    handle_error=lambda error: None)
    except Exception:
        module = None
    if module is None and os.environ.get("KILN_BLENDER_REQUIRE_INSTALLED"):
        raise SystemExit("kiln_blender is not on Blender's add-on path (BLENDER_USER_SCRIPTS="
                         "%s)" % os.environ.get("BLENDER_USER_SCRIPTS"))
    if module is None:
        source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender")
        sys.path.insert(0, os.path.abspath(source))
        module = addon_utils.enable("kiln_blender", default_set=True)
        print("note: kiln_blender enabled from the source tree %s" % os.path.abspath(source))
    else:
        print("note: kiln_blender enabled from %s" % os.path.dirname(module.__file__))
    if module is None:
        raise SystemExit("cannot enable the kiln_blender add-on")
    return module


# ---------------------------------------------------------------------------------------------
# The scene

def principled(name, colour, metallic=0.0, roughness=0.5, base_image=None):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    node = material.node_tree.nodes["Principled BSDF"]
    node.inputs["Base Color"].default_value = (*colour, 1.0)
    node.inputs["Metallic"].default_value = metallic
    node.inputs["Roughness"].default_value = roughness
    if base_image is not None:
        texture = material.node_tree.nodes.new("ShaderNodeTexImage")
        texture.image = base_image
        material.node_tree.links.new(texture.outputs["Color"], node.inputs["Base Color"])
    return material


def emission_only(name):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    tree = material.node_tree
    tree.nodes.remove(tree.nodes["Principled BSDF"])
    emission = tree.nodes.new("ShaderNodeEmission")
    tree.links.new(emission.outputs[0], tree.nodes["Material Output"].inputs["Surface"])
    return material


def checker_image(path):
    """An 8x8-square checker of 64 x 64 pixels (grey 0.2 and 0.6), saved as PNG."""
    image = bpy.data.images.new("checker", 64, 64)
    cells = (np.indices((64, 64)) // 8).sum(axis=0) % 2
    value = np.where(cells == 1, 0.6, 0.2)
    pixels = np.stack([value, value, value, np.ones_like(value)], axis=-1)
    image.pixels.foreach_set(pixels.astype(np.float32).ravel())
    image.filepath_raw = path
    image.file_format = "PNG"
    image.save()
    return image


def add_mesh(kind, name, location, material=None, **options):
    if kind == "sphere":
        bpy.ops.mesh.primitive_uv_sphere_add(location=location, **options)
    elif kind == "plane":
        bpy.ops.mesh.primitive_plane_add(location=location, **options)
    else:
        bpy.ops.mesh.primitive_cube_add(location=location, **options)
    obj = bpy.context.object
    obj.name = name
    if material is not None:
        obj.data.materials.append(material)
    return obj


def linked_duplicate(obj, name, location):
    copy = obj.copy()  # shares obj.data
    copy.name = name
    copy.location = location
    bpy.context.scene.collection.objects.link(copy)
    return copy


def build_scene():
    scene = bpy.context.scene
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    world = bpy.data.worlds.new("black")
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    gold = principled("Gold", (1.0, 0.766, 0.336), metallic=1.0, roughness=0.0)
    gold.kiln.source = "GRADIENT"
    gold.kiln.gradient_p0 = (-0.2, 0.0, 0.0)
    gold.kiln.gradient_p1 = (0.2, 0.0, 0.0)
    gold.kiln.gradient_t0 = T_COLD
    gold.kiln.gradient_t1 = T_HOT
    gold.kiln.gradient_space = "OBJECT"
    gold.kiln.gradient_extrapolate = "CLAMP"
    sphere = add_mesh("sphere", "Hot sphere", (0, 0, 0), gold, radius=1.0, segments=128,
                      ring_count=64)
    bpy.ops.object.shade_smooth()

    checker = checker_image(os.path.join(WORKDIR, "checker.png"))
    add_mesh("plane", "Floor", (0, 0, -1), principled("Checker", (0.5, 0.5, 0.5),
                                                      base_image=checker), size=20)

    bpy.ops.object.camera_add(location=(0, -CAMERA_DISTANCE, 0),
                              rotation=(math.radians(90), 0, 0))
    camera = bpy.context.object
    camera.data.lens = LENS
    camera.data.sensor_width = SENSOR
    camera.data.sensor_fit = "AUTO"
    scene.camera = camera

    # Under the floor (z < -1), out of sight of the camera and of the sphere:
    add_mesh("cube", "Glow A", (-4, 0, -4), emission_only("Glow A"), size=0.5)
    add_mesh("cube", "Glow B", (-3, 0, -4), emission_only("Glow B"), size=0.5)
    crate = add_mesh("cube", "Crate 1", (0, 0, -4), principled("Wood", (0.4, 0.25, 0.1)),
                     size=0.5)
    crate.data.name = "Crate mesh"
    linked_duplicate(crate, "Crate 2", (1, 0, -4))
    linked_duplicate(sphere, "Hot sphere copy", (0, 0, -6))
    noisy = add_mesh("cube", "Noisy", (3, 0, -4), principled("Rust", (0.3, 0.1, 0.05)),
                     size=0.5)
    noisy.kiln.source = "NOISE"
    noisy.kiln.noise_min, noisy.kiln.noise_max = 900.0, 1200.0
    noisy.data.materials[0].kiln.emission = "DIFFUSE"
    mapped = add_mesh("plane", "Heat mapped", (4, 0, -4), principled("Steel", (0.5, 0.5, 0.5)),
                      size=0.5)
    mapped.kiln.source = "IMAGE"
    mapped.kiln.image = checker
    mapped.kiln.image_tmin, mapped.kiln.image_tmax = 600.0, 1300.0
    painted = add_mesh("plane", "Painted", (5, 0, -4), principled("Slag", (0.2, 0.2, 0.2)),
                       size=0.5)
    painted.kiln.source = "ATTRIBUTE"
    painted.kiln.temperature = 1000.0
    with bpy.context.temp_override(object=painted, active_object=painted):
        bpy.ops.kiln.add_temperature_attribute()
    painted.data.attributes["temperature"].data[0].value = 1400.0
    return scene


# ---------------------------------------------------------------------------------------------
# Panels (Blender draws no UI in background mode: a stand-in layout checks what they draw)

class RecordingLayout:
    """Stands in for a UILayout: records every property, operator and label drawn and
    notes properties and operators that do not exist."""

    def __init__(self, problems):
        self.problems = problems
        self.drawn = []
        self.use_property_split = False

    def _check(self, data, name):
        self.drawn.append(name)
        if name not in data.bl_rna.properties:
            self.problems.append("%s has no property %s" % (data, name))

    def prop(self, data, name, **options):
        self._check(data, name)

    def prop_search(self, data, name, search_data, search_name, **options):
        self._check(data, name)
        self._check(search_data, search_name)

    def template_ID(self, data, name, **options):
        self._check(data, name)

    def operator(self, idname, **options):
        module, name = idname.split(".")
        self.drawn.append(idname)
        try:  # (bpy.ops.module.name always exists; its RNA type only if registered)
            getattr(getattr(bpy.ops, module), name).get_rna_type()
        except KeyError:
            self.problems.append("no operator %s" % idname)

    def label(self, **options):
        self.drawn.append("label")

    def column(self, **options):
        return self

    def row(self, **options):
        return self


def check_panels(kiln_blender):
    print("-- panels")
    from types import SimpleNamespace
    ui = kiln_blender.ui
    problems, drawn = [], set()
    gold = bpy.data.materials["Gold"]
    cube = bpy.data.objects["Noisy"]  # has no temperature attribute: the Add button shows
    for source, _, _ in kiln_blender.properties.TEMPERATURE_SOURCES:
        for panel, settings, context in (
                (ui.MATERIAL_PT_kiln, gold.kiln,
                 SimpleNamespace(material=gold, object=bpy.data.objects["Hot sphere"])),
                (ui.OBJECT_PT_kiln, cube.kiln, SimpleNamespace(object=cube))):
            saved = settings.source
            settings.source = source
            layout = RecordingLayout(problems)
            if not panel.poll(context):
                problems.append("%s does not show for %s" % (panel.__name__, source))
            panel.draw(SimpleNamespace(layout=layout), context)
            drawn.update(layout.drawn)
            settings.source = saved
    layout = RecordingLayout(problems)
    context = SimpleNamespace(scene=bpy.context.scene, engine="KILN")
    check(ui.RENDER_PT_kiln.poll(context) and
          not ui.RENDER_PT_kiln.poll(SimpleNamespace(engine="CYCLES")),
          "the render settings panel shows only with the kiln engine")
    ui.RENDER_PT_kiln.draw(SimpleNamespace(layout=layout), context)
    drawn.update(layout.drawn)
    wanted = {"kiln.add_temperature_attribute", "source", "temperature", "gradient_p0", "gradient_t1", "gradient_space",
              "gradient_extrapolate", "image", "image_tmin", "noise_octaves", "noise_max",
              "attribute_name", "emission", "metal", "samples", "seed", "threads",
              "emission_override", "executable"}
    check(not problems and wanted <= drawn,
          "the kiln panels draw existing properties (%s), missing %s"
          % ("; ".join(problems) or "no problems", sorted(wanted - drawn)))


# ---------------------------------------------------------------------------------------------
# Images

def read_exr(path):
    """(height, width, 3) linear RGB of an EXR, first row at the top."""
    image = bpy.data.images.load(path, check_existing=False)
    try:
        width, height = image.size
        pixels = np.empty(width * height * 4, dtype=np.float32)
        image.pixels.foreach_get(pixels)
    finally:
        bpy.data.images.remove(image)
    return pixels.reshape(height, width, 4)[::-1, :, :3].astype(np.float64)


def render(scene_path, out_path, seed, spp=SPP):
    command = [KILN, scene_path, "-o", out_path, "--spp", str(spp), "--seed", str(seed),
               "--quiet"]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError("%s failed (%d): %s" % (" ".join(command), done.returncode,
                                                   done.stderr))
    return read_exr(out_path)


def sphere_normals():
    """Per pixel: the unit-sphere normal (x, y, z in Blender's world) the pixel centre's
    camera ray hits, and the cosine between it and the direction back to the camera;
    NaN where the ray misses. Camera at (0, -d, 0) looking along +y, +x right, +z up."""
    half_w = SENSOR / 2 / LENS                     # horizontal fit: width spans the sensor
    half_h = half_w * HEIGHT / WIDTH
    cols = ((np.arange(WIDTH) + 0.5) / WIDTH * 2 - 1) * half_w
    rows = (1 - (np.arange(HEIGHT) + 0.5) / HEIGHT * 2) * half_h
    ax, az = np.meshgrid(cols, rows)
    direction = np.stack([ax, np.ones_like(ax), az], axis=-1)
    direction /= np.linalg.norm(direction, axis=-1, keepdims=True)
    origin = np.array([0.0, -CAMERA_DISTANCE, 0.0])
    b = direction @ origin
    disc = b * b - (origin @ origin - 1.0)
    t = -b - np.sqrt(np.where(disc > 0, disc, np.nan))
    normal = origin + t[..., None] * direction
    cosine = -(normal * direction).sum(axis=-1)
    return normal, cosine


def luminance(rgb):
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


class RegionStats:
    """Chromaticity (x = R / (R + G + B), y = G / (R + G + B)) and mean luminance of a pixel
    region of the average of two renders a, b with different seeds, with standard errors
    from the per-pixel differences: a single render's noise variance at a pixel is
    estimated as (a - b)^2 / 2, the average's as a quarter of (a - b)^2, and a region
    quantity's variance follows by linearising it in the pixel values (pixels' noise taken
    as independent)."""

    def __init__(self, a, b, mask):
        mean = (a[mask] + b[mask]) / 2
        diff = a[mask] - b[mask]
        total = mean.sum(axis=0)
        s = total.sum()
        self.x, self.y = total[0] / s, total[1] / s
        self.count = int(mask.sum())
        dsum = diff.sum(axis=1)
        self.sx = math.sqrt(((diff[:, 0] - self.x * dsum) ** 2).sum() / 4) / s
        self.sy = math.sqrt(((diff[:, 1] - self.y * dsum) ** 2).sum() / 4) / s
        lum = luminance(mean)
        self.lum = lum.mean()
        self.slum = math.sqrt((luminance(diff) ** 2).sum() / 4) / self.count


def compare(label, got, want, sigmas=4.0):
    """got and want agree in chromaticity and luminance within `sigmas` standard errors."""
    for name, g, w, sg, sw in (("x", got.x, want.x, got.sx, want.sx),
                               ("y", got.y, want.y, got.sy, want.sy),
                               ("luminance", got.lum, want.lum, got.slum, want.slum)):
        sigma = math.hypot(sg, sw)
        check(abs(g - w) <= sigmas * sigma,
              "%s %s: exported %.6g, reference %.6g, |difference| %.3g <= %g sigma = %.3g"
              % (label, name, g, w, abs(g - w), sigmas, sigmas * sigma))


# ---------------------------------------------------------------------------------------------
# Checks

def check_export(kiln_blender, result, text):
    print("-- the exported file")
    warnings = result.warnings
    print("\n".join("   warning: " + w for w in warnings))
    kinds = result.reports.kinds()
    check(result.reports.items("material-nodes") == ["Glow A", "Glow B"],
          "the two Emission-only materials are one report: %s"
          % result.reports.items("material-nodes"))
    check(sum(w.startswith("2 material(s) use nodes other than") for w in warnings) == 1
          and len(warnings) == len(kinds) == len(set(kinds)),
          "one warning per kind (%d warnings, kinds %s)" % (len(warnings), kinds))
    check(0 <= text.find("Scale -1 1 1") < text.find("LookAt") < text.find("Camera"),
          "Scale -1 1 1 before LookAt and Camera")
    expected_fov = math.degrees(2 * math.atan(SENSOR / 2 / LENS * HEIGHT / WIDTH))
    fov = re.search(r'"float fov" ([0-9.eE+-]+)', text)
    check(fov is not None and abs(float(fov.group(1)) - expected_fov) < 1e-4,
          "perspective camera with fov %.5f (expected %.5f)"
          % (float(fov.group(1)) if fov else float("nan"), expected_fov))
    check('"integer xresolution" %d "integer yresolution" %d' % (WIDTH, HEIGHT) in text,
          "film resolution %dx%d" % (WIDTH, HEIGHT))
    check(re.search(r'Material "conductor"\s+"spectrum eta" "metal-Au-eta" "spectrum k" '
                    r'"metal-Au-k"', text) is not None,
          "the gold material is a conductor with metal-Au-eta / metal-Au-k")
    match = re.search(r'Texture "([^"]+)" "float" "gradient"  # kiln\n((?:.*# kiln\n)+)', text)
    check(match is not None and '"point3 p0" [-0.2 0 0]' in match.group(2) and
          '"point3 p1" [0.2 0 0]' in match.group(2) and '"float t0" 1100' in match.group(2)
          and '"float t1" 1500' in match.group(2) and '"string space" "object"' in
          match.group(2) and '"string extrapolate" "clamp"' in match.group(2),
          "gradient texture with p0, p1, t0, t1, space, extrapolate")
    check(match is not None and '"texture temperature" "%s"  # kiln' % match.group(1) in text,
          "the gold material's temperature is the gradient texture")
    image = re.search(r'Texture "[^"]+" "spectrum" "imagemap"\s+"string filename" "([^"]+)"',
                      text)
    check(image is not None and os.path.isfile(os.path.join(WORKDIR, image.group(1))),
          "checker image as an imagemap texture, file written (%s)"
          % (image.group(1) if image else None))
    for kind in ("noise", "heatmap", "vertexattribute"):
        check('"float" "%s"  # kiln' % kind in text, "a %s temperature texture" % kind)
    check('"string emission" "diffuse"  # kiln' in text, "emission model diffuse written")
    check(text.count("ObjectBegin") == 1 and text.count("ObjectInstance") == 2 and
          'ObjectBegin "Crate mesh"' in text, "the cold linked duplicates are instanced")
    sphere_plys = re.findall(r'"string filename" "([^"]*Sphere[^"]*\.ply)"', text)
    check(len(sphere_plys) == 2 and len(set(sphere_plys)) == 1 and
          "ObjectInstance \"Sphere" not in text,
          "the hot sphere and its hot duplicate are plain shapes sharing one PLY")
    plys = re.findall(r'Shape "plymesh"\s+"string filename" "([^"]+)"', text)
    check(len(plys) >= 8 and all(os.path.isfile(os.path.join(WORKDIR, p)) for p in plys),
          "%d plymesh shapes, all files written" % len(plys))
    header = kiln_blender.ply.read_ply_header(os.path.join(WORKDIR, sphere_plys[0]))
    check("format binary_little_endian 1.0" in header and "property float nx" in header and
          "property float u" in header and "property float temperature" not in header,
          "sphere PLY: binary little-endian, normals, uv, no temperature")
    painted = [p for p in plys if "Plane" in p]
    temperature_plys = [p for p in plys if "property float temperature" in
                        kiln_blender.ply.read_ply_header(os.path.join(WORKDIR, p))]
    check(len(temperature_plys) == 1, "one PLY with the vertex property temperature (%s of %s)"
          % (temperature_plys, painted))


def check_render(scene_path):
    print("-- rendering with kiln and comparing with analytic gold spheres")
    started = time.time()
    exported = [render(scene_path, os.path.join(WORKDIR, "exported-%d.exr" % s), s)
                for s in (1, 2)]

    def reference(temperature, metal="Au"):
        path = os.path.join(WORKDIR, "reference-%s-%d.pbrt" % (metal, temperature))
        fov = math.degrees(2 * math.atan(SENSOR / 2 / LENS * HEIGHT / WIDTH))
        with open(path, "w") as f:
            f.write("# A gold sphere of radius 1 at constant temperature, seen as in the "
                    "Blender scene\n"
                    "LookAt 0 0 -%g  0 0 0  0 1 0\n" % CAMERA_DISTANCE +
                    'Camera "perspective" "float fov" %.9g\n' % fov +
                    'Film "rgb" "integer xresolution" %d "integer yresolution" %d\n'
                    % (WIDTH, HEIGHT) +
                    "WorldBegin\n"
                    'Material "conductor" "spectrum eta" "metal-%s-eta" "spectrum k" '
                    '"metal-%s-k" "float temperature" %g\n' % (metal, metal, temperature) +
                    'Shape "sphere" "float radius" 1\n')
        # other seeds than the exported scene's, so that the two renders' errors are
        # independent and their variances add
        return [render(path, path[:-5] + "-%d.exr" % s, s) for s in (11, 12)]

    hot_reference = reference(T_HOT)
    cold_reference = reference(T_COLD)
    copper = reference(T_HOT, "Cu")
    print("   renders took %.1f s" % (time.time() - started))

    normal, cosine = sphere_normals()
    nx, nz = normal[..., 0], normal[..., 2]
    inside = np.nan_to_num(cosine) >= 0.35
    # Both caps are at constant temperature (the gradient is clamped beyond |x| = 0.2); only
    # upward normals, whose mirror reflections see the black sky, not the floor.
    hot = inside & (np.nan_to_num(nx) >= 0.35) & (np.nan_to_num(nz) >= 0.15)
    cold = hot[:, ::-1]  # the mirror image: same view geometry, object x <= -0.35
    check(hot.sum() > 100, "hot region of %d pixels" % hot.sum())

    hot_got = RegionStats(exported[0], exported[1], hot)
    hot_want = RegionStats(hot_reference[0], hot_reference[1], hot)
    cold_got = RegionStats(exported[0], exported[1], cold)
    cold_want = RegionStats(cold_reference[0], cold_reference[1], cold)
    compare("hot end (1500 K) vs gold sphere at 1500 K:", hot_got, hot_want)
    compare("cold end (1100 K) vs gold sphere at 1100 K:", cold_got, cold_want)
    cu = RegionStats(copper[0], copper[1], hot)
    sigma = math.hypot(hot_got.sx, cu.sx)
    check(abs(hot_got.x - cu.x) > 8 * sigma,
          "the test can tell gold from copper at 1500 K: x %.5f vs copper %.5f (> 8 sigma "
          "= %.3g)" % (hot_got.x, cu.x, 8 * sigma))

    ratio = hot_got.lum / cold_got.lum
    check(ratio > 20, "hot end %.4g times as bright as the cold end (references: %.4g)"
          % (ratio, hot_want.lum / cold_want.lum))
    mean = (exported[0] + exported[1]) / 2
    lum = luminance(mean)
    edges = [-0.6, -0.2, -0.1, 0.0, 0.1, 0.2, 0.6]
    band = inside & (np.nan_to_num(nz) >= 0.15)
    levels = [lum[band & (nx >= lo) & (nx < hi)].mean() for lo, hi in zip(edges, edges[1:])]
    check(all(b > a for a, b in zip(levels[:-1], levels[1:])),
          "brightness rises along the gradient (object x from -0.6 to 0.6): %s"
          % ", ".join("%.3g" % v for v in levels))
    top, bottom = lum[:6].mean(), lum[-6:].mean()
    check(top == 0.0 and bottom > 0.0,
          "black sky at the top of the image (%.3g), lit floor at the bottom (%.3g)"
          % (top, bottom))


def check_interrupt(kiln_blender, scene_path):
    print("-- stopping kiln (SIGINT) during a render")
    runner = kiln_blender.runner
    image = os.path.join(WORKDIR, "interrupted.exr")
    if os.path.exists(image):
        os.remove(image)  # (a WORKDIR used before)
    run = runner.KilnRun(runner.kiln_command(KILN, scene_path, image, 1 << 16, seed=3),
                         cwd=WORKDIR)
    deadline = time.time() + 60
    spp = None
    while time.time() < deadline and run.returncode is None:
        changed, spp = run.poll()
        if changed and spp:
            break
        runner.sleep_briefly(0.05)
    run.stop()
    code = run.wait(timeout=60)
    final = kiln_blender.exr_header.read_attributes(image)
    check(code == 130 and 0 < final.get("samplesPerPixel", 0) < (1 << 16),
          "kiln exits 130 on SIGINT and leaves a partial image (%s spp; status %s)"
          % (final.get("samplesPerPixel"), code))


KILN_TEXTURES = ("gradient", "noise", "heatmap", "vertexattribute")
KILN_PARAMETERS = ("temperature", "emission")
ANSI = re.compile(r"\x1b\[[0-9;]*m")


def remove_directive(lines, start):
    """Remove the directive starting at line index `start` and its continuation lines."""
    end = start + 1
    while end < len(lines) and lines[end].startswith(" ") and not \
            re.match(r"\s*[A-Z][A-Za-z]+\b", lines[end]):
        end += 1
    del lines[start:end]


def check_pbrt(scene_path):
    print("-- pbrt-v4 reads the file, kiln's constructs aside")
    with open(scene_path) as f:
        lines = f.read().split("\n")
    for i, line in enumerate(lines):  # tiny image for pbrt-v4
        lines[i] = re.sub(r'"integer xresolution" \d+ "integer yresolution" \d+',
                          '"integer xresolution" 8 "integer yresolution" 6', line)
    path = os.path.join(WORKDIR, "pbrt-v4.pbrt")
    removed = []
    for attempt in range(60):
        with open(path, "w") as f:
            f.write("\n".join(lines))
        done = subprocess.run([PBRT, "--nthreads", "1", "--spp", "1", "--outfile",
                               os.path.join(WORKDIR, "pbrt-v4.exr"), path],
                              capture_output=True, text=True, cwd=WORKDIR)
        output = ANSI.sub("", done.stdout + done.stderr)
        errors = re.findall(r"Error: [^:]*pbrt-v4\.pbrt:(\d+):\d+: (.*)", output)
        if done.returncode == 0 and not errors:
            break
        if not errors:
            check(False, "pbrt-v4 failed without a located error: %s" % output[-2000:])
            return
        number, message = int(errors[0][0]), errors[0][1]
        line = lines[number - 1]
        texture = re.match(r'\s*Texture "([^"]+)" "float" "(\w+)"', line)
        parameter = re.search(r'"(?:float|texture|string) (\w+)"', line)
        if texture and texture.group(2) in KILN_TEXTURES:
            removed.append("Texture %s" % texture.group(2))
            remove_directive(lines, number - 1)
        elif parameter and parameter.group(1) in KILN_PARAMETERS and \
                line.rstrip().endswith("# kiln"):
            removed.append("parameter %s" % parameter.group(1))
            del lines[number - 1]
        else:
            check(False, "pbrt-v4 error not about a kiln construct: line %d: %s (%s)"
                  % (number, message, line.strip()))
            return
    else:
        check(False, "pbrt-v4 still fails after 60 removals")
        return
    print("   pbrt-v4 reported, one at a time: %s" % ", ".join(sorted(set(removed))))
    check(done.returncode == 0 and os.path.isfile(os.path.join(WORKDIR, "pbrt-v4.exr")),
          "pbrt-v4 renders the file after %d kiln constructs are removed (PLY files with the "
          "vertex property temperature included)" % len(removed))


def main():
    started = time.time()
    bpy.ops.wm.read_factory_settings(use_empty=True)  # (this disables add-ons: enable after)
    kiln_blender = enable_addon()
    import addon_utils
    addon_utils.disable("kiln_blender", default_set=True)
    check(not hasattr(bpy.types.Material, "kiln") and "KILN" not in
          {e.bl_idname for e in bpy.types.RenderEngine.__subclasses__() if e.is_registered},
          "disabling the add-on unregisters it")
    kiln_blender = enable_addon()
    for owner in (bpy.types.Material, bpy.types.Object, bpy.types.Scene):
        check(hasattr(owner, "kiln"), "%s.kiln is registered" % owner.__name__)
    scene = build_scene()
    check(abs(bpy.data.materials["Gold"].kiln.temperature) == 0.0 and
          bpy.data.objects["Hot sphere"].kiln.temperature == 0.0,
          "material.kiln.temperature and object.kiln.temperature exist (0 K by default)")
    check(kiln_blender.metals.guess_metal((1.0, 0.766, 0.336)) == "Au" and
          kiln_blender.metals.guess_metal((0.95, 0.64, 0.54)) == "Cu" and
          kiln_blender.metals.guess_metal((0.56, 0.56, 0.57)) == "Fe",
          "metal guess: gold -> Au, copper -> Cu, grey -> Fe")

    check_panels(kiln_blender)

    scene_path = os.path.join(WORKDIR, "scene.pbrt")
    result = kiln_blender.exporter.export_scene(bpy.context.evaluated_depsgraph_get(),
                                                scene_path)
    with open(scene_path) as f:
        text = f.read()
    check_export(kiln_blender, result, text)
    operator_path = os.path.join(WORKDIR, "operator", "scene.pbrt")
    status = bpy.ops.export_scene.kiln_pbrt(filepath=operator_path)
    check(status == {"FINISHED"} and os.path.isfile(operator_path),
          "the File > Export operator export_scene.kiln_pbrt writes the file")

    check_render(scene_path)
    check_interrupt(kiln_blender, scene_path)
    if PBRT:
        check_pbrt(scene_path)
    else:
        print("-- no pbrt-v4 binary given: skipping the pbrt-v4 check")

    scene.render.engine = "KILN"
    scene.kiln.samples = 16
    blend = os.path.join(WORKDIR, "scene.blend")
    bpy.ops.wm.save_as_mainfile(filepath=blend)
    check(os.path.isfile(blend), "saved %s for the headless render" % blend)
    print("addon_test: %d failure(s), %.1f s" % (len(FAILURES), time.time() - started))
    if FAILURES:
        raise SystemExit("addon_test: FAILED:\n  " + "\n  ".join(FAILURES))


main()
