#include "lights/goniometric_light.h"

#include "base/sphere_mappings.h"

namespace kiln {

Transform GoniometricLight::LightFromMap() {
    // Swaps y and z (its own inverse)
    SquareMatrix4 m;
    m.m[1][1] = m.m[2][2] = 0;
    m.m[1][2] = m.m[2][1] = 1;
    return Transform(m, m);
}

GoniometricLight::GoniometricLight(const Transform& renderFromLight, Spectrum I, Float scale,
                                   Image image)
    : renderFromMap(renderFromLight * LightFromMap()),
      position(renderFromLight(Point3f(0, 0, 0))),
      Iemit(std::move(I)),
      scale(scale),
      image(std::move(image)) {
    Point2i res = this->image.Resolution();
    mean = this->image.Average(0);
    // Every pixel of the equal-area map covers the same solid angle: no Jacobian
    std::vector<Float> d = this->image.GetSamplingDistribution();
    distribution = PiecewiseConstant2D(d, res.x, res.y);
}

SampledSpectrum GoniometricLight::I(Vector3f wMap, const SampledWavelengths& lambda) const {
    Float value = image.LookupNearestChannel(EqualAreaSphereToSquare(wMap), 0);
    return scale * value * Iemit.Sample(lambda);
}

std::optional<LightLiSample> GoniometricLight::SampleLi(const LightSampleContext& ctx, Point2f,
                                                        const SampledWavelengths& lambda,
                                                        bool) const {
    Float d2 = DistanceSquared(position, ctx.p);
    if (d2 == 0) return {};
    Vector3f wi = (position - ctx.p) / std::sqrt(d2);
    SampledSpectrum Li = I(Normalize(renderFromMap.ApplyInverse(-wi)), lambda) / d2;
    if (!Li) return {};
    return LightLiSample{Li, wi, 1, Interaction(position, Normal3f(), Point2f())};
}

std::optional<LightLeSample> GoniometricLight::SampleLe(Point2f u1, Point2f,
                                                        const SampledWavelengths& lambda) const {
    Float pdf = 0;
    Point2f uv = distribution.Sample(u1, &pdf);
    if (!(pdf > 0)) return {};
    Vector3f wMap = EqualAreaSquareToSphere(uv);
    SampledSpectrum L = I(wMap, lambda);
    if (!L) return {};
    return LightLeSample{L, Ray(position, Normalize(renderFromMap(wMap))), std::nullopt, 1,
                         pdf / (4 * Pi)};
}

LightLePDF GoniometricLight::PDF_Le(const Ray& ray) const {
    Vector3f wMap = Normalize(renderFromMap.ApplyInverse(ray.d));
    return {0, distribution.PDF(EqualAreaSphereToSquare(wMap)) / (4 * Pi)};
}

SampledSpectrum GoniometricLight::Phi(const SampledWavelengths& lambda) const {
    return 4 * Pi * scale * mean * Iemit.Sample(lambda);
}

}  // namespace kiln
