#include "materials/bxdfs/microfacet_quadrature.h"

#include <algorithm>
#include <cmath>

#include "base/quadrature.h"

namespace kiln {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Smoothstep substitution on [a, b], appended to t and w.
void SmoothstepRule(double a, double b, int panels, std::vector<double>* t,
                    std::vector<double>* w) {
    QuadratureRule r = SmoothstepGaussLegendre(panels, 8, a, b);
    t->insert(t->end(), r.x.begin(), r.x.end());
    w->insert(w->end(), r.weight.begin(), r.weight.end());
}

// The phi interval [phi0, phi1] of the region at theta_m (empty when phi1 <= phi0).
// Visibility: wo . wm = sin_o sin_m cos(phi) + cos_o cos_m > cosLo. Reflection band: the
// reflected cosine 2 (wo . wm) cos_m - cos_o = A cos(phi) + B, A = 2 sin_o sin_m cos_m,
// B = cos_o (2 cos_m^2 - 1), in [muLo, muHi].
void PhiInterval(double thetaM, double sinThetaO, double cosThetaO, const NormalRegion& region,
                 double* phi0, double* phi1) {
    double lo = -1, hi = 1;  // bounds on cos(phi)
    double sm = std::sin(thetaM), cm = std::cos(thetaM);
    double A = sinThetaO * sm, B = cosThetaO * cm;
    if (A > 0)
        lo = std::max(lo, (region.cosLo - B) / A);
    else if (B <= region.cosLo)
        lo = 2;  // nothing visible
    if (region.reflectionBand) {
        double Ar = 2 * sinThetaO * sm * cm, Br = cosThetaO * (2 * cm * cm - 1);
        if (Ar > 0) {
            lo = std::max(lo, (region.muLo - Br) / Ar);
            hi = std::min(hi, (region.muHi - Br) / Ar);
        } else if (Br <= region.muLo || Br > region.muHi) {
            lo = 2;  // normal incidence: the reflected cosine does not depend on phi
        }
    }
    if (lo >= hi || lo >= 1 || hi <= -1) {
        *phi0 = *phi1 = 0;
        return;
    }
    *phi0 = std::acos(std::min(1.0, hi));
    *phi1 = std::acos(std::max(-1.0, lo));
}

}  // namespace

std::vector<NormalQuadraturePoint> VisibleNormalQuadrature(double alpha, double cosThetaO,
                                                           const NormalRegion& region, int xPanels,
                                                           int phiPanels) {
    double sinThetaO = std::sqrt(std::max(0.0, 1 - cosThetaO * cosThetaO));
    double thetaO = std::acos(std::clamp(cosThetaO, -1.0, 1.0));
    double tan2ThetaO = (sinThetaO * sinThetaO) / (cosThetaO * cosThetaO);
    double G1 = 1 / (1 + (std::sqrt(1 + alpha * alpha * tan2ThetaO) - 1) / 2);
    auto xOfTheta = [&](double theta) {
        return theta <= 0 ? 0.0 : 2 / kPi * std::atan(std::tan(theta) / alpha);
    };

    // x breakpoints: where the interval's ends reach 0 or pi. wo . wm = c is reached at
    // phi = 0 and phi = pi for theta_m = acos(c) -+ theta_o; a reflected cosine mu for
    // theta_m = (acos(mu) +- theta_o) / 2.
    std::vector<double> breaks = {0, 1};
    for (double sign : {-1.0, 1.0}) {
        double theta = std::acos(std::clamp(region.cosLo, -1.0, 1.0)) + sign * thetaO;
        if (theta > 0 && theta < kPi / 2) breaks.push_back(xOfTheta(theta));
    }
    if (region.reflectionBand)
        for (double mu : {region.muLo, region.muHi})
            for (double sign : {-1.0, 1.0}) {
                double theta = (std::acos(std::clamp(mu, -1.0, 1.0)) + sign * thetaO) / 2;
                if (theta > 0 && theta < kPi / 2) breaks.push_back(xOfTheta(theta));
            }
    std::sort(breaks.begin(), breaks.end());
    std::vector<double> xs, xw;
    for (size_t b = 0; b + 1 < breaks.size(); ++b) {
        double x0 = breaks[b], x1 = std::min(breaks[b + 1], 1.0);
        if (!(x1 > x0 + 1e-12)) continue;
        // Panels in proportion to the interval's length, at least one
        SmoothstepRule(x0, x1, std::max(1, int(std::ceil(xPanels * (x1 - x0)))), &xs, &xw);
    }

    std::vector<NormalQuadraturePoint> points;
    std::vector<double> phis, phiw;
    for (size_t i = 0; i < xs.size(); ++i) {
        // t = tan(theta_m) / alpha; D(wm) sin(theta_m) dtheta_m / dx per radian of phi
        double t = std::tan(kPi / 2 * xs[i]);
        double at = alpha * t, s = std::sqrt(1 + at * at);
        double sinThetaM = at / s, cosThetaM = 1 / s;
        double jacobianD = t * s / (2 * (1 + t * t));
        double phi0, phi1;
        PhiInterval(std::atan(at), sinThetaO, cosThetaO, region, &phi0, &phi1);
        if (!(phi1 > phi0)) continue;
        phis.clear();
        phiw.clear();
        SmoothstepRule(phi0, phi1, phiPanels, &phis, &phiw);
        for (size_t j = 0; j < phis.size(); ++j) {
            double phi = phis[j];
            double woDotWm = sinThetaO * sinThetaM * std::cos(phi) + cosThetaO * cosThetaM;
            if (woDotWm <= std::max(0.0, region.cosLo)) continue;
            Vector3f wm(Float(sinThetaM * std::cos(phi)), Float(sinThetaM * std::sin(phi)),
                        Float(cosThetaM));
            // Both halves of the phi circle: factor 2
            double w = 2 * xw[i] * phiw[j] * jacobianD * G1 * woDotWm / cosThetaO;
            points.push_back({wm, w});
        }
    }
    return points;
}

}  // namespace kiln
