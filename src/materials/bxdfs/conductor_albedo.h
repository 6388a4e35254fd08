// Directional albedo of the rough conductor BxDF as a linear functional of its Fresnel
// reflectance, for Kirchhoff emission (emissivity = 1 - albedo; thermal/material_albedo.h).
//
// pbrt-v4's rough conductor reflects into direction wi = reflect(wo, wm) about a microfacet
// normal wm with weight F(wo . wm) G2(wo, wi) / G1(wo) when wm is drawn from the normals
// visible from wo (Sample_f), so its directional albedo is
//   A(wo) = integral D_wo(wm) F(wo . wm) G2(wo, wi) / G1(wo) [wi.z > 0] dwm.
// The Fresnel term depends on the material and wavelength, the rest only on alpha and theta_o;
// interpolating F cubically between fixed nodes mu_j of wo . wm makes A a weighted sum
//   A(wo) = sum_j W_j(alpha, cos theta_o) F(mu_j).
// The weights W_j come from deterministic quadrature (microfacet_quadrature.h); their sum is the
// albedo of a perfect (F = 1) mirror metal, which misses the multiply scattered energy.
#pragma once

#include <array>
#include <cstddef>

namespace kiln {

class ConductorAlbedoMoments {
  public:
    static constexpr int kNodes = 32;
    // The nodes mu_j of wo . wm, increasing from 0 to 1 (denser towards 0, where the Fresnel
    // reflectance of conductors rises to 1).
    static double Node(int j);
    // Cubic interpolation of F at mu through four nodes: F(mu) ~ sum_a w[a] F(Node(first + a));
    // returns first.
    static int InterpolationWeights(double mu, double w[4]);
    using Weights = std::array<double, kNodes>;
    // W_j for isotropic roughness alpha (> 0) seen from cos(theta_o) in (0, 1].
    static Weights Compute(double alpha, double cosThetaO);
    // Weights for the linear polarisation of the reflected light instead (polarised Kirchhoff
    // emission, thermal/material_albedo.h): under uniform unpolarised illumination a microfacet
    // reflects Stokes (F, dF, 0, 0) with dF = (Rs - Rp) / 2 in its own plane of incidence, whose
    // s axis is turned by chi about wo from the surface's; S1 with the surface's axis is
    // dF cos(2 chi), and S2 integrates to zero for isotropic roughness. So
    //   a1(wo) = sum_j W'_j dF(mu_j),
    // W'_j the weights above with the factor cos(2 chi) in the integrand.
    static Weights ComputeLinearPolarization(double alpha, double cosThetaO);
    // W_j for anisotropic roughness (alphaX, alphaY > 0) seen from the unit direction wo (local
    // frame, wo.z > 0). Normals are parameterised by psi, with tan(phi_m) = (alphaY / alphaX)
    // tan(psi) (uniform in psi for the distribution's azimuthal marginal, so its narrow peaks
    // at strong anisotropy are resolved), and x = (2 / pi) atan(tan(theta_m) / alpha(phi_m)),
    // alpha(phi_m) the roughness along that azimuth. At each psi the normals reflecting wo above
    // the horizon are exactly those with theta_m below a bound that varies smoothly with psi
    // (and are all visible), steeply near the azimuths perpendicular to wo's at grazing
    // incidence, and the normals of the smoother axis crowd into a narrow window of psi around
    // it; the psi circle is split at both, and each arc and the x interval use smoothstep
    // Gauss-Legendre rules (psiPanels x 8 points per half circle, xPanels x 8 in x), whose
    // points cluster at the ends.
    static Weights Compute(double alphaX, double alphaY, const double wo[3], int psiPanels = 3,
                           int xPanels = 4);
    // Anisotropic roughness: the weights of S1 (factor cos(2 chi)) and S2 (factor -sin(2 chi))
    // of the reflected light about the plane of the normal and wo, where S2 does not vanish.
    struct PolarizationWeights {
        Weights cos2, sin2;
    };
    static PolarizationWeights ComputeLinearPolarization(double alphaX, double alphaY,
                                                         const double wo[3], int psiPanels = 3,
                                                         int xPanels = 4);
    // Sum over the nodes of W_j F(mu_j), F given as a function of mu.
    template <typename F>
    static double Apply(const Weights& w, F&& fresnel) {
        double a = 0;
        for (int j = 0; j < kNodes; ++j) a += w[std::size_t(j)] * fresnel(Node(j));
        return a;
    }
};

}  // namespace kiln
