// Deterministic quadrature over the visible microfacet normals of an isotropic Trowbridge-Reitz
// (GGX) distribution, for tables built at load (emissivity = 1 - albedo; see
// thermal/material_albedo.h). Never used per sample.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

// Smith's Lambda of isotropic Trowbridge-Reitz roughness alpha for a direction with
// |cos theta| = mu (double precision; TrowbridgeReitzDistribution::Lambda for tables).
inline double SmithLambda(double alpha, double mu) {
    double mu2 = mu * mu;
    if (mu2 <= 0) return 1e30;
    return (std::sqrt(1 + alpha * alpha * std::max(0.0, 1 - mu2) / mu2) - 1) / 2;
}

struct NormalQuadraturePoint {
    Vector3f wm;    // microfacet normal, local frame (+z up)
    double weight;  // quadrature weight
};

// Which microfacet normals the quadrature covers: the normals visible from wo with
// wo . wm > cosLo (0: all visible normals; e.g. the critical cosine of total internal
// reflection to keep only normals that transmit), and, with a reflection band, only those that
// mirror wo into a direction whose cos theta lies in [muLo, muHi] (muLo = 0, muHi = 1: all
// reflections above the horizon).
struct NormalRegion {
    double cosLo = 0;
    bool reflectionBand = false;
    double muLo = 0, muHi = 1;

    static NormalRegion Visible(double cosLo = 0) { return {cosLo}; }
    static NormalRegion Reflected(double lo = 0, double hi = 1) { return {0, true, lo, hi}; }
};

// Points and weights with
//   sum_i weight_i g(wm_i) ~ integral over the region of D_wo(wm) g(wm) dwm,
//   D_wo(wm) = G1(wo) max(0, wo . wm) D(wm) / cos(theta_o)
// (the density of normals visible from wo, which integrates to 1 over Visible), for
// wo = (sin theta_o, 0, cos theta_o), cos theta_o = cosThetaO in (0, 1], and roughness alpha
// (isotropic). g must be symmetric about the plane of incidence: the points lie on the y >= 0
// half and their weights count both halves.
//
// Normals are parameterised by x = (2 / pi) atan(tan(theta_m) / alpha) in [0, 1), which spreads
// the points evenly over the lobe and its long tail for every alpha, and by phi. For each x the
// region is an interval of phi computed exactly (the reflected cosine is linear in cos phi), so
// an integrand that is smooth in the region is integrated accurately; the x axis is split where
// the interval's ends reach 0 or pi, and both axes use a smoothstep substitution on each
// interval to absorb the square-root behaviour of the region's boundary there. xPanels x 8
// points in x (Gauss-Legendre per panel), phiPanels x 8 in phi.
std::vector<NormalQuadraturePoint> VisibleNormalQuadrature(double alpha, double cosThetaO,
                                                           const NormalRegion& region,
                                                           int xPanels = 8, int phiPanels = 2);

}  // namespace kiln
