// ThermalAreaLight: a shape that glows because it is hot (kiln's reason to exist).
//
// Every shape whose material or own parameters give it a temperature gets one of these,
// bound to its material. The radiance leaving a point in direction w is, per wavelength,
//   kirchhoff (default): B(lambda, T) (1 - R(w, lambda)),   R the material's directional-
//                        hemispherical reflectance (materials/emissivity.h)
//   additive:            B(lambda, T)  (the surface also reflects as usual)
//   diffuse:             B(lambda, T)  (the surface is black: it does not reflect)
// with B Planck's spectral radiance in W m^-2 sr^-1 nm^-1 (spectral/planck.h) times "scale"
// (1 by default: absolute units). An opaque surface emits on both sides, like its BSDF
// reflects on both sides. It is sampled and MIS-weighted like any area light, by solid angle
// through the shape's own sampling strategy.
#pragma once

#include <optional>

#include "lights/light_sample.h"
#include "materials/emissivity.h"
#include "textures/texture.h"

namespace kiln {

class Shape;
class Material;

class ThermalAreaLight {
  public:
    // temperature: kelvin, evaluated at the emitting point; material: the shape's material
    // (not owned); reflectance: its table when the material is uniform (may be null).
    ThermalAreaLight(const Shape* shape, const Material* material, FloatTexture temperature,
                     EmissionModel model, Float scale, const ReflectanceTable* reflectance);

    LightType Type() const { return LightType::Area; }
    EmissionModel Model() const { return model; }
    Float Area() const;

    SampledSpectrum L(Point3f p, Normal3f n, Point2f uv, Vector3f w,
                      const SampledWavelengths& lambda) const;
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool allowIncompletePDF = false) const;
    // Emitted power (W nm^-1), for power-proportional light selection: area x pi x two sides x
    // the mean over the surface of B(lambda, T) times the hemispherical emissivity.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f&) const {}

    // Temperature (K) at a surface point.
    Float Temperature(Point3f p, Normal3f n, Point2f uv) const;

  private:
    SampledSpectrum Emissivity(Point3f p, Normal3f n, Point2f uv, Vector3f w,
                               const SampledWavelengths& lambda) const;

    const Shape* shape;
    const Material* material;
    FloatTexture temperature;
    EmissionModel model;
    Float scale;
    const ReflectanceTable* reflectance;
};

}  // namespace kiln
