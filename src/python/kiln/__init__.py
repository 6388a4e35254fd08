"""kiln: render pbrt-v4 scenes with glowing hot matter, and query materials, from Python.

    import kiln
    scene = kiln.load("scene.pbrt")            # kiln.load_string(text) for scene text
    img = scene.render(spp=16, seed=1)         # float32 array, height x width x 3, linear RGB
    scene.set_temperature("gold", 1500)        # a named material, float texture or object, K
    img2 = scene.render(spp=16, seed=1)        # the scene is created again, not re-parsed
    kiln.emissivity("conductor", {"spectrum eta": "metal-Au-eta", "spectrum k": "metal-Au-k"},
                    theta=0.0, wavelength=600.0)   # 1 - directional albedo

Scene.render(spp, seed, threads, crop, frame, time, fps, emission, stokes) renders and returns the
R, G, B channels; Scene.image() is the last render with every channel the film records (AOVs,
Stokes layers S0.R ... S3.B) and its metadata; Scene.write(path, view=...) writes it as the kiln
command writes its outputs; kiln.read_image(path) reads one back. Errors in scene text raise kiln.SceneError (a ValueError) whose
message starts with file:line:column.

Units: wavelengths in nm, temperatures in kelvin, angles in radians from the surface normal,
radiance in W m^-2 sr^-1 nm^-1.
"""

import math
import os
import sys
from collections import namedtuple

from . import _kiln  # before numpy: a Python that cannot load the extension fails here

try:
    import numpy as np
except ModuleNotFoundError:
    # The extension loaded, so this is a CPython of the version it was built for; Debian's
    # python3-numpy for that version is in /usr/lib/python3/dist-packages, which only Debian's
    # own interpreter searches (another build of it, e.g. pyenv's, does not)
    sys.path.append("/usr/lib/python3/dist-packages")
    import numpy as np

from ._kiln import Image, Scene, SceneError, read_image

__all__ = ["load", "load_string", "read_image", "Scene", "Image", "SceneError", "emissivity",
           "directional_albedo", "planck", "radiance_temperature", "band_radiance_temperature",
           "named_spectrum", "glow_color", "GlowColor",
           "material_parameters"]


def load(path):
    """Parses the pbrt-v4 scene file `path` (.pbrt or .pbrt.gz) and creates the scene.

    Raises FileNotFoundError when the file does not exist and kiln.SceneError (file:line:column:
    error: message) for invalid scene text."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(2, "no scene file", path)
    return _kiln._load(path)


def load_string(text, directory=""):
    """Parses scene text; relative file names in it resolve against `directory` (default: the
    working directory). Errors are reported at "<string>":line:column."""
    return _kiln._load_string(text, os.fspath(directory))


def material_parameters(params):
    """A parameter dict {"spectrum eta": "metal-Au-eta", "float roughness": 0.1, ...} in scene-
    file syntax. Values: a string, a number, a bool, or a sequence of them."""
    def value(v):
        if isinstance(v, (bool, np.bool_)):
            return "true" if v else "false"
        if isinstance(v, str):
            if '"' in v or "\n" in v:
                raise ValueError(f"parameter value {v!r}: quotes and newlines are not allowed")
            return f'"{v}"'
        if isinstance(v, (int, float, np.integer, np.floating)):
            if not math.isfinite(float(v)):
                raise ValueError(f"parameter value {v!r} is not finite")
            return repr(float(v)) if isinstance(v, (float, np.floating)) else str(int(v))
        return "[ " + " ".join(value(x) for x in v) + " ]"

    parts = []
    for declaration, v in (params or {}).items():
        if '"' in declaration or len(declaration.split()) != 2:
            raise ValueError(f'parameter {declaration!r}: expected "type name", e.g. "float roughness"')
        parts.append(f'"{declaration}" {value(v)}')
    return " ".join(parts)


def _probe(material, params):
    return _kiln._MaterialProbe(material, material_parameters(params))


def directional_albedo(material, params=None, theta=0.0, wavelength=550.0, polarized=False,
                       temperature=None):
    """The directional-hemispherical reflectance A(theta, wavelength) of a pbrt-v4 material
    ("diffuse", "conductor", "dielectric", "coateddiffuse", "coatedconductor", ...) made from
    `params`, as kiln's thermal module computes it (closed forms and load-time tables, no Monte
    Carlo). theta in radians from the normal, wavelength in nm (300-20000: the visible range's
    tables within 360-830 nm, as a render of the visible, those of Film "thermal" beyond);
    both may be arrays. temperature (K, may be an array): the surface's, for the conductors
    whose named optical constants follow it (metal-W, metal-Au, metal-Ag); None: the named
    tables. polarized=True returns (R_s, R_p), the reflectance of light polarised perpendicular
    and parallel to the plane of incidence (their mean is A)."""
    p = _probe(material, params)
    T = 0.0 if temperature is None else temperature
    if polarized:
        return p.albedo_s(theta, wavelength, T), p.albedo_p(theta, wavelength, T)
    return p.albedo(theta, wavelength, T)


def emissivity(material, params=None, theta=0.0, wavelength=550.0, polarized=False,
               temperature=None):
    """Kirchhoff's emissivity 1 - A(theta, wavelength) of the material (see directional_albedo,
    also for temperature): a hot surface of it emits B(wavelength, T) times this.
    polarized=True returns (e_s, e_p) = (1 - R_s, 1 - R_p): the emission polarised
    perpendicular and parallel to the plane of emission, each relative to half the
    blackbody's."""
    if polarized:
        rs, rp = directional_albedo(material, params, theta, wavelength, polarized=True,
                                    temperature=temperature)
        return 1 - rs, 1 - rp
    return 1 - directional_albedo(material, params, theta, wavelength, temperature=temperature)


