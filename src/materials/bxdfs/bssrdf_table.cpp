#include "materials/bxdfs/bssrdf_table.h"

#include <chrono>
#include <cmath>

#include "base/catmull_rom.h"
#include "base/sampling.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/hg_phase_function.h"

namespace kiln {

Float FresnelMoment1(Float eta) {
    Float eta2 = eta * eta, eta3 = eta2 * eta, eta4 = eta3 * eta, eta5 = eta4 * eta;
    if (eta < 1)
        return 0.45966f - 1.73965f * eta + 3.37668f * eta2 - 3.904945f * eta3 + 2.49277f * eta4 -
               0.68441f * eta5;
    return -4.61686f + 11.1136f * eta - 10.4646f * eta2 + 5.11455f * eta3 - 1.27198f * eta4 +
           0.12746f * eta5;
}

Float FresnelMoment2(Float eta) {
    Float eta2 = eta * eta, eta3 = eta2 * eta, eta4 = eta3 * eta, eta5 = eta4 * eta;
    if (eta < 1)
        return 0.27614f - 0.87350f * eta + 1.12077f * eta2 - 0.65095f * eta3 + 0.07883f * eta4 +
               0.04860f * eta5;
    Float r = 1 / eta, r2 = r * r, r3 = r2 * r;
    return -547.033f + 45.3087f * r3 - 218.725f * r2 + 458.843f * r + 404.557f * eta -
           189.519f * eta2 + 54.9327f * eta3 - 9.00603f * eta4 + 0.63942f * eta5;
}

Float BeamDiffusionMS(Float sigma_s, Float sigma_a, Float g, Float eta, Float r) {
    constexpr int nSamples = 100;
    // Reduced coefficients, Grosjean's diffusion coefficient and the transport coefficient
    Float sigmap_s = sigma_s * (1 - g), sigmap_t = sigma_a + sigmap_s;
    Float rhop = sigmap_s / sigmap_t;
    Float D_g = (2 * sigma_a + sigmap_s) / (3 * sigmap_t * sigmap_t);
    Float sigma_tr = SafeSqrt(sigma_a / D_g);
    // Extrapolated boundary distance and the exitance weights of fluence and flux
    Float fm1 = FresnelMoment1(eta), fm2 = FresnelMoment2(eta);
    Float ze = -2 * D_g * (1 + 3 * fm2) / (1 - 2 * fm1);
    Float cPhi = 0.25f * (1 - 2 * fm1), cE = 0.5f * (1 - 3 * fm2);
    Float Ed = 0;
    for (int i = 0; i < nSamples; ++i) {
        // A real source at depth zr along the beam (stratified exponential depths) and its
        // mirror image about the extrapolated boundary
        Float zr = SampleExponential((i + 0.5f) / nSamples, sigmap_t);
        Float zv = -zr + 2 * ze;
        Float dr = std::sqrt(Sqr(r) + Sqr(zr)), dv = std::sqrt(Sqr(r) + Sqr(zv));
        Float phiD = Inv4Pi / D_g * (std::exp(-sigma_tr * dr) / dr - std::exp(-sigma_tr * dv) / dv);
        Float EDn = Inv4Pi * (zr * (1 + sigma_tr * dr) * std::exp(-sigma_tr * dr) / (dr * dr * dr) -
                              zv * (1 + sigma_tr * dv) * std::exp(-sigma_tr * dv) / (dv * dv * dv));
        Float E = phiD * cPhi + EDn * cE;
        // Habel et al.'s correction for sources near the point of entry
        Float kappa = 1 - std::exp(-2 * sigmap_t * (dr + zr));
        Ed += kappa * rhop * rhop * E;
    }
    return Ed / nSamples;
}

Float BeamDiffusionSS(Float sigma_s, Float sigma_a, Float g, Float eta, Float r) {
    Float sigma_t = sigma_a + sigma_s, rho = sigma_s / sigma_t;
    // Depths below tCrit reach the exit point beyond the critical angle
    Float tCrit = r * SafeSqrt(Sqr(eta) - 1);
    constexpr int nSamples = 100;
    Float Ess = 0;
    for (int i = 0; i < nSamples; ++i) {
        Float ti = tCrit + SampleExponential((i + 0.5f) / nSamples, sigma_t);
        Float d = std::sqrt(Sqr(r) + Sqr(ti));
        Float cosTheta_o = ti / d;
        Ess += rho * std::exp(-sigma_t * (d + tCrit)) / Sqr(d) *
               HenyeyGreenstein(cosTheta_o, Clamp(g, -.99f, .99f)) *
               (1 - FrDielectric(-cosTheta_o, eta)) * std::abs(cosTheta_o);
    }
    return Ess / nSamples;
}

BSSRDFTable::BSSRDFTable(Float g, Float eta)
    : g(g),
      eta(eta),
      rhoSamples(100),
      radiusSamples(64),
      profile(rhoSamples.size() * radiusSamples.size()),
      rhoEff(rhoSamples.size()),
      profileCDF(profile.size()) {
    radiusSamples[0] = 0;
    radiusSamples[1] = 2.5e-3f;
    for (size_t i = 2; i < radiusSamples.size(); ++i)
        radiusSamples[i] = radiusSamples[i - 1] * 1.2f;
    const Float nRho = Float(rhoSamples.size() - 1);
    for (size_t i = 0; i < rhoSamples.size(); ++i)
        rhoSamples[i] = (1 - std::exp(-8 * Float(i) / nRho)) / (1 - std::exp(Float(-8)));
    const size_t n = radiusSamples.size();
    for (size_t i = 0; i < rhoSamples.size(); ++i) {
        Float rho = rhoSamples[i];
        for (size_t j = 0; j < n; ++j) {
            Float r = radiusSamples[j];
            profile[i * n + j] = 2 * Pi * r *
                                 (BeamDiffusionSS(rho, 1 - rho, g, eta, r) +
                                  BeamDiffusionMS(rho, 1 - rho, g, eta, r));
        }
        rhoEff[i] = IntegrateCatmullRom(radiusSamples, std::span<const Float>(&profile[i * n], n),
                                        std::span<Float>(&profileCDF[i * n], n));
    }
}

Float BSSRDFTable::EffectiveAlbedo(Float rho) const { return CatmullRom(rhoSamples, rhoEff, rho); }

Float BSSRDFTable::InvertEffectiveAlbedo(Float r) const {
    return InvertCatmullRom(rhoSamples, rhoEff, r);
}

const BSSRDFTable& BSSRDFTableCache::Get(Float g, Float eta) {
    for (const auto& t : tables)
        if (t->G() == g && t->Eta() == eta) return *t;
    auto start = std::chrono::steady_clock::now();
    tables.push_back(std::make_unique<BSSRDFTable>(g, eta));
    buildSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return *tables.back();
}

}  // namespace kiln
