"""kiln's named metals for the ``conductor`` material, and a guess of the metal from a colour.

The spectra are kiln's named spectra ``metal-XX-eta`` and ``metal-XX-k``: Ag, Al, Au, Cu,
CuZn, MgO and TiO2 are pbrt-v4's; Cr, Fe, Ni, Pt, Se, Ti and W are kiln's measured ones.
"""

# (identifier, label, description) for the Blender enum; identifiers are the XX in metal-XX-eta.
METALS = [
    ("Ag", "Silver (Ag)", "pbrt-v4's silver"),
    ("Al", "Aluminium (Al)", "pbrt-v4's aluminium"),
    ("Au", "Gold (Au)", "pbrt-v4's gold"),
    ("Cu", "Copper (Cu)", "pbrt-v4's copper"),
    ("CuZn", "Brass (CuZn)", "pbrt-v4's brass"),
    ("MgO", "Magnesium oxide (MgO)", "pbrt-v4's magnesium oxide"),
    ("TiO2", "Titanium dioxide (TiO2)", "pbrt-v4's titanium dioxide"),
    ("Cr", "Chromium (Cr)", "kiln's measured chromium"),
    ("Fe", "Iron (Fe)", "kiln's measured iron"),
    ("Ni", "Nickel (Ni)", "kiln's measured nickel"),
    ("Pt", "Platinum (Pt)", "kiln's measured platinum"),
    ("Se", "Selenium (Se)", "kiln's measured selenium"),
    ("Ti", "Titanium (Ti)", "kiln's measured titanium"),
    ("W", "Tungsten (W)", "kiln's measured tungsten"),
]

METAL_IDS = [m[0] for m in METALS]

# Approximate normal-incidence reflectance (linear sRGB) of the metals the guess chooses
# between, as published in common physically based shading tables. Only used to pick the
# nearest metal; the render uses kiln's spectra.
GUESS_COLOURS = {
    "Ag": (0.972, 0.960, 0.915),
    "Al": (0.913, 0.922, 0.924),
    "Au": (1.000, 0.766, 0.336),
    "Cu": (0.955, 0.638, 0.538),
    "CuZn": (0.910, 0.778, 0.423),
    "Fe": (0.562, 0.565, 0.578),
    "Ni": (0.660, 0.609, 0.526),
    "Pt": (0.673, 0.637, 0.585),
}


def guess_metal(rgb):
    """The metal of GUESS_COLOURS whose colour is nearest (Euclidean distance in linear RGB)
    to ``rgb``, the base colour's first three components. Gold-yellow gives Au, copper-red
    Cu, light grey Ag or Al, mid and dark grey Fe."""
    r, g, b = (float(c) for c in tuple(rgb)[:3])

    def distance(metal):
        cr, cg, cb = GUESS_COLOURS[metal]
        return (r - cr) ** 2 + (g - cg) ** 2 + (b - cb) ** 2

    return min(GUESS_COLOURS, key=distance)


def spectrum_names(metal):
    """kiln's named spectra (eta, k) of a metal identifier, e.g. ('metal-Au-eta', 'metal-Au-k')."""
    return "metal-%s-eta" % metal, "metal-%s-k" % metal
