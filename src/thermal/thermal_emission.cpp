#include "thermal/thermal_emission.h"

#include <cmath>

#include "spectral/planck.h"
#include "thermal/material_albedo.h"
#include "thermal/surface_emission.h"

namespace kiln {

namespace {

// A reflectance for the models that do not ask for one (additive, diffuse)
struct NoReflectance {
    SampledSpectrum DirectionalAlbedo(Vector3f, const SampledWavelengths&) const { return {}; }
    ReflectedPolarization LinearPolarization(Vector3f) const { return {}; }
};

}  // namespace

Float ThermalEmission::Temperature(const SurfaceInteraction& si) const {
    Float T = temperature.Evaluate(TextureEvalContext(si));
    return std::isfinite(T) && T > 0 ? T : 0;
}

template <typename Radiance>
Radiance ThermalEmission::L(const SurfaceInteraction& si, const BSDF& bsdf, Vector3f w,
                            const SampledWavelengths& lambda) const {
    if (model == EmissionModel::None) return {};
    Float T = Temperature(si);
    if (T <= 0) return {};
    SampledSpectrum B = scale * planck_radiance(lambda, T);
    if (model != EmissionModel::Kirchhoff) return Radiance(B);
    if (!bsdf) return {};
    return SurfaceEmission<Radiance>(model, B, albedo->Reflectance(si.material, bsdf, &si),
                                     bsdf.ShadingFrame(), w, lambda);
}

template SampledSpectrum ThermalEmission::L<SampledSpectrum>(const SurfaceInteraction&, const BSDF&,
                                                             Vector3f,
                                                             const SampledWavelengths&) const;
template Stokes ThermalEmission::L<Stokes>(const SurfaceInteraction&, const BSDF&, Vector3f,
                                           const SampledWavelengths&) const;

Float ThermalEmission::BandExitance(const SurfaceInteraction& si, const BSDF& bsdf) const {
    if (model != EmissionModel::Kirchhoff)
        return kiln::BandExitance(model, Temperature(si), scale, NoReflectance{}, band);
    if (!bsdf) return 0;
    return kiln::BandExitance(model, Temperature(si), scale,
                              albedo->Reflectance(si.material, bsdf, &si), band);
}

}  // namespace kiln
