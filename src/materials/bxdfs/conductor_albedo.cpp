#include "materials/bxdfs/conductor_albedo.h"

#include <algorithm>
#include <cmath>

#include "core/base/quadrature.h"
#include "materials/bxdfs/microfacet_quadrature.h"

namespace kiln {

double ConductorAlbedoMoments::Node(int j) {
    double x = double(j) / (kNodes - 1);
    return x * x * (2 - x) * 0.5 + x * 0.5;  // spacing at 0 half that at 1
}

int ConductorAlbedoMoments::InterpolationWeights(double mu, double w[4]) {
    mu = std::clamp(mu, 0.0, 1.0);
    int lo = 0, hi = kNodes - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        (Node(mid) <= mu ? lo : hi) = mid;
    }
    int first = std::clamp(lo - 1, 0, kNodes - 4);
    double x[4] = {Node(first), Node(first + 1), Node(first + 2), Node(first + 3)};
    CubicLagrangeWeights(x, mu, w);
    return first;
}

ConductorAlbedoMoments::Weights ConductorAlbedoMoments::Compute(double alpha, double cosThetaO) {
    Weights w{};
    double sinThetaO = std::sqrt(std::max(0.0, 1 - cosThetaO * cosThetaO));
    double lambdaO = SmithLambda(alpha, cosThetaO);
    for (const NormalQuadraturePoint& q :
         VisibleNormalQuadrature(alpha, cosThetaO, NormalRegion::Reflected(), 8, 2)) {
        double mu = sinThetaO * q.wm.x + cosThetaO * q.wm.z;  // wo . wm
        double wiz = 2 * mu * q.wm.z - cosThetaO;             // z of reflect(wo, wm)
        if (wiz <= 0) continue;
        double g = (1 + lambdaO) / (1 + lambdaO + SmithLambda(alpha, wiz));  // G2 / G1
        double lw[4];
        int first = InterpolationWeights(mu, lw);
        for (int a = 0; a < 4; ++a) w[size_t(first + a)] += q.weight * g * lw[a];
    }
    return w;
}

}  // namespace kiln
