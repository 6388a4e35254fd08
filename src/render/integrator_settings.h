// Scene creation step: the integrator's settings from the scene's Integrator directive, then
// the render's options (which override it, for comparisons).
#pragma once

#include "core/parser/diagnostics.h"
#include "render/render_options.h"
#include "render/scene.h"

namespace kiln {

struct SceneEntity;

// PathIntegratorSettings from the Integrator entity: pbrt-v4's name and parameters ("maxdepth",
// "regularize", "lightsampler") and kiln's ("strategy", "wavelengths", "emittersampling",
// "mediumemission", "glasswindows", "exactmediumemission", "weightabsorption",
// "collisionlightsampling", "splitdielectrics", "skipuniformenvironment",
// "wavelengthsampling"). SceneError
// for an unknown integrator name or parameter value; a warning for integrators rendered with
// another.
PathIntegratorSettings CreateIntegratorSettings(SceneEntity& e, const RenderOptions& options,
                                                Diagnostics& diag);

}  // namespace kiln
