"""Text of a pbrt-v4 scene file: numbers, quoted strings, parameters and directives.

Nothing here imports bpy, so the functions can be used (and tested) outside Blender.
A parameter is a tuple ``(type, name, value)``; ``value`` is a number, a string, a bool or a
sequence of numbers. Kiln-only parameters are written on a line of their own, followed by the
comment ``# kiln``, so that they are easy to see and to remove for pbrt-v4.
"""

KILN_MARK = "# kiln"


def fmt_number(x):
    """Format a number with at most 7 significant digits (about float32's precision).

    Integers (Python ints and bools excluded) are written as integers; ``-0`` becomes ``0``.
    """
    if isinstance(x, int) and not isinstance(x, bool):
        return str(x)
    text = "%.7g" % float(x)
    return "0" if text == "-0" else text


def quote(text):
    """Quote a string for a pbrt file. pbrt strings cannot hold a double quote, a backslash or
    a line break; each of those characters is replaced by an underscore."""
    cleaned = "".join("_" if c in '"\\\n\r' else c for c in str(text))
    return '"%s"' % cleaned


def fmt_value(ptype, value):
    """The value part of one parameter: strings quoted, bools as ``true``/``false``, sequences
    of numbers in square brackets, single numbers bare."""
    if ptype in ("string", "texture", "spectrum") and isinstance(value, str):
        return quote(value)
    if ptype == "bool":
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return "[" + " ".join(fmt_number(v) for v in value) + "]"
    return fmt_number(value)


def fmt_param(param):
    """``"type name" value`` for a parameter tuple ``(type, name, value)``."""
    ptype, name, value = param
    return '"%s %s" %s' % (ptype, name, fmt_value(ptype, value))


def directive(name, *args, params=(), kiln_params=(), indent=""):
    """The lines of one directive.

    ``name`` is the directive (``Shape``), ``args`` its quoted arguments (``"sphere"``).
    The standard ``params`` follow on one continuation line (none if empty); each of the
    ``kiln_params`` gets a continuation line of its own ending in ``# kiln``.
    Returns a list of lines without line breaks.
    """
    head = indent + name + "".join(" " + quote(a) for a in args)
    lines = [head]
    cont = indent + "    "
    if params:
        lines.append(cont + " ".join(fmt_param(p) for p in params))
    for p in kiln_params:
        lines.append(cont + fmt_param(p) + "  " + KILN_MARK)
    return lines


def matrix_values(matrix):
    """The 16 numbers of pbrt's ``Transform`` for a 4x4 matrix given row by row
    (``matrix[row][col]``, as Blender's mathutils.Matrix): pbrt reads the matrix column by
    column, so the values are written column after column."""
    return [matrix[row][col] for col in range(4) for row in range(4)]
