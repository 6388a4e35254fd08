"""Reading the header attributes of an OpenEXR file (no pixels), without OpenEXR libraries.

kiln records the samples per pixel an image holds in the standard ``samplesPerPixel``
attribute, and marks images written before the render finished with ``kiln:partial``.
"""

import struct

MAGIC = b"\x76\x2f\x31\x01"


def read_attributes(path):
    """The header attributes of the (first part of the) EXR file at ``path`` as a dict
    name -> value. ``int`` and ``float`` values are decoded, ``string`` values are decoded as
    UTF-8; every other type is returned as its raw bytes. Raises ValueError if the file is
    not an EXR file or its header is cut short."""
    with open(path, "rb") as f:
        data = f.read(1 << 20)  # headers are small; 1 MiB is plenty
    if data[:4] != MAGIC:
        raise ValueError("%s: not an OpenEXR file" % path)
    pos, attributes = 8, {}
    try:
        while True:
            end = data.index(b"\0", pos)
            name = data[pos:end].decode("utf-8", "replace")
            pos = end + 1
            if not name:
                return attributes
            end = data.index(b"\0", pos)
            kind = data[pos:end].decode("ascii", "replace")
            pos = end + 1
            (size,) = struct.unpack_from("<i", data, pos)
            pos += 4
            raw = data[pos:pos + size]
            if len(raw) != size:
                raise ValueError("%s: EXR header cut short" % path)
            pos += size
            if kind == "int":
                attributes[name] = struct.unpack("<i", raw)[0]
            elif kind == "float":
                attributes[name] = struct.unpack("<f", raw)[0]
            elif kind == "string":
                attributes[name] = raw.decode("utf-8", "replace")
            else:
                attributes[name] = raw
    except (ValueError, struct.error) as error:
        raise ValueError("%s: EXR header cut short (%s)" % (path, error))


def samples_per_pixel(path):
    """The ``samplesPerPixel`` attribute of the EXR at ``path``, or None if it has none."""
    value = read_attributes(path).get("samplesPerPixel")
    return value if isinstance(value, int) else None
