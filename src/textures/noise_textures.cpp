#include "textures/noise_textures.h"

#include <cmath>
#include <string>

#include "core/parser/diagnostics.h"
#include "spectral/color.h"
#include "textures/noise.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

namespace {

// "integer octaves" (8). Each octave's frequency is 1.99 times the last, so beyond 64 (1.99^64 =
// 1e19 times the first) they add nothing single precision can tell apart; more is an error at
// the parameter (octaves 1e38 ran wrinkled's loop over the aliased octaves 2^31 times per
// lookup, as pbrt-v4's Turbulence would).
int ReadOctaves(const TextureParameterDictionary& params) {
    int octaves = params.GetOneInt("octaves", 8);
    if (octaves > 64)
        throw SceneError(params.Loc("octaves"),
                         "\"octaves\" above 64 add nothing in single precision (each octave's "
                         "frequency is 1.99 times the last)",
                         std::to_string(octaves));
    return octaves;
}

}  // namespace

// FBmTexture and WrinkledTexture Method Definitions
Float FBmTexture::Evaluate(const TextureEvalContext& ctx) const {
    TexCoord3D c = mapping.Map(ctx);
    return FBm(c.p, c.dpdx, c.dpdy, omega, octaves);
}

FBmTexture* FBmTexture::Create(const TextureParameterDictionary& params,
                               const Transform& renderFromTexture, ObjectArena& arena) {
    return arena.New<FBmTexture>(TextureMapping3D::Create(renderFromTexture), ReadOctaves(params),
                                 params.GetOneFloat("roughness", 0.5f));
}

Float WrinkledTexture::Evaluate(const TextureEvalContext& ctx) const {
    TexCoord3D c = mapping.Map(ctx);
    return Turbulence(c.p, c.dpdx, c.dpdy, omega, octaves);
}

WrinkledTexture* WrinkledTexture::Create(const TextureParameterDictionary& params,
                                         const Transform& renderFromTexture, ObjectArena& arena) {
    return arena.New<WrinkledTexture>(TextureMapping3D::Create(renderFromTexture),
                                      ReadOctaves(params), params.GetOneFloat("roughness", 0.5f));
}

// WindyTexture Method Definitions
Float WindyTexture::Evaluate(const TextureEvalContext& ctx) const {
    TexCoord3D c = mapping.Map(ctx);
    Point3f p(0.1f * c.p.x, 0.1f * c.p.y, 0.1f * c.p.z);
    Float windStrength = FBm(p, 0.1f * c.dpdx, 0.1f * c.dpdy, 0.5f, 3);
    Float waveHeight = FBm(c.p, c.dpdx, c.dpdy, 0.5f, 6);
    return std::abs(windStrength) * waveHeight;
}

// Dots Function Definitions
bool InsidePolkaDot(Point2f st) {
    // Cell centred on integer (s, t); half the cells (by noise) hold a jittered dot
    Float sCell = std::floor(st.x + 0.5f), tCell = std::floor(st.y + 0.5f);
    if (Noise(sCell + 0.5f, tCell + 0.5f) <= 0) return false;
    constexpr Float radius = 0.35f, maxShift = 0.5f - radius;
    Float sCenter = sCell + maxShift * Noise(sCell + 1.5f, tCell + 2.8f);
    Float tCenter = tCell + maxShift * Noise(sCell + 4.5f, tCell + 9.8f);
    return Sqr(st.x - sCenter) + Sqr(st.y - tCenter) < Sqr(radius);
}

FloatDotsTexture* FloatDotsTexture::Create(const TextureParameterDictionary& params,
                                           const Transform& renderFromTexture, const FileLoc& loc,
                                           ObjectArena& arena) {
    // The dots show "outside" and the rest "inside", as pbrt-v4 renders them (its Create passes
    // the two to a constructor that takes them in the other order; docs/pbrt-v4-support.md)
    return arena.New<FloatDotsTexture>(TextureMapping2D::Create(params, renderFromTexture, loc),
                                       params.GetFloatTexture("outside", 0, arena),
                                       params.GetFloatTexture("inside", 1, arena));
}

SpectrumDotsTexture* SpectrumDotsTexture::Create(const TextureParameterDictionary& params,
                                                 const Transform& renderFromTexture,
                                                 SpectrumType type, const FileLoc& loc,
                                                 ObjectArena& arena) {
    // Swapped as for FloatDotsTexture above
    return arena.New<SpectrumDotsTexture>(
        TextureMapping2D::Create(params, renderFromTexture, loc),
        params.GetSpectrumTexture("outside", Spectrum(ConstantSpectrum(0)), type, arena),
        params.GetSpectrumTexture("inside", Spectrum(ConstantSpectrum(1)), type, arena));
}

// MarbleTexture Method Definitions
SampledSpectrum MarbleTexture::Evaluate(const TextureEvalContext& ctx,
                                        const SampledWavelengths& lambda) const {
    TexCoord3D c = mapping.Map(ctx);
    Point3f p(scale * c.p.x, scale * c.p.y, scale * c.p.z);
    Float marble = p.y + variation * FBm(p, scale * c.dpdx, scale * c.dpdy, omega, octaves);
    Float t = 0.5f + 0.5f * std::sin(marble);
    // Cubic Bezier spline through pbrt's marble colours (sRGB reflectances)
    static const RGB colors[] = {{.58f, .58f, .6f}, {.58f, .58f, .6f}, {.58f, .58f, .6f},
                                 {.5f, .5f, .5f},   {.6f, .59f, .58f}, {.58f, .58f, .6f},
                                 {.58f, .58f, .6f}, {.2f, .2f, .33f},  {.58f, .58f, .6f}};
    constexpr int nSeg = 9 - 3;
    int first = std::min(int(std::floor(t * nSeg)), nSeg - 1);
    t = t * nSeg - first;
    const RGB* cp = colors + first;
    Float u = 1 - t;
    RGB rgb = (u * u * u) * cp[0] + (3 * u * u * t) * cp[1] + (3 * u * t * t) * cp[2] +
              (t * t * t) * cp[3];
    rgb = 1.5f * rgb;
    rgb = RGB(Clamp(rgb.r, Float(0), Float(1)), Clamp(rgb.g, Float(0), Float(1)),
              Clamp(rgb.b, Float(0), Float(1)));
    return RGBAlbedoSpectrum(RGBColorSpace::sRGB(), rgb).Sample(lambda);
}

MarbleTexture* MarbleTexture::Create(const TextureParameterDictionary& params,
                                     const Transform& renderFromTexture, ObjectArena& arena) {
    return arena.New<MarbleTexture>(TextureMapping3D::Create(renderFromTexture),
                                    ReadOctaves(params), params.GetOneFloat("roughness", 0.5f),
                                    params.GetOneFloat("scale", 1),
                                    params.GetOneFloat("variation", 0.2f));
}

}  // namespace kiln
