// Light sampling shared by the area lights (diffuse and thermal): a point on the shape chosen
// by the shape's own solid-angle strategy, and the matching density (pbrt-v4's
// DiffuseAreaLight::SampleLi and PDF_Li).
#pragma once

#include <cmath>
#include <optional>

#include "base/rng.h"
#include "base/sampling.h"
#include "core/geometry/alpha_mask.h"
#include "core/geometry/shape.h"
#include "lights/light_sample.h"

namespace kiln {

// L(p, n, uv, w) gives the radiance leaving the sampled point towards the receiver.
template <typename RadianceAt>
std::optional<LightLiSample> SampleAreaLi(const Shape& shape, const LightSampleContext& ctx,
                                          Point2f u, RadianceAt L) {
    ShapeSampleContext shapeCtx(ctx.p, ctx.n, ctx.ns, 0);
    std::optional<ShapeSample> ss = shape.Sample(shapeCtx, u);
    if (!ss || !(ss->pdf > 0) || !std::isfinite(ss->pdf) || LengthSquared(ss->intr.p - ctx.p) == 0)
        return {};
    Vector3f wi = Normalize(ss->intr.p - ctx.p);
    SampledSpectrum Le = L(ss->intr.p, ss->intr.n, ss->intr.uv, -wi);
    if (!Le) return {};
    return LightLiSample{Le, wi, ss->pdf, ss->intr};
}

// Whether a light's sampled point p (leaving towards w) is cut out of its shape (pbrt-v4's
// AreaLight::AlphaMasked, the uniform number a hash of p).
inline bool IsCutOut(const Shape& shape, const AlphaMask& alpha, Point3f p, Vector3f w) {
    return alpha.Masked(shape.InteractionAt(p, 0, w), HashToUniform(Hash(p)));
}

// A direction leaving a surface of normal n, cosine-distributed about n, or on a side chosen
// by u[0] (each with probability 1/2) for a two-sided emitter (pbrt-v4's
// DiffuseAreaLight::SampleLe); pdf per sr, 0 if none.
inline Vector3f SampleEmissionDirection(Normal3f n, bool twoSided, Point2f u, Float* pdf) {
    Vector3f w;
    if (twoSided) {
        bool back = u[0] >= 0.5f;
        u[0] = std::min(back ? (u[0] - 0.5f) * 2 : u[0] * 2, OneMinusEpsilon);
        w = SampleCosineHemisphere(u);
        if (back) w.z = -w.z;
        *pdf = CosineHemispherePDF(std::abs(w.z)) / 2;
    } else {
        w = SampleCosineHemisphere(u);
        *pdf = CosineHemispherePDF(w.z);
    }
    return Frame::FromZ(Vector3f(n)).FromLocal(w);
}

// Its density per sr for direction w (unit).
inline Float EmissionDirectionPDF(Normal3f n, bool twoSided, Vector3f w) {
    return twoSided ? CosineHemispherePDF(AbsDot(n, w)) / 2
                    : std::max<Float>(0, CosineHemispherePDF(Dot(n, w)));
}

// Solid-angle density of SampleAreaLi choosing direction wi (0 where it is not finite).
inline Float AreaPDF_Li(const Shape& shape, const LightSampleContext& ctx, Vector3f wi) {
    ShapeSampleContext shapeCtx(ctx.p, ctx.n, ctx.ns, 0);
    Float pdf = shape.PDF(shapeCtx, wi);
    return std::isfinite(pdf) ? pdf : 0;
}

}  // namespace kiln
