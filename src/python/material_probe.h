// Material queries for authors (the Python module's kiln.emissivity, kiln.directional_albedo,
// kiln.glow_color): one material made from its pbrt-v4 parameters, evaluated at a flat point the
// way the thermal module evaluates it at a hit (thermal/material_albedo.h): the directional
// albedo A(theta, lambda) of the BSDF the integrator scatters with, and the linear polarisation
// of its reflection. By Kirchhoff's law the surface's emissivity is 1 - A, and per polarisation
// 1 - R_s and 1 - R_p (R_s = A + a1, R_p = A - a1, a1 the reflection's Stokes S1 about the plane
// of incidence).
#pragma once

#include <pybind11/pybind11.h>

namespace kiln {

// Registers kiln._MaterialProbe, kiln._planck, kiln._named_spectrum, kiln._cie_xyz and
// kiln._xyz_to_srgb (the Python layer in kiln/__init__.py builds the public functions on them).
void RegisterMaterialProbe(pybind11::module_& m);

}  // namespace kiln
