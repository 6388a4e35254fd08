// Trowbridge-Reitz (GGX) microfacet distribution with anisotropic roughness.
//
// Directions are unit vectors in the local shading frame (normal = +z). D(wm) is the
// distribution of microfacet normals (sr^-1, projected-area normalised: integral of
// D(wm) cos(theta_m) dwm = 1); G1/G are Smith's masking and masking-shadowing functions
// (dimensionless); D(w, wm) is the distribution of normals visible from w (sr^-1).
// References: Trowbridge & Reitz 1975; Walter et al. 2007; Heitz 2018 ("Sampling the GGX
// Distribution of Visible Normals", JCGT 7(4)); pbrt-v4 Sec. 9.6.
#pragma once

#include "base/vecmath.h"

namespace kiln {

// A rough BxDF's value between two directions without its Fresnel factor: the microfacet normal
// wm and the rest of f (D, G, Jacobians, sr^-1), for the unpolarised (scalar Fresnel) and
// polarised (Fresnel Mueller matrix) values to share.
struct MicrofacetTerm {
    Vector3f wm;
    Float scale;
    bool reflect = true;  // reflection (else refraction)
};

class TrowbridgeReitzDistribution {
  public:
    TrowbridgeReitzDistribution() = default;
    // alpha_x, alpha_y: roughness along the x and y axes of the shading frame (alpha = RMS
    // microfacet slope / sqrt 2). Effectively smooth below 1e-3; otherwise clamped to >= 1e-4.
    // Alphas are clamped to [0, kMaxAlpha] (NaN to 0): beyond it the lobe no longer changes
    // visibly, and alpha^2 tan^2(theta) must stay within float range.
    TrowbridgeReitzDistribution(Float alpha_x, Float alpha_y);
    static constexpr Float kMaxAlpha = 1e3f;

    Float D(Vector3f wm) const;
    Float D(Vector3f w, Vector3f wm) const {
        if (w.z == 0) return 0;
        return G1(w) / AbsCosTheta(w) * D(wm) * AbsDot(w, wm);
    }
    Float Lambda(Vector3f w) const;
    Float G1(Vector3f w) const { return 1 / (1 + Lambda(w)); }
    Float G(Vector3f wo, Vector3f wi) const { return 1 / (1 + Lambda(wo) + Lambda(wi)); }

    // Density of Sample_wm (visible normals from w), per steradian of wm.
    Float PDF(Vector3f w, Vector3f wm) const { return D(w, wm); }
    // Samples a normal visible from w (in the hemisphere of +z; w may lie on either side).
    Vector3f Sample_wm(Vector3f w, Point2f u) const;

    bool EffectivelySmooth() const { return std::max(alpha_x, alpha_y) < 1e-3f; }
    // pbrt-v4's mapping from the user-facing "roughness" parameter.
    static Float RoughnessToAlpha(Float roughness) { return std::sqrt(roughness); }
    // Widens near-specular lobes (path regularisation), as pbrt-v4.
    void Regularize();

    Float AlphaX() const { return alpha_x; }
    Float AlphaY() const { return alpha_y; }

  private:
    Float alpha_x = 0, alpha_y = 0;
};

}  // namespace kiln
