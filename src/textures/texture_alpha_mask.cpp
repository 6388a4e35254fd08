#include "textures/texture_alpha_mask.h"

#include <cmath>

#include "textures/basic_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

const AlphaMask* TextureAlphaMask::Read(const TextureParameterDictionary& params,
                                        ObjectArena& arena) {
    std::optional<FloatTexture> alpha = params.GetFloatTextureOrNull("alpha", arena);
    if (!alpha) return nullptr;
    bool constantZero = false;
    if (const FloatConstantTexture* c = alpha->GetIf<FloatConstantTexture>()) {
        Float a = c->Evaluate(TextureEvalContext());
        if (!std::isfinite(a))
            throw SceneError(params.Loc("alpha"), "\"alpha\" must be finite", "alpha");
        if (a >= 1) return nullptr;
        constantZero = a == 0;
    }
    return arena.New<TextureAlphaMask>(*alpha, constantZero);
}

}  // namespace kiln
