#include "materials/bxdfs/conductor_albedo.h"

#include <algorithm>
#include <cmath>

#include "base/quadrature.h"
#include "materials/bxdfs/microfacet_quadrature.h"

namespace kiln {

double ConductorAlbedoMoments::Node(int j) {
    double x = double(j) / (kNodes - 1);
    return x * x * (2 - x) * 0.5 + x * 0.5;  // spacing at 0 half that at 1
}

namespace {

// The nodes and, for each run of four starting at `first`, the denominators of their cubic
// Lagrange weights (computed once; the weights are evaluated for every quadrature point).
struct NodeTable {
    static constexpr int n = ConductorAlbedoMoments::kNodes;
    double node[n];
    double denominator[n - 3][4];
    NodeTable() {
        for (int j = 0; j < n; ++j) node[j] = ConductorAlbedoMoments::Node(j);
        for (int f = 0; f + 3 < n; ++f)
            for (int a = 0; a < 4; ++a) {
                denominator[f][a] = 1;
                for (int b = 0; b < 4; ++b)
                    if (b != a) denominator[f][a] *= node[f + a] - node[f + b];
            }
    }
};

const NodeTable& Nodes() {
    static const NodeTable table;
    return table;
}

}  // namespace

int ConductorAlbedoMoments::InterpolationWeights(double mu, double w[4]) {
    const NodeTable& t = Nodes();
    mu = std::clamp(mu, 0.0, 1.0);
    int lo = int(std::upper_bound(t.node, t.node + kNodes, mu) - t.node) - 1;
    int first = std::clamp(lo - 1, 0, kNodes - 4);
    const double* x = &t.node[first];
    double d[4] = {mu - x[0], mu - x[1], mu - x[2], mu - x[3]};
    w[0] = d[1] * d[2] * d[3] / t.denominator[first][0];
    w[1] = d[0] * d[2] * d[3] / t.denominator[first][1];
    w[2] = d[0] * d[1] * d[3] / t.denominator[first][2];
    w[3] = d[0] * d[1] * d[2] / t.denominator[first][3];
    return first;
}

namespace {

// The isotropic weights, with the factor cos(2 chi) when `polarization`.
ConductorAlbedoMoments::Weights IsotropicWeights(double alpha, double cosThetaO,
                                                 bool polarization) {
    ConductorAlbedoMoments::Weights w{};
    double sinThetaO = std::sqrt(std::max(0.0, 1 - cosThetaO * cosThetaO));
    double lambdaO = SmithLambda(alpha, cosThetaO);
    for (const NormalQuadraturePoint& q :
         VisibleNormalQuadrature(alpha, cosThetaO, NormalRegion::Reflected(), 8, 2)) {
        double mu = sinThetaO * q.wm.x + cosThetaO * q.wm.z;  // wo . wm
        double wiz = 2 * mu * q.wm.z - cosThetaO;             // z of reflect(wo, wm)
        if (wiz <= 0) continue;
        double g = (1 + lambdaO) / (1 + lambdaO + SmithLambda(alpha, wiz));  // G2 / G1
        if (polarization) {
            // wo = (sin, 0, cos): the surface's s axis z x wo is +y; the facet's is wm x wo
            double sx = q.wm.y * cosThetaO, sy = q.wm.z * sinThetaO - q.wm.x * cosThetaO,
                   sz = -q.wm.y * sinThetaO;
            double len2 = sx * sx + sy * sy + sz * sz;
            double cos2 = len2 > 0 ? sy * sy / len2 : 1;  // cos^2 chi
            g *= 2 * cos2 - 1;
        }
        double lw[4];
        int first = ConductorAlbedoMoments::InterpolationWeights(mu, lw);
        for (int a = 0; a < 4; ++a) w[size_t(first + a)] += q.weight * g * lw[a];
    }
    return w;
}

}  // namespace

ConductorAlbedoMoments::Weights ConductorAlbedoMoments::Compute(double alpha, double cosThetaO) {
    return IsotropicWeights(alpha, cosThetaO, false);
}

ConductorAlbedoMoments::Weights ConductorAlbedoMoments::ComputeLinearPolarization(
    double alpha, double cosThetaO) {
    return IsotropicWeights(alpha, cosThetaO, true);
}

namespace {

// The anisotropic quadrature: calls add(mu, weight, wm) for each visible normal wm (local
// frame) that reflects wo above the horizon, weight the measure times G2 / G1.
template <typename Add>
void AnisotropicQuadrature(double alphaX, double alphaY, const double wo[3], int psiPanels,
                           int xPanels, Add&& add) {
    constexpr double kPi = 3.14159265358979323846;
    // Smith's Lambda of a direction (local frame) under the anisotropic distribution
    auto lambda = [&](double x, double y, double z) {
        if (z <= 0) return 1e30;
        double t2 = (alphaX * alphaX * x * x + alphaY * alphaY * y * y) / (z * z);
        return (std::sqrt(1 + t2) - 1) / 2;
    };
    double cosThetaO = wo[2], sinThetaO = std::sqrt(std::max(0.0, 1 - cosThetaO * cosThetaO));
    double lambdaO = lambda(wo[0], wo[1], wo[2]);
    double G1 = 1 / (1 + lambdaO);
    // The psi circle is split where the integrand changes fastest: at the azimuths
    // perpendicular to wo's (the reflection bound, at grazing incidence) and at the axes (the
    // normals of the smoother axis crowd into a narrow window of psi there)
    double phiO = sinThetaO > 0 ? std::atan2(wo[1], wo[0]) : 0;
    double psiPerp =
        std::atan2(alphaX * std::sin(phiO + kPi / 2), alphaY * std::cos(phiO + kPi / 2));
    std::vector<double> splits = {0, kPi / 2, kPi, 3 * kPi / 2};
    for (double psi : {psiPerp, psiPerp + kPi}) splits.push_back(std::fmod(psi + 4 * kPi, 2 * kPi));
    std::sort(splits.begin(), splits.end());
    splits.push_back(splits.front() + 2 * kPi);
    QuadratureRule psis;
    for (size_t a = 0; a + 1 < splits.size(); ++a) {
        double length = splits[a + 1] - splits[a];
        if (!(length > 1e-9)) continue;
        int panels = std::max(1, int(std::ceil(psiPanels * length / kPi)));
        QuadratureRule arc = SmoothstepGaussLegendre(panels, 8, splits[a], splits[a + 1]);
        psis.x.insert(psis.x.end(), arc.x.begin(), arc.x.end());
        psis.weight.insert(psis.weight.end(), arc.weight.begin(), arc.weight.end());
    }
    const QuadratureRule unitX = SmoothstepGaussLegendre(xPanels, 8, 0, 1);
    for (size_t k = 0; k < psis.x.size(); ++k) {
        double cx = alphaX * std::cos(psis.x[k]), sy = alphaY * std::sin(psis.x[k]);
        double alpha = std::sqrt(cx * cx + sy * sy);  // roughness along phi_m
        double cosPhi = cx / alpha, sinPhi = sy / alpha;
        // Reflected z = a sin(2 theta) + b cos(2 theta) > 0 for theta < (delta + pi / 2) / 2
        double a = wo[0] * cosPhi + wo[1] * sinPhi;  // sin(theta_o) cos(phi_m - phi_o)
        double delta = std::atan2(a, cosThetaO);
        double xMax = 2 / kPi * std::atan(std::tan((delta + kPi / 2) / 2) / alpha);
        for (size_t i = 0; i < unitX.x.size(); ++i) {
            // t = tan(theta_m) / alpha; the measure D(wm) dwm per dx dpsi is t s / (2 (1 + t^2))
            // with s = sqrt(1 + alpha^2 t^2), as for isotropic roughness
            double t = std::tan(kPi / 2 * xMax * unitX.x[i]);
            double at = alpha * t, s = std::sqrt(1 + at * at);
            double sinThetaM = at / s, cosThetaM = 1 / s;
            double nx = sinThetaM * cosPhi, ny = sinThetaM * sinPhi, nz = cosThetaM;
            double mu = wo[0] * nx + wo[1] * ny + wo[2] * nz;  // wo . wm
            double iz = 2 * mu * nz - wo[2];
            if (mu <= 0 || iz <= 0) continue;
            double ix = 2 * mu * nx - wo[0], iy = 2 * mu * ny - wo[1];
            double measure = t * s / (2 * (1 + t * t)) * xMax * unitX.weight[i] * psis.weight[k];
            double visible = G1 * mu / cosThetaO;
            double g = (1 + lambdaO) / (1 + lambdaO + lambda(ix, iy, iz));  // G2 / G1
            const double wm[3] = {nx, ny, nz};
            add(mu, measure * visible * g, wm);
        }
    }
}

// Adds weight to the four interpolation weights of mu in w.
void AddAt(ConductorAlbedoMoments::Weights& w, double mu, double weight) {
    double lw[4];
    int first = ConductorAlbedoMoments::InterpolationWeights(mu, lw);
    for (int c = 0; c < 4; ++c) w[size_t(first + c)] += weight * lw[c];
}

}  // namespace

ConductorAlbedoMoments::Weights ConductorAlbedoMoments::Compute(double alphaX, double alphaY,
                                                                const double wo[3], int psiPanels,
                                                                int xPanels) {
    Weights w{};
    AnisotropicQuadrature(alphaX, alphaY, wo, psiPanels, xPanels,
                          [&](double mu, double weight, const double*) { AddAt(w, mu, weight); });
    return w;
}

ConductorAlbedoMoments::PolarizationWeights ConductorAlbedoMoments::ComputeLinearPolarization(
    double alphaX, double alphaY, const double wo[3], int psiPanels, int xPanels) {
    PolarizationWeights p{};
    // The surface's s axis z x wo; a facet's wm x wo, turned by theta about wo to it
    double sx = -wo[1], sy = wo[0];
    double sLen = std::sqrt(sx * sx + sy * sy);
    if (sLen == 0) {
        sx = 1;  // normal incidence: PlaneAxis's fixed axis (x); the result is 0 here anyway
        sy = 0;
    } else {
        sx /= sLen;
        sy /= sLen;
    }
    AnisotropicQuadrature(
        alphaX, alphaY, wo, psiPanels, xPanels, [&](double mu, double weight, const double* m) {
            double fx = m[1] * wo[2] - m[2] * wo[1], fy = m[2] * wo[0] - m[0] * wo[2],
                   fz = m[0] * wo[1] - m[1] * wo[0];
            double len = std::sqrt(fx * fx + fy * fy + fz * fz);
            if (len == 0) {
                AddAt(p.cos2, mu, weight);  // wm = wo: no polarisation (dF = 0) anyway
                return;
            }
            // cos and sin of theta: f . s and (f x s) . wo, f the facet axis
            double c = (fx * sx + fy * sy) / len;
            double cx = fy * 0 - fz * sy, cy = fz * sx - fx * 0, cz = fx * sy - fy * sx;
            double sn = (cx * wo[0] + cy * wo[1] + cz * wo[2]) / len;
            // S1' = cos(2 theta) dF, S2' = -sin(2 theta) dF
            AddAt(p.cos2, mu, weight * (c * c - sn * sn));
            AddAt(p.sin2, mu, -weight * 2 * sn * c);
        });
    return p;
}

}  // namespace kiln