def planck(wavelength, temperature):
    """Blackbody spectral radiance B(wavelength nm, temperature K), W m^-2 sr^-1 nm^-1; arrays
    broadcast. 0 for temperature <= 0."""
    return _kiln._planck(wavelength, temperature)


def radiance_temperature(wavelength, radiance):
    """What a narrow-band pyrometer at wavelength (nm) reads from spectral radiance (W m^-2 sr^-1
    nm^-1): the temperature (K) of the blackbody as bright there, planck inverted; arrays
    broadcast. 0 for radiance <= 0."""
    return _kiln._radiance_temperature(wavelength, radiance)


def band_radiance_temperature(wavelength_low, wavelength_high, radiance):
    """What a thermal camera with a flat response over [wavelength_low, wavelength_high] (nm)
    reads from the band's radiance (W m^-2 sr^-1): the temperature (K) of the blackbody with
    that band radiance; arrays broadcast. 0 for radiance <= 0."""
    return _kiln._band_radiance_temperature(wavelength_low, wavelength_high, radiance)


def named_spectrum(name, wavelength):
    """kiln's named spectrum (e.g. "metal-Au-eta", "metal-W-k", "glass-BK7") at wavelength nm."""
    return _kiln._named_spectrum(name, np.asarray(wavelength, dtype=np.float64))


GlowColor = namedtuple("GlowColor", ["xy", "XYZ", "srgb", "srgb_display"])
GlowColor.__doc__ = """The colour of a glow.
xy: CIE 1931 chromaticity. XYZ: tristimulus values of the emitted radiance (Y in W m^-2 sr^-1
weighted by ybar, i.e. the integral of L ybar over nm divided by the integral of ybar, as kiln's
film). srgb: linear sRGB scaled to luminance Y = 1 (components may be negative outside the
gamut). srgb_display: the 8-bit sRGB colour of that hue at full brightness, out-of-gamut colours
mixed with the grey of equal luminance until they fit (as kiln's display transform keeps glow
hues), then scaled so the largest channel is 1."""


def glow_color(temperature, material=None, params=None, theta=0.0):
    """The colour of a surface glowing at `temperature` K, seen at theta (radians from the
    normal): Planck's radiance times the material's emissivity at that temperature (a blackbody
    when material is None), integrated against the CIE 1931 observer over 360-830 nm at 1 nm."""
    lam = np.arange(_kiln._lambda_min, _kiln._lambda_max + 1.0)
    radiance = planck(lam, float(temperature))
    if material is not None:
        radiance = radiance * emissivity(material, params, theta, lam,
                                         temperature=float(temperature))
    cmf = _kiln._cie_xyz(lam)
    XYZ = (radiance[:, None] * cmf).sum(axis=0) / _kiln._cie_y_integral
    total = XYZ.sum()
    if not total > 0:
        raise ValueError(f"nothing glows at {temperature} K")
    xy = (XYZ[0] / total, XYZ[1] / total)
    rgb = np.array(_kiln._xyz_to_srgb(*(XYZ / XYZ[1])))
    # Mix with the grey of equal luminance until no channel is negative
    luminance = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
    display = rgb
    if rgb.min() < 0:
        t = luminance / (luminance - rgb.min())
        display = luminance + t * (rgb - luminance)
    display = np.clip(display / display.max(), 0, 1)
    encoded = np.where(display <= 0.0031308, 12.92 * display,
                       1.055 * np.power(display, 1 / 2.4) - 0.055)
    srgb8 = tuple(int(round(255 * c)) for c in encoded)
    return GlowColor(xy=xy, XYZ=tuple(XYZ), srgb=tuple(rgb), srgb_display=srgb8)
