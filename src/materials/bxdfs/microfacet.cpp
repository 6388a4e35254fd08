#include "materials/bxdfs/microfacet.h"

namespace kiln {

TrowbridgeReitzDistribution::TrowbridgeReitzDistribution(Float ax, Float ay)
    // Negative or NaN alphas (from textures) become 0; huge ones kMaxAlpha
    : alpha_x(std::min(std::max(0.f, ax), kMaxAlpha)),
      alpha_y(std::min(std::max(0.f, ay), kMaxAlpha)) {
    if (!EffectivelySmooth()) {
        // A rough lobe with one near-zero alpha makes the slope term in D() blow up.
        alpha_x = std::max<Float>(alpha_x, 1e-4f);
        alpha_y = std::max<Float>(alpha_y, 1e-4f);
    }
}

// Distribution of normals
Float TrowbridgeReitzDistribution::D(Vector3f wm) const {
    Float tan2Theta = Tan2Theta(wm);
    if (std::isinf(tan2Theta) || std::isnan(tan2Theta)) return 0;
    Float cos4Theta = Sqr(Cos2Theta(wm));
    if (cos4Theta < 1e-16f) return 0;
    Float e = tan2Theta * (Sqr(CosPhi(wm) / alpha_x) + Sqr(SinPhi(wm) / alpha_y));
    return 1 / (Pi * alpha_x * alpha_y * cos4Theta * Sqr(1 + e));
}

// Smith masking
Float TrowbridgeReitzDistribution::Lambda(Vector3f w) const {
    Float tan2Theta = Tan2Theta(w);
    if (std::isinf(tan2Theta) || std::isnan(tan2Theta)) return 0;
    Float alpha2 = Sqr(CosPhi(w) * alpha_x) + Sqr(SinPhi(w) * alpha_y);
    return (std::sqrt(1 + alpha2 * tan2Theta) - 1) / 2;
}

// Visible-normal sampling (Heitz 2018)
Vector3f TrowbridgeReitzDistribution::Sample_wm(Vector3f w, Point2f u) const {
    // Stretch w to the configuration of a hemisphere of unit roughness.
    Vector3f wh = Normalize(Vector3f(alpha_x * w.x, alpha_y * w.y, w.z));
    if (wh.z < 0) wh = -wh;
    // Orthonormal basis around wh.
    Vector3f T1 = (wh.z < 0.99999f) ? Normalize(Cross(Vector3f(0, 0, 1), wh)) : Vector3f(1, 0, 0);
    Vector3f T2 = Cross(wh, T1);
    // Uniform point on the unit disk (polar map), warped to the visible half-disk.
    Float r = std::sqrt(u.x), phi = 2 * Pi * u.y;
    Float px = r * std::cos(phi), py = r * std::sin(phi);
    Float h = std::sqrt(std::max<Float>(0, 1 - Sqr(px)));
    py = Lerp((1 + wh.z) / 2, h, py);
    // Project onto the hemisphere and unstretch.
    Float pz = std::sqrt(std::max<Float>(0, 1 - Sqr(px) - Sqr(py)));
    Vector3f nh = px * T1 + py * T2 + pz * wh;
    return Normalize(Vector3f(alpha_x * nh.x, alpha_y * nh.y, std::max<Float>(1e-6f, nh.z)));
}

void TrowbridgeReitzDistribution::Regularize() {
    if (alpha_x < 0.3f) alpha_x = Clamp(2 * alpha_x, 0.1f, 0.3f);
    if (alpha_y < 0.3f) alpha_y = Clamp(2 * alpha_y, 0.1f, 0.3f);
}

}  // namespace kiln
