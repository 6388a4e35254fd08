#include "materials/bxdfs/layered_albedo.h"

#include <algorithm>
#include <cmath>

#include "base/quadrature.h"
#include "materials/bxdfs/conductor_albedo.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/microfacet_quadrature.h"

namespace kiln {

namespace {

constexpr double kSmoothAlpha = 1e-3;  // TrowbridgeReitzDistribution::EffectivelySmooth
constexpr int kNodesPerGroup = 40;

// Direction nodes mu in [0, 1], in one group or two split at breakMu, the cosine of total
// internal reflection inside the coat, where the functions of mu have a kink. Within a group
// they are interpolated cubically in a variable s: s = (mu - a) / (b - a) below the break, and
// s = sqrt((mu - a) / (b - a)) above it, where the coat's transmittance rises like the square
// root of mu - breakMu. Chebyshev-Lobatto nodes in s.
class DirectionGrid {
  public:
    explicit DirectionGrid(double breakMu) {
        if (breakMu > 0.02 && breakMu < 0.98) {
            AddGroup(0, breakMu, false);
            AddGroup(breakMu, 1, true);
        } else {
            AddGroup(0, 1, false);
        }
        // Cosine-weighted integrals of the interpolation basis
        cosineWeights.assign(mu.size(), 0);
        for (const Group& g : groups) {
            QuadratureRule r = CompositeGaussLegendre(16, 8, 0, 1);
            for (size_t k = 0; k < r.x.size(); ++k) {
                double m = g.Mu(r.x[k]);
                Scatter(m, 2 * m * r.weight[k] * g.DMuDs(r.x[k]), cosineWeights);
            }
        }
    }
    int Size() const { return int(mu.size()); }
    double Node(int i) const { return mu[size_t(i)]; }
    // The group edges, from 0 to 1
    const std::vector<double>& Bands() const { return bands; }
    // out[j] += w basis_j(m)
    void Scatter(double m, double w, std::vector<double>& out) const {
        m = std::clamp(m, 0.0, 1.0);
        const Group* g = &groups[0];
        for (const Group& gg : groups)
            if (m >= gg.a) g = &gg;
        double at = g->S(m);
        const double* x = &s[size_t(g->first)];
        int k = 0;
        while (k + 2 < kNodesPerGroup && x[k + 1] <= at) ++k;
        int first = std::clamp(k - 1, 0, kNodesPerGroup - 4);
        double lw[4];
        CubicLagrangeWeights(x + first, at, lw);
        for (int a = 0; a < 4; ++a) out[size_t(g->first + first + a)] += w * lw[a];
    }
    // integral_0^1 2 mu basis_j(mu) dmu
    std::vector<double> cosineWeights;

