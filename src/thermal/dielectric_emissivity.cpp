#include "thermal/dielectric_emissivity.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "materials/bxdfs/fresnel.h"
#include "materials/materials.h"

namespace kiln {

namespace {

constexpr int kAlphaNodes = 24;
constexpr int kMaxPoints = 64, kMinPoints = 8;
constexpr double kSampleBudget = 6.5e6;

// A direction at cosine mu from the normal, on the side `side` (0 outside, 1 inside)
Vector3f Direction(float mu, int side) {
    Float cosTheta = std::clamp(mu, 1e-4f, 1.f);
    Float sinTheta = std::sqrt(std::max<Float>(0, 1 - cosTheta * cosTheta));
    return Vector3f(sinTheta, 0, side == 0 ? cosTheta : -cosTheta);
}

}  // namespace

// Sample_wm places a microfacet normal at radius sqrt(u.x) of a disk projected onto a
// hemisphere: its height sqrt(1 - u.x) has an infinite slope at u.x = 1, where the steep facets
// that lose most light lie. With u.x = 1 - s^2 the height is about s, smooth, and midpoints in
// s (weight 2 s) converge much faster than midpoints in u.x.
Float DielectricEmissivity::Quadrature(const DielectricBxDF& bxdf, Vector3f wo, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        double s = (i + 0.5) / n, rowSum = 0;
        for (int j = 0; j < n; ++j) {
            Point2f u(Float(1 - s * s), (j + 0.5f) / n);
            for (BxDFReflTransFlags lobe :
                 {BxDFReflTransFlags::Reflection, BxDFReflTransFlags::Transmission}) {
                std::optional<BSDFSample> bs =
                    bxdf.Sample_f(wo, 0.5f, u, TransportMode::Importance, lobe);
                if (bs && bs->pdf > 0) rowSum += double(bs->f[0]) * AbsCosTheta(bs->wi) / bs->pdf;
            }
        }
        sum += 2 * s * rowSum;
    }
    return Float(sum / (double(n) * n));
}

// Creation
DielectricEmissivity::DielectricEmissivity(const DielectricMaterial& m, const EmissivityTables& t)
    : tables(&t) {
    // Roughness: the material's alpha, or an axis of them
    std::optional<Float> u = m.URoughness().ConstantValue(), v = m.VRoughness().ConstantValue();
    auto remap = [&](Float r) {
        return std::max(0.f,
                        m.RemapRoughness() ? TrowbridgeReitzDistribution::RoughnessToAlpha(r) : r);
    };
    std::vector<float> alphaNodes;
    if (u && v) {
        exact = remap(*u) == remap(*v);
        alphaNodes.push_back(std::log(std::max(1e-4f, std::sqrt(remap(*u) * remap(*v)))));
    } else {
        exact = false;
        const double logMin = std::log(1e-3), logMax = std::log(4.0);
        for (int i = 0; i < kAlphaNodes; ++i)
            alphaNodes.push_back(float(logMin + (logMax - logMin) * i / (kAlphaNodes - 1)));
    }
    logAlphas = TableAxis(std::move(alphaNodes));

    // The second axis: eta where k is constant, else the wavelength
    const SpectralRange& range = t.Range();
    const std::optional<Spectrum>& k = m.K();
    byWavelength = k && !k->Is<ConstantSpectrum>();
    Float constantK = k ? std::max<Float>(0, (*k)(range.min)) : 0;
    auto etaAt = [&](Float lambda) {
        Float e = m.Eta()(lambda);
        return e == 0 ? Float(1) : e;  // as the material's SampleEta
    };
    std::vector<float> spectralNodes;
    if (byWavelength) {
        spectralNodes = t.Wavelengths().Nodes();
    } else if (m.Eta().Is<ConstantSpectrum>()) {
        spectralNodes.push_back(etaAt(range.min));
    } else {
        Float lo = etaAt(range.max), hi = lo;
        for (double l = range.min; l < range.max; l *= 1.005) {
            lo = std::min(lo, etaAt(Float(l)));
            hi = std::max(hi, etaAt(Float(l)));
        }
        int n = std::clamp(int(std::ceil((hi - lo) / 0.02f)) + 1, 2, 8);
        if (hi == lo) n = 1;
        for (int i = 0; i < n; ++i)
            spectralNodes.push_back(lo + (hi - lo) * i / std::max(1, n - 1));
    }
    spectral = TableAxis(std::move(spectralNodes));

    // The table, by quadrature on every node
    const int nCos = t.Cosines().Size(), nAlpha = logAlphas.Size(), nSpectral = spectral.Size();
    const size_t nodes = size_t(nSpectral) * nAlpha * 2 * nCos;
    int points = int(std::sqrt(kSampleBudget / (2.0 * double(nodes))));
    points = std::clamp(points, kMinPoints, kMaxPoints);
    if (points < kMaxPoints) exact = false;
    table.resize(nodes);
    tbb::parallel_for(size_t(0), size_t(nSpectral) * nAlpha, [&](size_t sa) {
        int s = int(sa / size_t(nAlpha)), a = int(sa % size_t(nAlpha));
        Float eta = byWavelength ? etaAt(spectral.Node(s)) : spectral.Node(s);
        Float kk = byWavelength ? std::max<Float>(0, (*k)(spectral.Node(s))) : constantK;
        Float alpha = std::exp(logAlphas.Node(a));
        DielectricBxDF bxdf(eta, TrowbridgeReitzDistribution(alpha, alpha), kk);
        for (int side = 0; side < 2; ++side)
            for (int c = 0; c < nCos; ++c)
                table[(sa * 2 + size_t(side)) * size_t(nCos) + size_t(c)] =
                    Quadrature(bxdf, Direction(t.Cosines().Node(c), side), points);
    });
}

