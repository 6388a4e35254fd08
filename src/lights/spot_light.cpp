#include "lights/spot_light.h"

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

SampledSpectrum SpotLight::Phi(const SampledWavelengths& lambda) const {
    return scale * Iemit.Sample(lambda) * ConeSolidAngle(cosFalloffStart, cosFalloffEnd);
}

}  // namespace kiln