  private:
    struct Group {
        int first;
        double a, b;
        bool sqrtMap;
        double Mu(double sv) const { return a + (b - a) * (sqrtMap ? sv * sv : sv); }
        double DMuDs(double sv) const { return (b - a) * (sqrtMap ? 2 * sv : 1); }
        double S(double m) const {
            double t = std::clamp((m - a) / (b - a), 0.0, 1.0);
            return sqrtMap ? std::sqrt(t) : t;
        }
    };
    void AddGroup(double a, double b, bool sqrtMap) {
        if (bands.empty()) bands.push_back(a);
        bands.push_back(b);
        Group g{int(mu.size()), a, b, sqrtMap};
        groups.push_back(g);
        const double pi = 3.14159265358979323846;
        for (int k = 0; k < kNodesPerGroup; ++k) {
            double sv = (1 - std::cos(pi * k / (kNodesPerGroup - 1))) / 2;
            s.push_back(sv);
            mu.push_back(g.Mu(sv));
        }
    }
    std::vector<Group> groups;
    std::vector<double> s, mu;  // per node: interpolation variable and cosine
    std::vector<double> bands;
};

// One interaction of the walk with a dielectric interface met from above (wo.z = muIn > 0),
// relative IOR e (below over above): the expected weight of DielectricBxDF::Sample_f
// (radiance transport) reflected into cos theta = mu', reflected(mu', w), and transmitted into
// cos theta = -mu', transmitted(mu', w).
// bands: cosines splitting the reflected directions (the direction grid's group edges), so the
// quadrature never straddles a kink of the function the weights are scattered onto.
template <typename Reflected, typename Transmitted>
void DielectricTransfer(double e, double alpha, double muIn, const std::vector<double>& bands,
                        Reflected reflected, Transmitted transmitted) {
    if (muIn <= 0) return;
    if (e == 1 || alpha < kSmoothAlpha) {
        double R = FrDielectric(Float(muIn), Float(e));
        reflected(muIn, R);
        double sin2t = (1 - muIn * muIn) / (e * e);
        if (sin2t < 1 && R < 1) transmitted(std::sqrt(1 - sin2t), (1 - R) / (e * e));
        return;
    }
    double sinIn = std::sqrt(std::max(0.0, 1 - muIn * muIn));
    double lambdaO = SmithLambda(alpha, muIn);
    // Reflection: the mirrored direction must stay above (exact regions, band by band)
    for (size_t b = 0; b + 1 < bands.size(); ++b)
        for (const NormalQuadraturePoint& q : VisibleNormalQuadrature(
                 alpha, muIn, NormalRegion::Reflected(bands[b], bands[b + 1]), 8, 2)) {
            double c = sinIn * q.wm.x + muIn * q.wm.z;
            double wiz = 2 * c * q.wm.z - muIn;
            if (wiz <= 0) continue;
            double R = FrDielectric(Float(c), Float(e));
            reflected(wiz, q.weight * R * (1 + lambdaO) / (1 + lambdaO + SmithLambda(alpha, wiz)));
        }
    // Transmission: refraction about wm must go below; normals beyond the critical angle
    // (e < 1) reflect totally
    double cosCritical = e < 1 ? std::sqrt(1 - e * e) : 0;
    for (const NormalQuadraturePoint& q :
         VisibleNormalQuadrature(alpha, muIn, NormalRegion::Visible(cosCritical), 12, 3)) {
        double c = sinIn * q.wm.x + muIn * q.wm.z;
        double T = 1 - FrDielectric(Float(c), Float(e));
        double sin2t = (1 - c * c) / (e * e);
        if (T <= 0 || sin2t >= 1) continue;
        double cost = std::sqrt(1 - sin2t);
        // wi = -wo / e + (c / e - cos_t) wm, z component
        double wiz = -muIn / e + (c / e - cost) * q.wm.z;
        if (wiz >= 0) continue;
        transmitted(-wiz, q.weight * T * (1 + lambdaO) / (1 + lambdaO + SmithLambda(alpha, -wiz)) /
                              (e * e));
    }
}

// The coat's transfers on a grid: from outside (entering) and from inside going up.
struct CoatTransfer {
    std::vector<double> reflectedOutside;            // [o]: reflection at the entrance
    std::vector<std::vector<double>> enter;          // [o][j]: into the layer, going down
    std::vector<double> exit;                        // [i]: out through the coat from node i
    std::vector<std::vector<double>> reflectInside;  // [i][j]: back down from node i

