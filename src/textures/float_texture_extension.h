// FloatTextureExtension: the one open member of kiln's closed FloatTexture set, for float
// textures that a module above textures/ defines: the thermal module's temperature fields
// (thermal/temperature_field.h). kiln's texture set cannot name them without an include that
// runs upward through the layers (docs/architecture.md), so they enter it through this
// interface, as they would enter a host renderer's texture set through one adapter class.
// An evaluation costs one virtual call on top of the set's switch.
#pragma once

#include "base/vecmath.h"
#include "textures/texture_eval_context.h"

namespace kiln {

class FloatTextureExtension {
  public:
    virtual ~FloatTextureExtension() = default;
    // As FloatTexture::Evaluate and FloatTexture::UsesFootprint.
    virtual Float Evaluate(const TextureEvalContext& ctx) const = 0;
    virtual bool UsesFootprint() const = 0;
};

}  // namespace kiln
