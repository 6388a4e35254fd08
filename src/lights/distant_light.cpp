#include "lights/distant_light.h"

#include "base/sampling.h"

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

std::optional<LightLeSample> DistantLight::SampleLe(Point2f u1, Point2f,
                                                    const SampledWavelengths& lambda) const {
    SampledSpectrum L = scale * Lemit.Sample(lambda);
    if (!L || !(sceneRadius > 0)) return {};
    Frame frame = Frame::FromZ(wLight);
    Point2f cd = SampleUniformDiskConcentric(u1);
    Point3f pDisk = sceneCenter + sceneRadius * frame.FromLocal(Vector3f(cd.x, cd.y, 0));
    return LightLeSample{L, Ray(pDisk + sceneRadius * wLight, -wLight), std::nullopt,
                         1 / (Pi * Sqr(sceneRadius)), 1};
}

SampledSpectrum DistantLight::Phi(const SampledWavelengths& lambda) const {
    return scale * Lemit.Sample(lambda) * Pi * Sqr(sceneRadius);
}

void DistantLight::Preprocess(const Bounds3f& sceneBounds) const {
    sceneBounds.BoundingSphere(&sceneCenter, &sceneRadius);
}

}  // namespace kiln
