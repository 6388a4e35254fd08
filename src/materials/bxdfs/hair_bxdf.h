// Hair scattering (pbrt-v4's HairBxDF): the model of Chiang, Bitterli, Tappan and Burley 2016,
// "A Practical and Controllable Hair and Fur Model for Production Path Tracing", after d'Eon et
// al. 2011 and Marschner et al. 2003. A fibre is a rough dielectric cylinder with an absorbing
// interior: light leaving after p internal paths (R, TT, TRT, and the rest summed) has a
// longitudinal lobe Mp (tilted by the cuticle scales, alpha), an attenuation Ap (Fresnel and
// absorption sigma_a per unit diameter) and an azimuthal lobe Np (trimmed logistic).
//
// Local frame: x along the fibre (dp/du), z the curve's normal facing the ray, h = -1 ... 1 the
// offset across the fibre where the ray met it (from the curve's v: h = 2 v - 1). With
// sigma_a = 0 the model conserves energy: the attenuations sum to 1, and sampling draws wi
// with density proportional to f |cos theta_i|, every sample's weight exactly 1.
#pragma once

#include <array>
#include <optional>

#include "materials/bxdfs/bxdf_types.h"
#include "spectral/color.h"

namespace kiln {

class HairBxDF {
  public:
    static constexpr int pMax = 3;
    // Scattering in the fibre is tracked unpolarised: the hair BSDF depolarises (bxdf.h).
    static constexpr bool kDepolarizes = true;

    // h in [-1, 1]; eta: the fibre's refractive index; sigma_a: absorption per unit diameter;
    // beta_m, beta_n in [0, 1]: longitudinal and azimuthal roughness; alpha: scale tilt
    // (degrees).
    HairBxDF(Float h, Float eta, const SampledSpectrum& sigma_a, Float beta_m, Float beta_n,
             Float alpha);

    SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode mode) const;
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    // pbrt-v4 declares hair a glossy reflector (it scatters to every direction).
    BxDFFlags Flags() const { return BxDFFlags::GlossyReflection; }
    void Regularize() {}
    // The directional albedo, the integral of f |cos theta_i| over every wi: the lobes Mp and
    // Np are normalised, so it is the sum of the attenuations, f + (1 - f)^2 T / (1 - T f) (f
    // the Fresnel reflectance at the fibre's surface, T one crossing's transmittance). What a
    // hot fibre does not scatter it emits (thermal/material_albedo.h).
    SampledSpectrum Albedo(Vector3f wo) const;

    // Absorption (per unit diameter, linear sRGB) of eumelanin and pheomelanin concentrations
    // (d'Eon et al. 2011's coefficients, as pbrt-v4).
    static RGB SigmaAFromConcentration(Float eumelanin, Float pheomelanin);
    // The absorption that gives the hair colour c (in [0, 1]) after multiple scattering at
    // azimuthal roughness beta_n (Chiang et al. 2016's fit).
    static SampledSpectrum SigmaAFromReflectance(const SampledSpectrum& c, Float beta_n);

  private:
    // The scale-tilted sin and cos of theta_o for lobe p.
    void TiltedThetaO(int p, Float sinThetaO, Float cosThetaO, Float* sinThetaOp,
                      Float* cosThetaOp) const;
    std::array<SampledSpectrum, pMax + 1> Attenuation(Float cosThetaO, Float sinThetaO) const;
    std::array<Float, pMax + 1> LobePDF(Float cosThetaO, Float sinThetaO) const;
    // The refracted ray's gamma_t.
    Float GammaT(Float sinThetaO, Float cosThetaO) const;
    // sum over lobes p of Mp Np weights[p]: f |cos theta_i| with the attenuations as weights,
    // the density with the lobe probabilities (dphi = phi_i - phi_o).
    template <typename W>
    W SumLobes(Float sinThetaO, Float cosThetaO, Float sinThetaI, Float cosThetaI, Float dphi,
               const std::array<W, pMax + 1>& weights) const;

    Float h, gammaO, eta;
    SampledSpectrum sigma_a;
    Float v[pMax + 1];  // longitudinal variances
    Float s;            // azimuthal logistic scale
    Float sin2kAlpha[pMax], cos2kAlpha[pMax];
};

}  // namespace kiln