    CoatTransfer(const CoatParameters& coat, const DirectionGrid& grid,
                 const std::vector<double>& muO) {
        size_t n = size_t(grid.Size());
        reflectedOutside.assign(muO.size(), 0);
        enter.assign(muO.size(), std::vector<double>(n, 0));
        for (size_t o = 0; o < muO.size(); ++o)
            DielectricTransfer(
                coat.eta, coat.alpha, muO[o], grid.Bands(),
                [&](double, double w) { reflectedOutside[o] += w; },
                [&](double mu, double w) { grid.Scatter(mu, w, enter[o]); });
        exit.assign(n, 0);
        reflectInside.assign(n, std::vector<double>(n, 0));
        for (size_t i = 0; i < n; ++i)
            DielectricTransfer(
                1 / coat.eta, coat.alpha, grid.Node(int(i)), grid.Bands(),
                [&](double mu, double w) { grid.Scatter(mu, w, reflectInside[i]); },
                [&](double, double w) { exit[i] += w; });
    }
};

double Transmittance(double thickness, double mu) { return mu > 0 ? std::exp(-thickness / mu) : 0; }

// The total-internal-reflection cosine inside the coat (0 when there is none).
double CriticalCosine(double eta) { return eta > 1 ? std::sqrt(1 - 1 / (eta * eta)) : 0; }

}  // namespace

// coateddiffuse: the walk's value as polynomials in r (coefficient vectors)
std::vector<std::vector<double>> CoatedDiffuseAlbedoPolynomials(const CoatParameters& coat,
                                                                const std::vector<double>& muO) {
    DirectionGrid grid(CriticalCosine(coat.eta));
    CoatTransfer transfer(coat, grid, muO);
    const int n = grid.Size(), N = coat.maxDepth, degree = N / 2 + 1;
    using Poly = std::vector<double>;
    auto zero = [&] { return std::vector<Poly>(size_t(n), Poly(size_t(degree + 1), 0)); };
    // up[i], down[i]: expected exit weight at the start of depth d (d = N: nothing)
    std::vector<Poly> up = zero(), down = zero();
    for (int d = N - 1; d >= 0; --d) {
        // down at depth d: transmittance, then the diffuse base sends r x cosine upwards into
        // depth d + 1 (the up values still hold depth d + 1 here)
        Poly s(size_t(degree + 1), 0);
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < degree; ++k)
                s[size_t(k + 1)] += grid.cosineWeights[size_t(j)] * up[size_t(j)][size_t(k)];
        std::vector<Poly> newDown = zero(), newUp = zero();
        for (int i = 0; i < n; ++i) {
            double tr = Transmittance(coat.thickness, grid.Node(i));
            for (int k = 0; k <= degree; ++k) newDown[size_t(i)][size_t(k)] = tr * s[size_t(k)];
            // up at depth d: transmittance, exit, or reflection into down at depth d + 1
            newUp[size_t(i)][0] = tr * transfer.exit[size_t(i)];
            for (int j = 0; j < n; ++j) {
                double kr = transfer.reflectInside[size_t(i)][size_t(j)];
                if (kr == 0) continue;
                for (int k = 0; k <= degree; ++k)
                    newUp[size_t(i)][size_t(k)] += tr * kr * down[size_t(j)][size_t(k)];
            }
        }
        up = std::move(newUp);
        down = std::move(newDown);
    }
    std::vector<std::vector<double>> result(muO.size(), std::vector<double>(size_t(degree + 1), 0));
    for (size_t o = 0; o < muO.size(); ++o) {
        result[o][0] = transfer.reflectedOutside[o];
        for (int j = 0; j < n; ++j)
            for (int k = 0; k <= degree; ++k)
                result[o][size_t(k)] += transfer.enter[o][size_t(j)] * down[size_t(j)][size_t(k)];
    }
    return result;
}

