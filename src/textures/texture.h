// Textures: closed sets of float- and spectrum-valued textures (pbrt-v4's FloatTexture and
// SpectrumTexture) and their creation from "Texture" directives.
//
// A FloatTexture returns a dimensionless value (roughness, amount, bump height...) at a
// surface point. A SpectrumTexture returns a SampledSpectrum at the path's wavelengths; its
// unit follows the SpectrumType it was created for: albedo (reflectance, in [0, 1]),
// unbounded (e.g. index of refraction) or illuminant (relative emitted radiance).
#pragma once

#include <optional>

#include <map>
#include <memory>
#include <string>
#include <variant>

#include "base/closed_set.h"
#include "base/object_arena.h"
#include "base/transform.h"
#include "core/parser/diagnostics.h"
#include "core/parser/parameter_dictionary.h"
#include "spectral/sampled_spectrum.h"
#include "textures/texture_eval_context.h"

namespace kiln {

class FloatConstantTexture;
class FloatBilerpTexture;
class FloatCheckerboardTexture;
class FloatDirectionMixTexture;
class FloatImageTexture;
class FloatMixTexture;
class FloatScaledTexture;
class FBmTexture;
class WrinkledTexture;
class WindyTexture;
class FloatDotsTexture;
class FloatTextureExtension;
class MarbleTexture;
class SpectrumDotsTexture;
class SpectrumMetalTemperatureTexture;
class SpectrumConstantTexture;
class SpectrumBilerpTexture;
class SpectrumCheckerboardTexture;
class SpectrumDirectionMixTexture;
class SpectrumImageTexture;
class SpectrumMixTexture;
class SpectrumScaledTexture;
class TextureParameterDictionary;
class ImageTextureCache;

// FloatTexture Definition
class FloatTexture
    : public ClosedSet<const FloatConstantTexture*, const FloatBilerpTexture*,
                       const FloatCheckerboardTexture*, const FloatDirectionMixTexture*,
                       const FloatImageTexture*, const FloatMixTexture*, const FloatScaledTexture*,
                       const FBmTexture*, const WrinkledTexture*, const WindyTexture*,
                       const FloatDotsTexture*, const FloatTextureExtension*> {
  public:
    using ClosedSet::ClosedSet;

    // Value at the point: dimensionless, or in the unit of what it stands for (e.g. kelvin
    // for the thermal module's temperature fields, an extension:
    // textures/float_texture_extension.h).
    Float Evaluate(const TextureEvalContext& ctx) const;
    // Whether the value depends on the screen-space footprint (dpdx, dudx, ...): image
    // textures filter with it, checkerboards and noise antialias with it. Shading computes
    // footprints only for surfaces that need them.
    bool UsesFootprint() const;
    // The value when it is the same everywhere (a constant texture), else nullopt.
    std::optional<Float> ConstantValue() const;
};

// SpectrumTexture Definition
class SpectrumTexture
    : public ClosedSet<const SpectrumConstantTexture*, const SpectrumBilerpTexture*,
                       const SpectrumCheckerboardTexture*, const SpectrumDirectionMixTexture*,
                       const SpectrumImageTexture*, const SpectrumMixTexture*,
                       const SpectrumScaledTexture*, const MarbleTexture*,
                       const SpectrumDotsTexture*, const SpectrumMetalTemperatureTexture*> {
  public:
    using ClosedSet::ClosedSet;

    // Values at the wavelengths lambda (unit per the texture's SpectrumType).
    SampledSpectrum Evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const;
    // As FloatTexture::UsesFootprint.
    bool UsesFootprint() const;
};

// NamedTextures Definition
// Textures declared so far, by name; spectrum textures are created once per SpectrumType a
// material may ask for (pbrt-v4 does the same). imageCache shares MIP maps between image
// textures with the same file and options; it holds pointers into the scene's ObjectArena and
// must not outlive it. renderFromWorld is the scene's render-from-world transform (identity
// when render space is world space): "gradient" textures with "space" "world" need it.
struct NamedTextures {
    NamedTextures();
    Transform renderFromWorld;
    std::map<std::string, FloatTexture> floatTextures;
    std::map<std::string, SpectrumTexture> albedoSpectrumTextures, unboundedSpectrumTextures,
        illuminantSpectrumTextures;
    std::shared_ptr<ImageTextureCache> imageCache;

    const std::map<std::string, SpectrumTexture>& SpectrumTextures(SpectrumType type) const;
    std::map<std::string, SpectrumTexture>& SpectrumTextures(SpectrumType type);
};

// Texture creation from `Texture "name" "float"|"spectrum" "class" ...`. Classes: constant,
// scale, mix, directionmix, checkerboard, bilerp, imagemap, dots; float only: fbm, wrinkled,
// windy; spectrum only: marble. ptex (and the float-only/spectrum-only classes asked for the
// other kind, and the thermal module's temperature fields asked for as spectrum textures) warn
// and give a constant 0.5. The temperature fields (gradient, noise, heatmap, vertexattribute,
// cooling, keyframes) are created by the thermal module (thermal/temperature_field.h), which
// scene creation asks first. An unknown class throws SceneError at loc.
FloatTexture CreateFloatTexture(const std::string& className, const Transform& renderFromTexture,
                                const TextureParameterDictionary& params, const FileLoc& loc,
                                ObjectArena& arena, Diagnostics& diag);
SpectrumTexture CreateSpectrumTexture(const std::string& className,
                                      const Transform& renderFromTexture,
                                      const TextureParameterDictionary& params, SpectrumType type,
                                      const FileLoc& loc, ObjectArena& arena, Diagnostics& diag);

}  // namespace kiln
