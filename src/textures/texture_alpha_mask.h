// A shape's "alpha" given by a float texture (core/geometry/alpha_mask.h), as pbrt-v4 reads it.
#pragma once

#include "base/object_arena.h"
#include "core/geometry/alpha_mask.h"
#include "textures/texture.h"

namespace kiln {

class TextureParameterDictionary;

class TextureAlphaMask : public AlphaMask {
  public:
    explicit TextureAlphaMask(FloatTexture alpha, bool constantZero = false)
        : alpha(alpha), constantZero(constantZero) {}
    Float Alpha(const SurfaceInteraction& si) const override {
        return alpha.Evaluate(TextureEvalContext(si));
    }
    bool IsConstantZero() const override { return constantZero; }

    // A shape's "float alpha" or "texture alpha" (SceneError for an undefined texture or a
    // non-finite value); nullptr when absent or a constant >= 1 (opaque, no test at all).
    static const AlphaMask* Read(const TextureParameterDictionary& params, ObjectArena& arena);

  private:
    FloatTexture alpha;
    bool constantZero;  // a constant texture of value 0 (pbrt-v4's test: exactly 0)
};

}  // namespace kiln
