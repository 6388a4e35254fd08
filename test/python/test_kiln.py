"""Tests of the Python module kiln (run by ctest as Python.Module: pytest with PYTHONPATH set to
the build's python folder and KILN_BINARY to the kiln executable)."""

import math
import os
import subprocess

import numpy as np
import pytest

import kiln

KILN_BINARY = os.environ.get("KILN_BINARY", "kiln")

# A hot gold sphere (named material "gold", 1000 K) over a cold diffuse floor, lit by nothing else.
# The sphere covers the image's centre (SPHERE), the floor its lowest rows (FLOOR).
SCENE = """
LookAt 0 1.2 -5  0 0.6 0  0 1 0
Camera "perspective" "float fov" 30
Film "rgb" "integer xresolution" 48 "integer yresolution" 36 "string filename" "scene.exr"
Sampler "zsobol" "integer pixelsamples" 16
WorldBegin
MakeNamedMaterial "gold" "string type" "conductor"
    "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k" "float roughness" 0.1
    "float temperature" {temperature}
Texture "floor-heat" "float" "constant" "float value" 0
MakeNamedMaterial "floor" "string type" "diffuse" "rgb reflectance" [0.5 0.5 0.5]
    "texture temperature" "floor-heat"
AttributeBegin
  NamedMaterial "gold"
  Translate 0 0.6 0
  Shape "sphere" "float radius" 0.6
AttributeEnd
ObjectBegin "slab"
  NamedMaterial "floor"
  Shape "bilinearmesh" "point3 P" [-3 0 -3 3 0 -3 -3 0 3 3 0 3]
ObjectEnd
ObjectInstance "slab"
"""

GOLD = {"spectrum eta": "metal-Au-eta", "spectrum k": "metal-Au-k"}


SPHERE = (slice(14, 22), slice(20, 28))
FLOOR = (slice(31, 36), slice(0, 48))


def scene_text(temperature=1000):
    return SCENE.replace("{temperature}", str(temperature))


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.pbrt"
    path.write_text(scene_text())
    return path


def fresnel_conductor(cos_i, eta, k):
    """Reflectance of a smooth conductor (n = eta + i k) for s and p polarisation."""
    n = complex(eta, k)
    sin2 = 1 - cos_i * cos_i
    cos_t = np.sqrt(1 - sin2 / (n * n))
    rs = (cos_i - n * cos_t) / (cos_i + n * cos_t)
    rp = (n * cos_i - cos_t) / (n * cos_i + cos_t)
    return abs(rs) ** 2, abs(rp) ** 2


# The interface outside tests rely on (issue 25), as written there

def test_the_documented_interface(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "scene.pbrt").write_text(scene_text())
    scene = kiln.load("scene.pbrt")
    img = scene.render(spp=16, seed=1)
    assert img.dtype == np.float32 and img.shape == (36, 48, 3)
    scene.set_temperature("gold", 1500)
    img2 = scene.render(spp=16, seed=1)
    # Planck at 600 nm: B(1500 K) / B(1000 K) = 1600; the glow is far brighter where gold is
    assert img2[SPHERE].mean() > 20 * img[SPHERE].mean()
    e = kiln.emissivity("conductor", {"spectrum eta": "metal-Au-eta",
                                      "spectrum k": "metal-Au-k"}, theta=0.0, wavelength=600.0)
    assert 0.05 < e < 0.12
    assert isinstance(kiln.load_string(scene_text()), kiln.Scene)


# Rendering

