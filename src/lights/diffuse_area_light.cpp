#include "lights/diffuse_area_light.h"

#include "lights/area_light_sampling.h"

#include "core/geometry/alpha_mask.h"
#include "core/geometry/shape.h"
#include "spectral/color.h"

namespace kiln {

DiffuseAreaLight::DiffuseAreaLight(const Transform&, Spectrum Lemit, Float scale,
                                   const Shape* shape, bool twoSided, Image image,
                                   const RGBColorSpace* imageColorSpace, const AlphaMask* alpha)
    : shape(shape),
      alpha(alpha && !alpha->IsConstantZero() ? alpha : nullptr),
      invisible(alpha && alpha->IsConstantZero()),
      area(shape->Area()),
      twoSided(twoSided),
      Lemit(std::move(Lemit)),
      scale(scale),
      image(std::move(image)),
      imageColorSpace(imageColorSpace ? imageColorSpace : &RGBColorSpace::sRGB()) {}

// Emission
SampledSpectrum DiffuseAreaLight::L(Point3f, Normal3f n, Point2f uv, Vector3f w,
                                    const SampledWavelengths& lambda) const {
    if (!twoSided && Dot(n, w) < 0) return SampledSpectrum(0);
    if (image) {
        // Image rows run top to bottom while v runs up (pbrt-v4 flips v)
        Point2f st(uv.x, 1 - uv.y);
        RGB rgb;
        for (int c = 0; c < 3; ++c) rgb[c] = std::max<Float>(0, image.BilerpChannel(st, c));
        return scale * RGBIlluminantSpectrum(*imageColorSpace, rgb).Sample(lambda);
    }
    return scale * Lemit.Sample(lambda);
}

// Sampling
std::optional<LightLiSample> DiffuseAreaLight::SampleLi(const LightSampleContext& ctx, Point2f u,
                                                        const SampledWavelengths& lambda,
                                                        bool) const {
    return SampleAreaLi(*shape, ctx, u, [&](Point3f p, Normal3f n, Point2f uv, Vector3f w) {
        if (alpha && IsCutOut(*shape, *alpha, p, w)) return SampledSpectrum(0);
        return L(p, n, uv, w, lambda);
    });
}

Float DiffuseAreaLight::PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool) const {
    return AreaPDF_Li(*shape, ctx, wi);
}

std::optional<LightLeSample> DiffuseAreaLight::SampleLe(Point2f u1, Point2f u2,
                                                        const SampledWavelengths& lambda) const {
    std::optional<ShapeSample> ss = shape->Sample(u1);
    if (!ss || !(ss->pdf > 0)) return {};
    Float pdfDir = 0;
    Vector3f w = SampleEmissionDirection(ss->intr.n, twoSided, u2, &pdfDir);
    if (!(pdfDir > 0)) return {};
    if (alpha && IsCutOut(*shape, *alpha, ss->intr.p, w)) return {};
    SampledSpectrum Le = L(ss->intr.p, ss->intr.n, ss->intr.uv, w, lambda);
    if (!Le) return {};
    return LightLeSample{Le, ss->intr.SpawnRay(w), ss->intr, ss->pdf, pdfDir};
}

LightLePDF DiffuseAreaLight::PDF_Le(const Interaction& intr, Vector3f w) const {
    return {shape->PDF(intr), EmissionDirectionPDF(intr.n, twoSided, w)};
}

// Power
SampledSpectrum DiffuseAreaLight::Phi(const SampledWavelengths& lambda) const {
    if (!(area > 0)) return SampledSpectrum(0);
    SampledSpectrum L(0);
    if (image) {
        Point2i res = image.Resolution();
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                RGB rgb;
                for (int c = 0; c < 3; ++c)
                    rgb[c] = std::max<Float>(0, image.GetChannel({x, y}, c));
                L += RGBIlluminantSpectrum(*imageColorSpace, rgb).Sample(lambda);
            }
        L *= scale / (Float(res.x) * res.y);
    } else {
        L = scale * Lemit.Sample(lambda);
    }
    return Pi * (twoSided ? 2 : 1) * area * L;
}

}  // namespace kiln
