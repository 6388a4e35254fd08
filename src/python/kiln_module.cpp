// kiln's Python extension (kiln._kiln): scenes and material queries. The public API is the
// package kiln (src/python/kiln/__init__.py), which builds on these.
#include <pybind11/pybind11.h>

#include "python/material_probe.h"
#include "python/python_scene.h"

PYBIND11_MODULE(_kiln, m) {
    m.doc() = "kiln's C++ core; use the package kiln";
    kiln::RegisterScene(m);
    kiln::RegisterMaterialProbe(m);
}