def test_render_agrees_with_the_kiln_binary(scene_file, tmp_path):
    """The same scene rendered by the binary with another seed: the per-pixel differences have
    mean zero within their standard error; with the same seed the images are the same."""
    scene = kiln.load(scene_file)
    ours = scene.render(spp=64, seed=1)
    for seed, name in ((1, "same.exr"), (2, "other.exr")):
        subprocess.run([KILN_BINARY, str(scene_file), "--spp", "64", "--seed", str(seed),
                        "-o", str(tmp_path / name), "--quiet"], check=True)
    # The binary's EXR (half floats) of the same seed: the same render to half precision
    same = kiln.read_image(str(tmp_path / "same.exr"))
    assert same.metadata["samples_per_pixel"] == 64 and same.metadata["seed"] == 1
    np.testing.assert_allclose(same.array(["R", "G", "B"]), ours, rtol=1e-3, atol=1e-7)
    theirs = kiln.load_string(scene_text()).render(spp=64, seed=2)
    # Means of 4 x 4 blocks: the film spreads each sample over the pixels within the filter's
    # radius, so neighbouring pixels' differences are correlated
    h, w = ours.shape[0] // 4 * 4, ours.shape[1] // 4 * 4
    d = (ours - theirs)[:h, :w].reshape(h // 4, 4, w // 4, 4, 3).mean(axis=(1, 3)).reshape(-1, 3)
    n = d.shape[0]
    for c in range(3):
        z = d[:, c].mean() / (d[:, c].std(ddof=1) / math.sqrt(n))
        assert abs(z) < 4.5, f"channel {c}: mean difference {z:.2f} standard errors from 0"


def test_reconstruction_spread_or_as_pbrt_v4(scene_file):
    """Samples spread over the pixels within the filter's radius (default) or drawn from the
    filter for one pixel (pbrt-v4): the same image, less per-pixel noise spread."""
    scene = kiln.load(scene_file)
    spread = [scene.render(spp=16, seed=s) for s in (1, 2)]
    importance = [scene.render(spp=16, seed=s, reconstruction="importance") for s in (1, 2)]
    def mean_and_error(a, b):
        # the mean of both seeds; its standard error from 4 x 4 blocks of their difference
        h, w = a.shape[0] // 4 * 4, a.shape[1] // 4 * 4
        d = (a - b)[:h, :w].reshape(h // 4, 4, w // 4, 4, 3).mean(axis=(1, 3))
        return (a.mean() + b.mean()) / 2, math.sqrt((d ** 2).mean() / d[..., 0].size) / 2
    var_spread = ((spread[0] - spread[1]) ** 2).mean() / 2
    var_importance = ((importance[0] - importance[1]) ** 2).mean() / 2
    assert var_spread < 0.7 * var_importance
    (m_s, e_s), (m_i, e_i) = mean_and_error(*spread), mean_and_error(*importance)
    assert abs(m_s - m_i) < 5 * math.hypot(e_s, e_i)
    with pytest.raises(ValueError, match="reconstruction"):
        scene.render(spp=1, reconstruction="splat")


def test_set_temperature_recreates_without_reading_the_file(scene_file):
    scene = kiln.load(scene_file)
    scene.render(spp=4, seed=3)
    os.remove(scene_file)  # the file is gone: nothing can be parsed again
    scene.set_temperature("gold", 1300)
    edited = scene.render(spp=16, seed=3)
    fresh = kiln.load_string(scene_text(1300)).render(spp=16, seed=3)
    np.testing.assert_array_equal(edited, fresh)


def test_set_temperature_of_a_texture_an_object_and_a_shape():
    # Wavelengths by the visible density, the same whatever glows, so that renders with one seed
    # differ only by what the edits change (the sphere's own glow is a small part of its pixels)
    scene = kiln.load_string(scene_text().replace(
        "WorldBegin", 'Integrator "volpath" "string wavelengthsampling" "visible"\nWorldBegin'))
    assert scene.names == {"materials": ["gold", "floor"], "textures": ["floor-heat"],
                           "objects": ["slab"], "shapes": 1}
    cold = scene.render(spp=8, seed=5, emission="diffuse")
    scene.set_temperature("floor-heat", 1200)
    warm = scene.render(spp=8, seed=5, emission="diffuse")
    # Blackbody emission at 1200 K: B(600 nm) = 4.3e-3 W m^-2 sr^-1 nm^-1, where the floor was black
    assert warm[FLOOR].mean() > cold[FLOOR].mean() + 1e-3
    # The object's shapes take their own temperature over their material's
    scene.set_temperature("slab", 1500, kind="object")
    hotter = scene.render(spp=8, seed=5, emission="diffuse")
    assert hotter[FLOOR].mean() > 10 * warm[FLOOR].mean()
    # The sphere (shape 0) at 0 K does not glow. (Emitting as a blackbody that reflects
    # nothing, the sphere's pixels show its own glow alone: with Kirchhoff emission gold's
    # reflectance changes with its temperature too, metal_temperature.h)
    glowing = scene.render(spp=8, seed=5, emission="diffuse")
    scene.set_shape_temperature(0, 0)
    dark = scene.render(spp=8, seed=5, emission="diffuse")
    assert dark[SPHERE].mean() < 0.5 * glowing[SPHERE].mean()


def test_frames_follow_the_animation_without_reloading():
    text = scene_text().replace(
        '"float temperature" 1000',
        '"texture temperature" "cooling-gold"').replace(
        'MakeNamedMaterial "gold"',
        'Texture "cooling-gold" "float" "keyframes" "float times" [0 2] '
        '"float values" [1400 900]\nMakeNamedMaterial "gold"')
    scene = kiln.load_string(text)
    early = scene.render(spp=8, seed=2, frame=0)
    late = scene.render(spp=8, seed=2, frame=36)  # 1.5 s at 24 frames per second
    fresh = kiln.load_string(text).render(spp=8, seed=2, frame=36)
    np.testing.assert_array_equal(late, fresh)
    assert late.mean() < 0.5 * early.mean()
    by_time = scene.render(spp=8, seed=2, time=1.5)
    np.testing.assert_array_equal(by_time, late)


def test_emission_model_crop_and_image_channels(tmp_path):
    scene = kiln.load_string(scene_text(1400))
    kirchhoff = scene.render(spp=16, seed=4)
    additive = scene.render(spp=16, seed=4, emission="additive")
    # Gold emits 1 - R (a few percent to 60 %); additive emits all of B
    assert additive[SPHERE].mean() > 2 * kirchhoff[SPHERE].mean()
    crop = scene.render(spp=16, seed=4, crop=(0.25, 0.75, 0.0, 0.5))
    assert crop.shape == (18, 24, 3)
    polarised = scene.render(spp=16, seed=4, stokes=True)
    image = scene.image()
    assert {"R", "G", "B", "S0.R", "S1.R", "S2.R", "S3.R"} <= set(image.channels)
    np.testing.assert_allclose(image["S0.R"], polarised[:, :, 0], rtol=1e-6, atol=0)
    assert image.array(["R", "G"]).shape == (36, 48, 2)
    meta = image.metadata
    assert meta["samples_per_pixel"] == 16 and meta["seed"] == 4
    assert meta["full_resolution"] == (48, 36)
    out = tmp_path / "glow.png"
    scene.write(str(out), view="Glow")
    assert kiln.read_image(str(out)).array().shape == (36, 48, 3)
    scene.write(str(tmp_path / "stokes.exr"))
    back = kiln.read_image(str(tmp_path / "stokes.exr"))
    assert set(image.channels) <= set(back.channels)
    np.testing.assert_allclose(back["S1.R"], image["S1.R"], rtol=1e-3, atol=1e-7)
    with pytest.raises(KeyError):
        image["nope"]


# Material queries

@pytest.mark.parametrize("metal", ["Au", "Cu", "W"])
def test_smooth_metal_emissivity_is_one_minus_fresnel(metal):
    params = {"spectrum eta": f"metal-{metal}-eta", "spectrum k": f"metal-{metal}-k"}
    for wavelength in (450.0, 600.0, 750.0):
        eta = float(kiln.named_spectrum(f"metal-{metal}-eta", wavelength))
        k = float(kiln.named_spectrum(f"metal-{metal}-k", wavelength))
        for theta in (0.0, 0.7, 1.3):
            rs, rp = fresnel_conductor(math.cos(theta), eta, k)
            es, ep = kiln.emissivity("conductor", params, theta, wavelength, polarized=True)
            assert es == pytest.approx(1 - rs, abs=2e-5)
            assert ep == pytest.approx(1 - rp, abs=2e-5)
            e = kiln.emissivity("conductor", params, theta, wavelength)
            assert e == pytest.approx(1 - (rs + rp) / 2, abs=2e-5)
    # Arrays broadcast
    curve = kiln.emissivity("conductor", params, np.linspace(0, 1.5, 7), 600.0)
    assert curve.shape == (7,)


def test_named_metals_follow_the_surface_temperature_into_the_infrared():
    W = {"spectrum eta": "metal-W-eta", "spectrum k": "metal-W-k"}
    # Tungsten at its melting point through a 653 nm pyrometer: measured 3208 +- 10 K
    # (Cezairliyan and Miiller 1982); kiln's hot tungsten is fitted to other measurements
    e = kiln.emissivity("conductor", W, 0.0, 653.0, temperature=3695.0)
    T = kiln.radiance_temperature(653.0, e * kiln.planck(653.0, 3695.0))
    assert abs(T - 3208) < 15
    assert kiln.emissivity("conductor", W, 0.0, 653.0) > e + 0.08  # the room's constants
    # Beyond the visible: polished gold at 10 um, and more emissive when hot (electrons
    # scatter more)
    gold = kiln.emissivity("conductor", GOLD, 0.0, 10000.0)
    assert 0.008 < gold < 0.02
    assert kiln.emissivity("conductor", GOLD, 0.0, 10000.0, temperature=600.0) > 1.3 * gold
    # Arrays of temperatures broadcast
    assert kiln.emissivity("conductor", W, 0.0, 653.0, temperature=[1000.0, 2000.0]).shape == (2,)
    for bad in ({"wavelength": 25000.0}, {"wavelength": 600.0, "temperature": -1.0}):
        with pytest.raises(ValueError):
            kiln.emissivity("conductor", W, 0.0, **bad)


def test_other_materials():
    assert kiln.emissivity("diffuse", {"rgb reflectance": [0.3, 0.3, 0.3]}) == \
        pytest.approx(0.7, abs=0.02)
    assert kiln.emissivity("dielectric", {"float eta": 1.5}, theta=0.5) == 0
    rough = kiln.directional_albedo("conductor", {**GOLD, "float roughness": 0.3}, 0.3, 600.0)
    smooth = kiln.directional_albedo("conductor", GOLD, 0.3, 600.0)
    assert 0.5 < rough < smooth <= 1  # single scattering loses energy
    coated = kiln.emissivity("coateddiffuse", {"rgb reflectance": [0.2, 0.4, 0.6]}, 0.2, 500.0)
    assert 0 < coated < 1


def test_radiance_temperatures_invert_planck():
    # A pyrometer at 653 nm reads a blackbody's own temperature, and a grey body cooler (Wien:
    # 1/T_r = 1/T - lambda/c2 ln e)
    T = np.array([300.0, 1300.0, 3695.0])
    assert kiln.radiance_temperature(653.0, kiln.planck(653.0, T)) == pytest.approx(T, rel=1e-10)
    c2 = 6.62607015e-34 * 299792458.0 / 1.380649e-23
    wien = 1 / (1 / 3695.0 - 653e-9 / c2 * math.log(0.4))
    assert kiln.radiance_temperature(653.0, 0.4 * kiln.planck(653.0, 3695.0)) == pytest.approx(
        wien, abs=2)
    assert kiln.radiance_temperature(653.0, 0.0) == 0
    # A thermal camera over 8-14 um: the band radiance of 300 K, by the midpoint rule over 1 nm
    lam = np.arange(8000.0, 14000.0) + 0.5
    band = kiln.planck(lam, 300.0).sum()
    assert kiln.band_radiance_temperature(8000.0, 14000.0, band) == pytest.approx(300.0, abs=1e-3)


def test_planck_and_glow_colours():
    c2 = 6.62607015e-34 * 299792458.0 / 1.380649e-23
    for lam, T in ((500.0, 1000.0), (1000.0, 3000.0), (360.0, 6000.0)):
        l = lam * 1e-9
        expected = 2 * 6.62607015e-34 * 299792458.0 ** 2 / l ** 5 / math.expm1(c2 / (l * T)) * 1e-9
        assert kiln.planck(lam, T) == pytest.approx(expected, rel=1e-12)
    assert kiln.planck(550.0, 0.0) == 0
    # CIE illuminant A is a Planckian radiator at 2856 K: x = 0.44757, y = 0.40745 (CIE 015)
    a = kiln.glow_color(2856)
    assert a.xy[0] == pytest.approx(0.44757, abs=5e-4)
    assert a.xy[1] == pytest.approx(0.40745, abs=5e-4)
    # Gold glows yellower than a blackbody at the same temperature (its emissivity is higher in
    # blue and green)
    black = kiln.glow_color(1300)
    gold = kiln.glow_color(1300, "conductor", GOLD)
    assert gold.xy[1] > black.xy[1] and gold.srgb_display[1] > black.srgb_display[1]
    assert max(black.srgb_display) == 255


# Bad input

def test_bad_input_raises_located_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        kiln.load(tmp_path / "missing.pbrt")
    bad = 'WorldBegin\nMaterial "diffuse" "rgb reflectance" [2 0 0]\n'
    with pytest.raises(kiln.SceneError, match=r"<string>:2:\d+: .*reflectance"):
        kiln.load_string(bad)
    (tmp_path / "bad.pbrt").write_text(bad)
    with pytest.raises(ValueError, match=r"bad\.pbrt:2:\d+: "):
        kiln.load(tmp_path / "bad.pbrt")
    with pytest.raises(kiln.SceneError, match="temprature"):
        kiln.emissivity("conductor", {**GOLD, "float temprature": 3})
    scene = kiln.load_string(scene_text())
    with pytest.raises(KeyError, match="materials: \"gold\", \"floor\""):
        scene.set_temperature("silver", 1000)
    with pytest.raises(KeyError, match="finite"):
        scene.set_temperature("gold", float("nan"))
    with pytest.raises(IndexError):
        scene.set_shape_temperature(3, 1000)
    with pytest.raises(ValueError, match="crop"):
        scene.render(spp=1, crop=(0.5, 0.2, 0, 1))
    with pytest.raises(ValueError, match="emission"):
        scene.render(spp=1, emission="glowing")
    with pytest.raises(RuntimeError, match="nothing rendered"):
        scene.write(str(tmp_path / "x.exr"))
    scene.render(spp=1)
    with pytest.raises(RuntimeError, match="no-such-folder"):
        scene.write(str(tmp_path / "no-such-folder" / "x.exr"))
    with pytest.raises(ValueError, match="wavelength"):
        kiln.emissivity("conductor", GOLD, 0.0, 25000.0)


def test_a_thermal_film_renders_radiance_and_temperature():
    """Film "thermal": render returns L (in-band radiance) and T (the reported temperature)."""
    scene = kiln.load_string("""
Option "float ambienttemperature" 300
Film "thermal" "string sensor" "lwir" "integer xresolution" 8 "integer yresolution" 6
Sampler "zsobol" "integer pixelsamples" 16
LookAt 0 0 -3 0 0 0 0 1 0
Camera "perspective" "float fov" 40
WorldBegin
Material "diffuse" "spectrum reflectance" [300 0.5 20000 0.5]
Shape "sphere" "float radius" 10
""")
    image = scene.render(seed=1)
    assert image.shape == (6, 8, 2)
    L, T = image[..., 0], image[..., 1]
    # A closed room at 300 K is a blackbody: 8-14 um radiance and temperature
    lam = np.linspace(8000.0, 14000.0, 6001)
    band = np.trapz(kiln.planck(lam, 300.0), lam)
    assert abs(L.mean() / band - 1) < 0.02
    assert abs(T.mean() - 300) < 2
