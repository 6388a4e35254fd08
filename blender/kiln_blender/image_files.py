"""Writing image files for the exported scene: 8-bit PNG and float PFM from pixel arrays,
and copying Blender images (file, packed or generated) next to the scene.

``write_png`` and ``write_pfm`` need only numpy; ``ImageWriter`` takes bpy Image objects.
"""

import os
import shutil
import struct
import zlib

import numpy as np


def write_png(path, pixels):
    """Write ``pixels`` ((height, width, 4) floats in [0, 1], first row at the top) as an
    8-bit RGBA PNG. Values are clipped to [0, 1] and rounded to the nearest code value;
    they are stored as given (no colour transfer function is applied)."""
    pixels = np.asarray(pixels, dtype=np.float64)
    height, width = pixels.shape[:2]
    codes = np.clip(np.rint(pixels[:, :, :4] * 255.0), 0, 255).astype(np.uint8)
    rows = np.concatenate([np.zeros((height, 1), np.uint8), codes.reshape(height, width * 4)],
                          axis=1)  # filter type 0 at the start of each row

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", header))
        f.write(chunk(b"IDAT", zlib.compress(rows.tobytes(), 6)))
        f.write(chunk(b"IEND", b""))


def write_pfm(path, rgb):
    """Write ``rgb`` ((height, width, 3) floats, first row at the top) as a little-endian
    colour PFM (whose rows are stored bottom to top)."""
    rgb = np.asarray(rgb, dtype="<f4")
    height, width = rgb.shape[:2]
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
        f.write(np.ascontiguousarray(rgb[::-1, :, :3]).tobytes())


def image_pixels(image):
    """A Blender image's pixels as a (height, width, 4) float array, first row at the top.
    Byte images give their stored code values / 255, float images their linear values
    (Blender's own convention for ``Image.pixels``)."""
    width, height = image.size
    flat = np.empty(width * height * 4, dtype=np.float32)
    image.pixels.foreach_get(flat)
    return flat.reshape(height, width, 4)[::-1]


def srgb_to_linear(values):
    """The sRGB transfer function inverted (code value in [0, 1] to linear)."""
    values = np.asarray(values, dtype=np.float64)
    return np.where(values <= 0.04045, values / 12.92, ((values + 0.055) / 1.055) ** 2.4)


def safe_name(text):
    """A file-name-safe version of ``text``: letters, digits, '-', '_' and '.' kept, every
    other character replaced by '_'."""
    cleaned = "".join(c if (c.isalnum() or c in "-_.") else "_" for c in text)
    return cleaned.strip(".") or "unnamed"


class ImageWriter:
    """Puts Blender images into one folder next to the scene file, each image once.

    ``folder`` is the absolute folder, ``relative`` the same folder as the scene file names it
    (e.g. ``scene_textures``). ``path_of(image)`` returns the scene-relative path of the
    image's file, or None if it could not be written:
      - an image read from an existing file is copied (its format kept);
      - a packed image is written from its packed bytes;
      - a generated or otherwise unsaved image is written from its pixels: float images as
        PFM, byte images as PNG.
    Sequences, movies and tiled (UDIM) images are not written (None).
    """

    def __init__(self, folder, relative):
        self.folder = folder
        self.relative = relative
        self._done = {}
        self._used = set()

    def _target(self, stem, extension):
        name = safe_name(stem) + extension
        base, n = name, 1
        while name in self._used:
            n += 1
            name = "%s-%d%s" % (os.path.splitext(base)[0], n, extension)
        self._used.add(name)
        os.makedirs(self.folder, exist_ok=True)
        return name

    def path_of(self, image):
        """The scene-relative path of ``image``'s exported file, or None (see the class)."""
        key = image.name_full if hasattr(image, "name_full") else image.name
        if key in self._done:
            return self._done[key]
        result = self._write(image)
        self._done[key] = result
        return result

    def _write(self, image):
        if image.source in ("SEQUENCE", "MOVIE", "TILED"):
            return None
        import bpy  # only here: the rest of the module works without Blender
        source = bpy.path.abspath(image.filepath, library=image.library) if image.filepath else ""
        extension = os.path.splitext(source)[1].lower()
        stem = os.path.splitext(os.path.basename(source))[0] if source else image.name
        if image.packed_file is not None:
            name = self._target(stem, extension or ".png")
            with open(os.path.join(self.folder, name), "wb") as f:
                f.write(bytes(image.packed_file.data))
            return self.relative + "/" + name
        if image.source == "FILE" and source and os.path.isfile(source):
            name = self._target(stem, extension)
            shutil.copyfile(source, os.path.join(self.folder, name))
            return self.relative + "/" + name
        if image.has_data or image.source == "GENERATED":
            pixels = image_pixels(image)
            if pixels.size == 0:
                return None
            if image.is_float:
                name = self._target(stem, ".pfm")
                write_pfm(os.path.join(self.folder, name), pixels[:, :, :3])
            else:
                name = self._target(stem, ".png")
                write_png(os.path.join(self.folder, name), pixels)
            return self.relative + "/" + name
        return None
