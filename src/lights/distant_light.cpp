#include "lights/distant_light.h"

namespace kiln {

DistantLight::DistantLight(const Transform& renderFromLight, Spectrum Lemit, Float scale)
    : wLight(Normalize(renderFromLight(Vector3f(0, 0, 1)))),
      Lemit(std::move(Lemit)),
      scale(scale) {}

std::optional<LightLiSample> DistantLight::SampleLi(const LightSampleContext& ctx, Point2f,
                                                    const SampledWavelengths& lambda, bool) const {
    SampledSpectrum Li = scale * Lemit.Sample(lambda);
    if (!Li) return {};
    // A point for shadow rays beyond anything in the scene
    Point3f pOutside = ctx.p + wLight * (2 * sceneRadius);
    return LightLiSample{Li, wLight, 1, Interaction(pOutside, Normal3f(), Point2f())};
}

SampledSpectrum DistantLight::Phi(const SampledWavelengths& lambda) const {
    return scale * Lemit.Sample(lambda) * Pi * Sqr(sceneRadius);
}

void DistantLight::Preprocess(const Bounds3f& sceneBounds) const {
    sceneBounds.BoundingSphere(&sceneCenter, &sceneRadius);
}

}  // namespace kiln
