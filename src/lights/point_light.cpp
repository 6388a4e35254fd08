#include "lights/point_light.h"

namespace kiln {

PointLight::PointLight(const Transform& renderFromLight, Spectrum I, Float scale)
    : position(renderFromLight(Point3f(0, 0, 0))), I(std::move(I)), scale(scale) {}

std::optional<LightLiSample> PointLight::SampleLi(const LightSampleContext& ctx, Point2f,
                                                  const SampledWavelengths& lambda, bool) const {
    // A receiver at the light itself gets no well-defined direction
    Float d2 = DistanceSquared(position, ctx.p);
    if (d2 == 0) return {};
    Vector3f wi = (position - ctx.p) / std::sqrt(d2);
    SampledSpectrum Li = scale * I.Sample(lambda) / d2;
    if (!Li) return {};
    return LightLiSample{Li, wi, 1, Interaction(position, Normal3f(), Point2f())};
}

std::optional<LightLeSample> PointLight::SampleLe(Point2f u1, Point2f,
                                                  const SampledWavelengths& lambda) const {
    SampledSpectrum L = scale * I.Sample(lambda);
    if (!L) return {};
    return LightLeSample{L, Ray(position, SampleUniformSphere(u1)), std::nullopt, 1,
                         UniformSpherePDF()};
}

SampledSpectrum PointLight::Phi(const SampledWavelengths& lambda) const {
    return 4 * Pi * scale * I.Sample(lambda);
}

}  // namespace kiln