// coatedconductor
std::vector<std::vector<double>> CoatedConductorAlbedo(
    const CoatParameters& coat, double conductorAlpha,
    const std::vector<std::function<double(double)>>& fresnels, const std::vector<double>& muO) {
    DirectionGrid grid(CriticalCosine(coat.eta));
    CoatTransfer transfer(coat, grid, muO);
    const int n = grid.Size(), N = coat.maxDepth;
    const int H = ConductorAlbedoMoments::kNodes;

    // Base reflection from node i, as weights on the Fresnel moment nodes h and the grid
    // nodes j: base[i][h * n + j] (rough), or the node's own cosine (smooth)
    bool smoothBase = conductorAlpha < kSmoothAlpha;
    std::vector<std::vector<double>> base;
    if (!smoothBase) {
        base.assign(size_t(n), std::vector<double>(size_t(H * n), 0));
        std::vector<double> scatter(static_cast<size_t>(n), 0.0);
        for (int i = 1; i < n; ++i) {
            double mu = grid.Node(i), sinO = std::sqrt(std::max(0.0, 1 - mu * mu));
            double lambdaO = SmithLambda(conductorAlpha, mu);
            for (size_t b = 0; b + 1 < grid.Bands().size(); ++b)
                for (const NormalQuadraturePoint& q : VisibleNormalQuadrature(
                         conductorAlpha, mu,
                         NormalRegion::Reflected(grid.Bands()[b], grid.Bands()[b + 1]), 8, 2)) {
                    double c = std::clamp(sinO * q.wm.x + mu * q.wm.z, 0.0, 1.0);
                    double wiz = 2 * c * q.wm.z - mu;
                    if (wiz <= 0) continue;
                    double v =
                        q.weight * (1 + lambdaO) / (1 + lambdaO + SmithLambda(conductorAlpha, wiz));
                    // Cubic interpolation of F in c through the moment nodes
                    double lw[4];
                    int first = ConductorAlbedoMoments::InterpolationWeights(c, lw);
                    std::fill(scatter.begin(), scatter.end(), 0.0);
                    grid.Scatter(wiz, v, scatter);
                    for (int a = 0; a < 4; ++a)
                        for (int j = 0; j < n; ++j)
                            if (scatter[size_t(j)] != 0)
                                base[size_t(i)][size_t((first + a) * n + j)] +=
                                    lw[a] * scatter[size_t(j)];
                }
        }
    }

    std::vector<std::vector<double>> result(fresnels.size(), std::vector<double>(muO.size(), 0));
    std::vector<double> kb(size_t(n) * size_t(n));
    for (size_t l = 0; l < fresnels.size(); ++l) {
        const std::function<double(double)>& F = fresnels[l];
        if (!smoothBase) {
            double Fh[ConductorAlbedoMoments::kNodes];
            for (int h = 0; h < H; ++h) Fh[h] = F(ConductorAlbedoMoments::Node(h));
            std::fill(kb.begin(), kb.end(), 0.0);
            for (int i = 0; i < n; ++i)
                for (int h = 0; h < H; ++h)
                    for (int j = 0; j < n; ++j)
                        kb[size_t(i * n + j)] += Fh[h] * base[size_t(i)][size_t(h * n + j)];
        }
        std::vector<double> up(size_t(n), 0), down(size_t(n), 0),
            newUp(static_cast<size_t>(n), 0.0), newDown(static_cast<size_t>(n), 0.0);
        for (int d = N - 1; d >= 0; --d) {
            for (int i = 0; i < n; ++i) {
                double tr = Transmittance(coat.thickness, grid.Node(i));
                double dn = 0;
                if (smoothBase)
                    dn = F(grid.Node(i)) * up[size_t(i)];
                else
                    for (int j = 0; j < n; ++j) dn += kb[size_t(i * n + j)] * up[size_t(j)];
                newDown[size_t(i)] = tr * dn;
                double u = transfer.exit[size_t(i)];
                for (int j = 0; j < n; ++j)
                    u += transfer.reflectInside[size_t(i)][size_t(j)] * down[size_t(j)];
                newUp[size_t(i)] = tr * u;
            }
            std::swap(up, newUp);
            std::swap(down, newDown);
        }
        for (size_t o = 0; o < muO.size(); ++o) {
            double a = transfer.reflectedOutside[o];
            for (int j = 0; j < n; ++j) a += transfer.enter[o][size_t(j)] * down[size_t(j)];
            result[l][o] = a;
        }
    }
    return result;
}

}  // namespace kiln
