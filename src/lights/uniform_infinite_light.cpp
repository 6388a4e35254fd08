#include "lights/uniform_infinite_light.h"

#include "base/sampling.h"

namespace kiln {

UniformInfiniteLight::UniformInfiniteLight(const Transform&, Spectrum Lemit, Float scale)
    : Lemit(std::move(Lemit)), scale(scale) {}

SampledSpectrum UniformInfiniteLight::Le(const Ray&, const SampledWavelengths& lambda) const {
    return scale * Lemit.Sample(lambda);
}

std::optional<LightLiSample> UniformInfiniteLight::SampleLi(const LightSampleContext& ctx,
                                                            Point2f u,
                                                            const SampledWavelengths& lambda,
                                                            bool allowIncompletePDF) const {
    if (allowIncompletePDF) return {};
    Vector3f wi = SampleUniformSphere(u);
    Point3f pOutside = ctx.p + wi * (2 * sceneRadius);
    return LightLiSample{scale * Lemit.Sample(lambda), wi, UniformSpherePDF(),
                         Interaction(pOutside, Normal3f(), Point2f())};
}

Float UniformInfiniteLight::PDF_Li(const LightSampleContext&, Vector3f,
                                   bool allowIncompletePDF) const {
    return allowIncompletePDF ? 0 : UniformSpherePDF();
}

std::optional<LightLeSample> UniformInfiniteLight::SampleLe(
    Point2f u1, Point2f u2, const SampledWavelengths& lambda) const {
    SampledSpectrum L = scale * Lemit.Sample(lambda);
    if (!L || !(sceneRadius > 0)) return {};
    Vector3f w = SampleUniformSphere(u1);
    Frame frame = Frame::FromZ(-w);
    Point2f cd = SampleUniformDiskConcentric(u2);
    Point3f pDisk = sceneCenter + sceneRadius * frame.FromLocal(Vector3f(cd.x, cd.y, 0));
    return LightLeSample{L, Ray(pDisk - sceneRadius * w, w), std::nullopt,
                         1 / (Pi * Sqr(sceneRadius)), UniformSpherePDF()};
}

LightLePDF UniformInfiniteLight::PDF_Le(const Ray&) const {
    return {1 / (Pi * Sqr(sceneRadius)), UniformSpherePDF()};
}

SampledSpectrum UniformInfiniteLight::Phi(const SampledWavelengths& lambda) const {
    return 4 * Pi * Pi * Sqr(sceneRadius) * scale * Lemit.Sample(lambda);
}

void UniformInfiniteLight::Preprocess(const Bounds3f& sceneBounds) const {
    sceneBounds.BoundingSphere(&sceneCenter, &sceneRadius);
}

}  // namespace kiln