// Evaluation
SampledSpectrum DielectricEmissivity::Albedo(const DielectricBxDF& bxdf, Vector3f wo,
                                             const SampledWavelengths& lambda) const {
    const TrowbridgeReitzDistribution& d = bxdf.Distribution();
    if (d.EffectivelySmooth() || bxdf.Eta() == 1) {
        // Fresnel's split loses nothing, but for an absorbing body seen from outside beyond
        // the cone that refracts into it
        Float eta = bxdf.Eta();
        if (bxdf.K() > 0 && CosTheta(wo) > 0 && eta < 1 && Sin2Theta(wo) >= Sqr(eta))
            return SampledSpectrum(FrAbsorbingDielectric(CosTheta(wo), eta, bxdf.K()));
        return SampledSpectrum(1.f);
    }
    // Linear in each axis: 2 x 2 x 2 nodes
    auto [s0, ts] = spectral.Locate(byWavelength ? lambda[0] : bxdf.Eta());
    Float alpha = std::sqrt(d.AlphaX() * d.AlphaY());
    auto [a0, ta] = logAlphas.Locate(std::log(std::max(alpha, 1e-4f)));
    auto [c0, tc] = tables->Cosines().Locate(std::abs(CosTheta(wo)));
    const int nCos = tables->Cosines().Size(), nAlpha = logAlphas.Size();
    const int side = CosTheta(wo) < 0 ? 1 : 0;
    const int nS = spectral.Size() > 1 ? 2 : 1, nA = nAlpha > 1 ? 2 : 1;
    double E = 0;
    for (int i = 0; i < nS; ++i)
        for (int j = 0; j < nA; ++j) {
            Float w = (i ? ts : 1 - ts) * (j ? ta : 1 - ta);
            const float* row =
                &table[((size_t(s0 + i) * nAlpha + size_t(a0 + j)) * 2 + size_t(side)) * nCos];
            E += w * ((1 - tc) * row[c0] + tc * row[c0 + 1]);
        }
    return SampledSpectrum(Float(E));
}

}  // namespace kiln
