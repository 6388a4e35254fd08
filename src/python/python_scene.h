// kiln.Scene (the Python module): a scene parsed once and rendered as often as the caller likes.
// Samples per pixel, seed, crop window and threads change per render (a new render job:
// Scene::SetJob), the frame moves the animated temperatures (Scene::SetAnimation); an emission
// model or Stokes layers other than the scene was created with, and temperatures set with
// set_temperature, create the scene again from its parsed description (render/scene_edits.h):
// no file is read again.
#pragma once

#include <pybind11/pybind11.h>

namespace kiln {

// Registers kiln.Scene, kiln.Image, kiln.load and kiln.load_string in `m`.
void RegisterScene(pybind11::module_& m);

}  // namespace kiln
