// Thermal emission of an opaque surface at a hit: the thermal module's host interface for
// surfaces (docs/thermal-module.md). It depends on base/ and spectral/ only. The host hands in
// the temperature, the shading frame and an object that answers for the BSDF it scatters with
// at that point; the module answers the emitted radiance, unpolarised or as a Stokes vector.
//
// Wilkie & Weidlich 2011's approaches (emission_model.h), with B = scale B(lambda, T) Planck's
// spectral radiance in W m^-2 sr^-1 nm^-1 (spectral/planck.h):
//   kirchhoff: Le = B (1 - A(wo)), A the directional albedo of the surface's own BSDF
//   additive:  Le = B (the surface also reflects as usual)
//   diffuse:   Le = B (the host gives the surface a non-reflecting BSDF)
// Polarisation (Kirchhoff per polarisation state): in a closed isothermal cavity the light a
// surface reflects towards wo, Stokes B (A, a1, a2, 0) with reference axis perpendicular to the
// plane of the shading normal and wo, plus what it emits must be unpolarised B, so it emits
// B (1 - A, -a1, -a2, 0): polarised parallel to that plane where its reflection is polarised
// perpendicular to it. Additive and diffuse emission are unpolarised, as in the paper.
#pragma once

#include <algorithm>
#include <concepts>
#include <limits>
#include <type_traits>

#include "base/vecmath.h"
#include "spectral/planck.h"
#include "spectral/polarization.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/spectral_range.h"
#include "thermal/emission_model.h"

namespace kiln {

// The polarisation of what a BSDF reflects towards wo under uniform unpolarised illumination of
// unit radiance: Stokes S1 and S2 with reference axis perpendicular to the plane of the normal
// and wo (S0 is the albedo; S3 vanishes). Zero for depolarising BSDFs.
struct ReflectedPolarization {
    SampledSpectrum s1, s2;
    explicit operator bool() const { return bool(s1) || bool(s2); }
};

// What the module asks of the host's BSDF at the hit, directions in its local shading frame
// (z the shading normal): the directional albedo A(wo) (the expected f |cos| / pdf of the BSDF
// the integrator scatters with, in [0, 1] per wavelength) and the polarisation of its
// reflection (only for polarised transport).
template <typename R>
concept SurfaceReflectance = requires(const R& r, Vector3f wo, const SampledWavelengths& lambda) {
    { r.DirectionalAlbedo(wo, lambda) } -> std::convertible_to<SampledSpectrum>;
    { r.LinearPolarization(wo) } -> std::convertible_to<ReflectedPolarization>;
};

// Optionally, a reflectance also answers r.EquilibriumScale(wo, lambda): the radiance of
// thermal equilibrium on wo's side of the surface over B, n^2 inside a transparent body of
// refractive index n (radiance in a medium of index n is n^2 times that in vacuum). Where it
// exceeds 1 the surface emits that much more towards wo: B n^2 (1 - A(wo)). 1 where absent.
template <typename R>
SampledSpectrum EquilibriumScaleOf(const R& r, Vector3f wo, const SampledWavelengths& lambda) {
    if constexpr (requires { r.EquilibriumScale(wo, lambda); })
        return r.EquilibriumScale(wo, lambda);
    else
        return SampledSpectrum(1.f);
}

// Radiance emitted towards w (render space) by a surface with blackbody radiance B at the hit,
// shading frame `shading` and reflectance r. Radiance: SampledSpectrum, or Stokes in the
// implicit frame of w (spectral/polarization.h).
template <typename Radiance, SurfaceReflectance R>
Radiance SurfaceEmission(EmissionModel model, const SampledSpectrum& B, const R& r,
                         const Frame& shading, Vector3f w, const SampledWavelengths& lambda) {
    if (model == EmissionModel::None) return {};
    if (model != EmissionModel::Kirchhoff) return Radiance(B);
    Vector3f wo = shading.ToLocal(w);
    SampledSpectrum Bside = B * EquilibriumScaleOf(r, wo, lambda);
    SampledSpectrum Le = Bside * (SampledSpectrum(1.f) - r.DirectionalAlbedo(wo, lambda));
    if constexpr (std::is_same_v<Radiance, SampledSpectrum>) {
        return Le;
    } else {
        ReflectedPolarization a = r.LinearPolarization(wo);
        if (!a) return Stokes(Le);
        // B (1 - A, -a1, -a2, 0) with reference axis perpendicular to the plane of ns and w
        Vector3f axis = shading.FromLocal(PlaneAxis(Vector3f(0, 0, 1), wo));
        return RotateStokesBasis(Stokes(Le, -Bside * a.s1, -Bside * a.s2, {}), w, axis,
                                 StokesBasis(w));
    }
}

// Cosine-weighted hemispherical albedo 2 integral A(mu) mu dmu of r (for power estimates), by
// 4-point Gauss-Legendre quadrature over mu.
template <SurfaceReflectance R>
SampledSpectrum HemisphericalAlbedo(const R& r, const SampledWavelengths& lambda) {
    // 4-point Gauss-Legendre nodes and weights on [0, 1]
    constexpr Float mus[4] = {0.0694318442f, 0.3300094782f, 0.6699905218f, 0.9305681558f};
    constexpr Float ws[4] = {0.1739274226f, 0.3260725774f, 0.3260725774f, 0.1739274226f};
    SampledSpectrum sum(0.f);
    for (int i = 0; i < 4; ++i) {
        Vector3f wo(std::sqrt(1 - mus[i] * mus[i]), 0, mus[i]);
        sum += 2 * mus[i] * ws[i] * r.DirectionalAlbedo(wo, lambda);
    }
    return sum;
}

// Radiant exitance over the band (the scene's wavelengths, by default 360-830 nm) from both
// sides, W m^-2: 2 pi scale times the integral of B(lambda, T) over the band (exact:
// planck_band_radiance) for additive and diffuse; for kirchhoff times the hemispherical
// emissivity 1 - HemisphericalAlbedo averaged with weights B at the midpoints of 8 equal
// intervals of the band (exact for an emissivity constant over the band). For power estimates
// (light selection), not for radiance.
template <SurfaceReflectance R>
Float BandExitance(EmissionModel model, Float T, Float scale, const R& r,
                   const SpectralRange& band = {}) {
    if (model == EmissionModel::None || !(T > 0)) return 0;
    const Float lambdaMin = band.min, lambdaMax = band.max;
    double M = 2 * Pi * double(scale) * planck_band_radiance(lambdaMin, lambdaMax, T);
    if (model == EmissionModel::Kirchhoff) {
        // The midpoints (2k + 1) / 16 of the band, as two sets of four equally spaced ones
        double sumB = 0, sumBe = 0;
        for (Float u : {1.f / 16, 3.f / 16}) {
            SampledWavelengths lambda = SampledWavelengths::SampleUniform(u, lambdaMin, lambdaMax);
            SampledSpectrum B = planck_radiance(lambda, T);
            SampledSpectrum e = SampledSpectrum(1.f) - HemisphericalAlbedo(r, lambda);
            for (int i = 0; i < NSpectrumSamples; ++i) {
                sumB += B[i];
                sumBe += double(B[i]) * e[i];
            }
        }
        M *= sumB > 0 ? sumBe / sumB : 0;
    }
    return Float(std::min(M, double(std::numeric_limits<Float>::max())));
}

}  // namespace kiln
