#include "lights/spot_light.h"

#include "base/sampling.h"

namespace kiln {

SpotLight::SpotLight(const Transform& renderFromLight, Spectrum I, Float scale, Float totalWidthDeg,
                     Float falloffStartDeg)
    : renderFromLight(renderFromLight),
      position(renderFromLight(Point3f(0, 0, 0))),
      Iemit(std::move(I)),
      scale(scale),
      cosFalloffStart(std::cos(Radians(falloffStartDeg))),
      cosFalloffEnd(std::cos(Radians(totalWidthDeg))) {}

Float SpotLight::ConeSolidAngle(Float cosFalloffStart, Float cosFalloffEnd) {
    // Integral of the falloff over the sphere: the full cone plus the smoothstep ring, whose
    // integral over cos theta is half its width
    return 2 * Pi * ((1 - cosFalloffStart) + (cosFalloffStart - cosFalloffEnd) / 2);
}

SampledSpectrum SpotLight::I(Vector3f wLight, const SampledWavelengths& lambda) const {
    return SmoothStep(CosTheta(wLight), cosFalloffEnd, cosFalloffStart) * scale *
           Iemit.Sample(lambda);
}

std::optional<LightLiSample> SpotLight::SampleLi(const LightSampleContext& ctx, Point2f,
                                                 const SampledWavelengths& lambda, bool) const {
    Float d2 = DistanceSquared(position, ctx.p);
    if (d2 == 0) return {};
    Vector3f wi = (position - ctx.p) / std::sqrt(d2);
    // Direction of emission (from the light towards the receiver) in light space
    Vector3f wLight = Normalize(renderFromLight.ApplyInverse(-wi));
    SampledSpectrum Li = I(wLight, lambda) / d2;
    if (!Li) return {};
    return LightLiSample{Li, wi, 1, Interaction(position, Normal3f(), Point2f())};
}

namespace {

// Density over x in [a, b] proportional to SmoothStep(x, a, b), whose integral is (b - a) / 2
Float SmoothStepPDF(Float x, Float a, Float b) {
    if (x < a || x > b) return 0;
    return 2 / (b - a) * SmoothStep(x, a, b);
}

// Inverts its CDF 2 t^3 - t^4 (t = (x - a) / (b - a)) by Newton steps kept inside a bisection
// bracket
Float SampleSmoothStep(Float u, Float a, Float b) {
    double lo = 0, hi = 1, t = 0.5;
    for (int i = 0; i < 60; ++i) {
        double cdf = 2 * t * t * t - t * t * t * t - u;
        if (std::abs(cdf) < 1e-9) break;
        if (cdf > 0)
            hi = t;
        else
            lo = t;
        double deriv = 6 * t * t - 4 * t * t * t;
        double next = deriv > 0 ? t - cdf / deriv : 0.5 * (lo + hi);
        t = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    }
    return Float(a + t * (b - a));
}

}  // namespace

std::optional<LightLeSample> SpotLight::SampleLe(Point2f u1, Point2f u2,
                                                 const SampledWavelengths& lambda) const {
    // Probabilities of the cone and of the ring: their shares of the falloff's integral
    Float pCone = 1 - cosFalloffStart, pRing = (cosFalloffStart - cosFalloffEnd) / 2;
    Float total = pCone + pRing;
    if (!(total > 0)) return {};
    Vector3f wLight;
    Float pdfDir;
    if (u2[0] < pCone / total) {
        wLight = SampleUniformCone(u1, cosFalloffStart);
        pdfDir = UniformConePDF(cosFalloffStart) * pCone / total;
    } else {
        Float cosTheta = SampleSmoothStep(u1[0], cosFalloffEnd, cosFalloffStart);
        Float sinTheta = SafeSqrt(1 - Sqr(cosTheta)), phi = u1[1] * 2 * Pi;
        wLight = Vector3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
        pdfDir = SmoothStepPDF(cosTheta, cosFalloffEnd, cosFalloffStart) * pRing / (total * 2 * Pi);
    }
    SampledSpectrum L = I(wLight, lambda);
    if (!L || !(pdfDir > 0)) return {};
    return LightLeSample{L, Ray(position, Normalize(renderFromLight(wLight))), std::nullopt, 1,
                         pdfDir};
}

LightLePDF SpotLight::PDF_Le(const Ray& ray) const {
    Float pCone = 1 - cosFalloffStart, pRing = (cosFalloffStart - cosFalloffEnd) / 2;
    Float total = pCone + pRing;
    if (!(total > 0)) return {};
    Float cosTheta = CosTheta(Normalize(renderFromLight.ApplyInverse(ray.d)));
    if (cosTheta >= cosFalloffStart) return {0, UniformConePDF(cosFalloffStart) * pCone / total};
    return {0, SmoothStepPDF(cosTheta, cosFalloffEnd, cosFalloffStart) * pRing / (total * 2 * Pi)};
}

SampledSpectrum SpotLight::Phi(const SampledWavelengths& lambda) const {
    return scale * Iemit.Sample(lambda) * ConeSolidAngle(cosFalloffStart, cosFalloffEnd);
}

}  // namespace kiln
