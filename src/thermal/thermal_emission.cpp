#include "thermal/thermal_emission.h"

#include <cmath>

#include "materials/bxdfs/fresnel_mueller.h"
#include "spectral/planck.h"
#include "thermal/material_albedo.h"

namespace kiln {

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
    SampledSpectrum Le =
        B * (SampledSpectrum(1.f) - albedo->Evaluate(si.material, bsdf, w, lambda));
    if constexpr (std::is_same_v<Radiance, SampledSpectrum>) {
        return Le;
    } else {
        ReflectedPolarization a = albedo->LinearPolarization(si.material, bsdf, w);
        if (!a) return Stokes(Le);
        // B (1 - A, -a1, -a2, 0) with reference axis perpendicular to the plane of ns and w
        Vector3f axis = bsdf.LocalToRender(PlaneAxis(Vector3f(0, 0, 1), bsdf.RenderToLocal(w)));
        return RotateStokesBasis(Stokes(Le, -B * a.s1, -B * a.s2, {}), w, axis, StokesBasis(w));
    }
}

template SampledSpectrum ThermalEmission::L<SampledSpectrum>(const SurfaceInteraction&, const BSDF&,
                                                             Vector3f,
                                                             const SampledWavelengths&) const;
template Stokes ThermalEmission::L<Stokes>(const SurfaceInteraction&, const BSDF&, Vector3f,
                                           const SampledWavelengths&) const;

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
