#include "lights/thermal_emission.h"

#include <cmath>

#include "materials/emissivity.h"
#include "spectral/planck.h"

namespace kiln {

Float ThermalEmission::Temperature(const SurfaceInteraction& si) const {
    Float T = temperature.Evaluate(TextureEvalContext(si));
    return std::isfinite(T) && T > 0 ? T : 0;
}

SampledSpectrum ThermalEmission::L(const SurfaceInteraction& si, const BSDF& bsdf, Vector3f w,
                                   const SampledWavelengths& lambda) const {
    if (model == EmissionModel::None) return SampledSpectrum(0.f);
    Float T = Temperature(si);
    if (T <= 0) return SampledSpectrum(0.f);
    SampledSpectrum B = scale * planck_radiance(lambda, T);
    if (model != EmissionModel::Kirchhoff) return B;
    if (!bsdf) return SampledSpectrum(0.f);
    return B * (SampledSpectrum(1.f) - albedo->Evaluate(si.material, bsdf, w, lambda));
}

Float ThermalEmission::VisibleExitance(const SurfaceInteraction& si, const BSDF& bsdf) const {
    if (model == EmissionModel::None) return 0;
    Float T = Temperature(si);
    if (T <= 0) return 0;
    if (model == EmissionModel::Kirchhoff && !bsdf) return 0;
    // Midpoints of 8 equal intervals of 360-830 nm, as two sets of four wavelengths
    constexpr Float lambdaMin = 360, lambdaMax = 830;
    double sum = 0;
    for (Float u : {1.f / 16, 9.f / 16}) {
        SampledWavelengths lambda = SampledWavelengths::SampleUniform(u, lambdaMin, lambdaMax);
        SampledSpectrum M = scale * planck_radiance(lambda, T);
        if (model == EmissionModel::Kirchhoff)
            M *= SampledSpectrum(1.f) - albedo->Hemispherical(si.material, bsdf, lambda);
        for (int i = 0; i < NSpectrumSamples; ++i) sum += M[i];
    }
    return Float(2 * Pi * sum * (lambdaMax - lambdaMin) / 8);
}

}  // namespace kiln
