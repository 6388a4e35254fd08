"""Turning an equirectangular (latitude-longitude) environment image into the square
equal-area octahedral map that pbrt-v4's ``infinite`` light reads. Needs only numpy.

Directions are Blender world directions (+z up). The equirectangular image is read as
Blender's Environment Texture node reads it: column u = 0.5 - atan2(y, x) / (2 pi) and row
v = 0.5 + asin(z) / pi from the bottom, so +x is the middle of the image and +z its top row.
The square map is pbrt-v4's equal-area (Clarberg) octahedral parameterisation of the sphere
in the light's space; the light is written with the identity transform, so light space is the
Blender world.
"""

import math

import numpy as np


def equal_area_square_to_sphere(u, v):
    """Directions (x, y, z arrays) of points (u, v) in [0, 1]^2 of the equal-area square
    (Clarberg's mapping, as pbrt-v4's EqualAreaSquareToSphere): the centre of the square is
    +z, its corners -z, its edge midpoints the equator."""
    a = 2.0 * np.asarray(u, dtype=np.float64) - 1.0
    b = 2.0 * np.asarray(v, dtype=np.float64) - 1.0
    abs_a, abs_b = np.abs(a), np.abs(b)
    signed_distance = 1.0 - (abs_a + abs_b)
    r = 1.0 - np.abs(signed_distance)
    with np.errstate(divide="ignore", invalid="ignore"):
        phi = np.where(r == 0, 1.0, (abs_b - abs_a) / np.where(r == 0, 1.0, r) + 1.0) * math.pi / 4
    z = np.copysign(1.0 - r * r, signed_distance)
    cos_phi = np.copysign(np.cos(phi), a)
    sin_phi = np.copysign(np.sin(phi), b)
    scale = r * np.sqrt(np.maximum(0.0, 2.0 - r * r))
    return cos_phi * scale, sin_phi * scale, z


def sample_equirectangular(image, x, y, z):
    """Bilinear lookup of ``image`` ((height, width, channels), first row at the top) in the
    directions (x, y, z), with Blender's equirectangular layout (see the module); the image
    wraps around horizontally and is clamped at the poles."""
    height, width = image.shape[:2]
    u = (0.5 - np.arctan2(y, x) / (2 * math.pi)) % 1.0
    v = 0.5 + np.arcsin(np.clip(z, -1.0, 1.0)) / math.pi
    # continuous pixel coordinates (column from the left, row from the top), centres at +0.5
    col = u * width - 0.5
    row = (1.0 - v) * height - 0.5
    c0 = np.floor(col).astype(np.int64)
    r0 = np.floor(row).astype(np.int64)
    fc = (col - c0)[..., None]
    fr = (row - r0)[..., None]
    c1 = (c0 + 1) % width
    c0 = c0 % width
    r1 = np.clip(r0 + 1, 0, height - 1)
    r0 = np.clip(r0, 0, height - 1)
    top = image[r0, c0] * (1 - fc) + image[r0, c1] * fc
    bottom = image[r1, c0] * (1 - fc) + image[r1, c1] * fc
    return top * (1 - fr) + bottom * fr


def square_size_for(height):
    """Side of the square map for an equirectangular image ``height`` pixels tall: about the
    same solid angle per pixel as the source at its equator (N^2 = 4 h^2 / pi), 16 to 4096."""
    return int(min(4096, max(16, round(2.0 * height / math.sqrt(math.pi)))))


def equirectangular_to_equal_area(image, size=None):
    """The square equal-area map ((size, size, 3), first row at the top) of an
    equirectangular ``image`` ((height, width, >= 3) linear values, first row at the top).
    Pixel (row i, column j) holds the source's value in the direction of the square's point
    ((j + 0.5) / size, (i + 0.5) / size)."""
    image = np.asarray(image, dtype=np.float64)[:, :, :3]
    if size is None:
        size = square_size_for(image.shape[0])
    centres = (np.arange(size) + 0.5) / size
    u, v = np.meshgrid(centres, centres)  # u along columns, v along rows
    x, y, z = equal_area_square_to_sphere(u, v)
    return sample_equirectangular(image, x, y, z).astype(np.float32)
