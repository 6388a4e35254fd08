#include "thermal/conductor_emissivity.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "base/low_rank.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/materials.h"
#include "textures/basic_textures.h"
#include "textures/metal_temperature_texture.h"

namespace kiln {

namespace {

constexpr int H = ConductorAlbedoMoments::kNodes;
constexpr size_t kTemperatureStride = 4;

bool IsConstant(const std::optional<SpectrumTexture>& t) {
    if (!t) return true;
    // A named metal's constants at a temperature the material fixes
    if (const auto* m = t->GetIf<SpectrumMetalTemperatureTexture>()) return !m->FollowsSurface();
    return t->Is<SpectrumConstantTexture>();
}

// The named metal's table, when eta and k both follow the surface's temperature
const MetalTemperatureTable* FollowsTemperature(const std::optional<SpectrumTexture>& eta,
                                                const std::optional<SpectrumTexture>& k) {
    if (!eta || !k) return nullptr;
    const auto* e = eta->GetIf<SpectrumMetalTemperatureTexture>();
    const auto* kk = k->GetIf<SpectrumMetalTemperatureTexture>();
    if (!e || !kk || !e->FollowsSurface() || !kk->FollowsSurface()) return nullptr;
    return &e->Table();
}

// Isotropic alpha standing in for an anisotropic distribution (textured anisotropic roughness
// only): the root mean square of the two, which came closest to the anisotropic albedo among
// the simple choices tried (projected on wo's azimuth, geometric mean, blends of the two).
Float EquivalentAlpha(const TrowbridgeReitzDistribution& d) {
    if (d.AlphaX() == d.AlphaY()) return d.AlphaX();
    return std::sqrt((Sqr(d.AlphaX()) + Sqr(d.AlphaY())) / 2);
}

// Reflectance nodes for textured "reflectance" (F as a function of r, eta = 1): denser
// towards r = 1, where k = 2 sqrt(r) / sqrt(1 - r) grows without bound.
TableAxis ReflectanceNodes() {
    std::vector<float> r;
    constexpr int n = 513;
    for (int i = 0; i < n; ++i) {
        double x = double(i) / (n - 1);
        r.push_back(float(std::min(0.9999, 1 - (1 - x) * (1 - x))));
    }
    r.erase(std::unique(r.begin(), r.end()), r.end());
    return TableAxis(std::move(r));
}

// Cubic Lagrange weights in x over four nodes of an evenly spaced axis (clamped to its ends);
// returns the first of the four nodes.
int CubicWeights(const TableAxis& axis, float x, float w[4]) {
    auto [i, ti] = axis.Locate(x);
    int first = std::clamp(i - 1, 0, axis.Size() - 4);
    double t = i + ti - first;  // position among the nodes first .. first + 3
    w[0] = float(-(t - 1) * (t - 2) * (t - 3) / 6);
    w[1] = float(t * (t - 2) * (t - 3) / 2);
    w[2] = float(-t * (t - 1) * (t - 3) / 2);
    w[3] = float(t * (t - 1) * (t - 2) / 6);
    return first;
}

// The albedo from the factorised tables: G_r = sum over cells of weight * projected row, then
// per wavelength sum_r G_r V_r(x), V interpolated at x. S (the row stride, a multiple of four)
// is a compile-time constant and the sums run in four lanes, so the loops vectorise.
struct FactorisedLookup {
    const float* projected;
    const int* cell;
    const float* weight;
    int cells;
    const float* basis;
    const TableAxis& nodes;
    const Float* x;

    template <int S>
    SampledSpectrum Apply() const {
        static_assert(S % 4 == 0 && S <= ConductorEmissivity::kMaxRank);
        float g[S] = {};
        for (int k = 0; k < cells; ++k) {
            const float* row = projected + size_t(cell[k]) * S;
            for (int r = 0; r < S; ++r) g[r] += weight[k] * row[r];
        }
        SampledSpectrum A;
        for (int i = 0; i < NSpectrumSamples; ++i) {
            auto [xi, xt] = nodes.Locate(x[i]);
            const float* v0 = basis + size_t(xi) * S;
            const float* v1 = basis + size_t(nodes.Next(xi)) * S;
            float s0[4] = {}, s1[4] = {};
            for (int r = 0; r < S; r += 4)
                for (int q = 0; q < 4; ++q) {
                    s0[q] += g[r + q] * v0[r + q];
                    s1[q] += g[r + q] * v1[r + q];
                }
            A[i] = (1 - xt) * ((s0[0] + s0[1]) + (s0[2] + s0[3])) +
                   xt * ((s1[0] + s1[1]) + (s1[2] + s1[3]));
        }
        return A;
    }
};

}  // namespace

// Azimuths
double ConductorEmissivity::Azimuths::Phi(int i) const {
    double u = Pi / 2 * i / (n - 1);
    double phi = std::atan2(std::sin(u), k * std::cos(u));  // tan(phi) = tan(u) / k
    return smoothAxisY ? Pi / 2 - phi : phi;
}

int ConductorEmissivity::Azimuths::Weights(Vector3f wo, int node[4], float weight[4]) const {
    if (n == 1) {
        node[0] = 0;
        weight[0] = 1;
        return 1;
    }
    double c = std::abs(CosPhi(wo)), s = std::abs(SinPhi(wo));
    if (smoothAxisY) std::swap(c, s);
    double x = std::atan2(k * s, c) / (Pi / 2) * (n - 1);
    int i = std::clamp(int(x), 0, n - 2);
    double t = x - i;
    // Cubic Lagrange weights of nodes i - 1 .. i + 2; the albedo is even about both ends, so
    // nodes beyond them mirror inside
    weight[0] = float(-t * (t - 1) * (t - 2) / 6);
    weight[1] = float((t + 1) * (t - 1) * (t - 2) / 2);
    weight[2] = float(-(t + 1) * t * (t - 2) / 2);
    weight[3] = float((t + 1) * t * (t - 1) / 6);
    for (int a = 0; a < 4; ++a) {
        int j = i - 1 + a;
        node[a] = j < 0 ? -j : j > n - 1 ? 2 * (n - 1) - j : j;
    }
    return 4;
}

// ConductorEmissivity
ConductorEmissivity::ConductorEmissivity(const ConductorMaterial& m, EmissivityTables& t)
    : tables(&t) {
    std::optional<Float> u = m.URoughness().ConstantValue(), v = m.VRoughness().ConstantValue();
    auto remap = [&](Float r) {
        return std::max(0.f,
                        m.RemapRoughness() ? TrowbridgeReitzDistribution::RoughnessToAlpha(r) : r);
    };
    if (u && v) {
        uniformAlpha = true;
        alphaX = remap(*u);
        alphaY = remap(*v);
        if (std::max(alphaX, alphaY) < 1e-3f) return;  // smooth: Fresnel's equations
    } else {
        // Textured roughness: exact when both directions share one texture
        exact = m.URoughness() == m.VRoughness();
    }

    // Moment weights
    const TableAxis& cosines = t.Cosines();
    if (uniformAlpha) {
        if (alphaX != alphaY) {
            azimuths.n = 17;
            azimuths.smoothAxisY = alphaY < alphaX;
            azimuths.k = std::pow(
                double(std::max(alphaX, alphaY)) / std::max(1e-4, double(std::min(alphaX, alphaY))),
                0.25);
        }
        const int na = azimuths.n;
        weights.resize(size_t(cosines.Size()) * na * H);
        tbb::parallel_for(0, cosines.Size() * na, [&](int cell) {
            double mu = std::max(1e-4, double(cosines.Node(cell / na)));
            ConductorAlbedoMoments::Weights w;
            if (na == 1) {
                w = ConductorAlbedoMoments::Compute(alphaX, mu);
            } else {
                double phi = azimuths.Phi(cell % na), sinTheta = std::sqrt(1 - mu * mu);
                double wo[3] = {sinTheta * std::cos(phi), sinTheta * std::sin(phi), mu};
                w = ConductorAlbedoMoments::Compute(std::max(1e-4f, alphaX),
                                                    std::max(1e-4f, alphaY), wo);
            }
            for (int j = 0; j < H; ++j) weights[size_t(cell) * H + j] = float(w[size_t(j)]);
        });
        // Polarised rendering: the S1 and S2 weights on the same cells
        if (t.polarized) {
            polarizationWeights.resize(size_t(cosines.Size()) * na * 2 * H);
            tbb::parallel_for(0, cosines.Size() * na, [&](int cell) {
                double mu = std::max(1e-4, double(cosines.Node(cell / na)));
                ConductorAlbedoMoments::PolarizationWeights p{};
                if (na == 1) {
                    p.cos2 = ConductorAlbedoMoments::ComputeLinearPolarization(alphaX, mu);
                } else {
                    // S2 is odd about both axes and steep beside them at grazing angles: the
                    // table holds S2 / sin(2 phi), which interpolates well (at the axes, from
                    // azimuths 1e-3 inside them)
                    double phi = azimuths.Phi(cell % na), sinTheta = std::sqrt(1 - mu * mu);
                    double ax = std::max(1e-4f, alphaX), ay = std::max(1e-4f, alphaY);
                    double wo[3] = {sinTheta * std::cos(phi), sinTheta * std::sin(phi), mu};
                    p = ConductorAlbedoMoments::ComputeLinearPolarization(ax, ay, wo);
                    double phi2 = std::clamp(phi, 1e-3, Pi / 2 - 1e-3);
                    if (phi2 != phi) {
                        double wo2[3] = {sinTheta * std::cos(phi2), sinTheta * std::sin(phi2), mu};
                        p.sin2 =
                            ConductorAlbedoMoments::ComputeLinearPolarization(ax, ay, wo2).sin2;
                    }
                    for (double& w : p.sin2) w /= std::sin(2 * phi2);
                }
                float* out = &polarizationWeights[size_t(cell) * 2 * H];
                for (int j = 0; j < H; ++j) {
                    out[j] = float(p.cos2[size_t(j)]);
                    out[H + j] = float(p.sin2[size_t(j)]);
                }
            });
        }
    } else {
        moments = &t.ConductorMoments();
        if (t.polarized) polarizationMoments = &t.ConductorPolarizationMoments();
    }

    // Fresnel factors F(mu_j, x) over x, factorised
    bool etaK = m.Eta() && m.K();
    const MetalTemperatureTable* hot = FollowsTemperature(m.Eta(), m.K());
    if (etaK ? IsConstant(m.Eta()) && IsConstant(m.K()) : IsConstant(m.Reflectance()))
        fresnelAxis = FresnelAxis::Wavelength;
    else if (hot)
        fresnelAxis = FresnelAxis::WavelengthTemperature;
    else if (!etaK)
        fresnelAxis = FresnelAxis::Reflectance;
    else
        return;  // textured eta and k: F per sample
    fresnelNodes =
        fresnelAxis == FresnelAxis::Reflectance ? ReflectanceNodes() : t.FineWavelengths();
    if (hot) {
        // Every fourth of the metal's 25 K nodes (100 K; the last one too): the Fresnel factors
        // change slowly with temperature
        const std::vector<float>& all = hot->Temperatures().Nodes();
        std::vector<float> nodes;
        for (size_t i = 0; i < all.size(); i += kTemperatureStride) nodes.push_back(all[i]);
        if (nodes.back() != all.back()) nodes.push_back(all.back());
        fresnelTemperatures = TableAxis(std::move(nodes));
    }
    const int nx = fresnelNodes.Size(), nT = hot ? fresnelTemperatures.Size() : 1;
    const int columns = nx * nT;  // [T][x]
    std::vector<double> f(size_t(H) * columns);
    tbb::parallel_for(0, columns, [&](int column) {
        const int x = column % nx;
        std::complex<Float> eta;
        if (fresnelAxis == FresnelAxis::Reflectance) {
            Float r = fresnelNodes.Node(x);
            eta = {1, 2 * std::sqrt(r) / std::sqrt(1 - r)};
        } else {
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(fresnelNodes.Node(x));
            MaterialEvalContext ctx;
            if (hot) ctx.temperature = fresnelTemperatures.Node(column / nx);
            ConductorBxDF b = m.GetBxDF(ctx, lambda);
            eta = {b.Eta()[0], b.K()[0]};
        }
        for (int j = 0; j < H; ++j)
            f[size_t(j) * columns + column] =
                FrComplex(Float(ConductorAlbedoMoments::Node(j)), eta);
    });
    LowRankFactors factors = FactorLowRank(f, H, columns, 1e-5);
    const int rank = factors.rank;
    stride = (rank + 3) / 4 * 4;  // rows padded with zeros to whole groups of four
    basis.assign(size_t(columns) * stride, 0.f);
    for (int x = 0; x < columns; ++x)
        for (int r = 0; r < rank; ++r)
            basis[size_t(x) * stride + r] = float(factors.v[size_t(x) * rank + r]);
    const std::vector<float>& w = moments ? *moments : weights;
    const size_t cells = w.size() / H;
    projected.assign(cells * stride, 0.f);
    for (size_t c = 0; c < cells; ++c)
        for (int r = 0; r < rank; ++r) {
            double g = 0;
            for (int j = 0; j < H; ++j) g += double(w[c * H + j]) * factors.u[size_t(j) * rank + r];
            projected[c * stride + r] = float(g);
        }
    if (!moments) {
        // Only the projections are needed (but for Fresnel factors per sample, without a
        // temperature)
        if (fresnelAxis != FresnelAxis::WavelengthTemperature) weights.clear();
        return;
    }
    // Textured roughness: the projections resampled (cubic in log alpha, as Cells interpolates
    // the shared table) to an alpha axis four times finer, so that a lookup interpolates
    // linearly between two alpha nodes instead of four
    const TableAxis& alphas = t.LogAlphas();
    const int nA = alphas.Size(), nF = 4 * (nA - 1) + 1, nC = cosines.Size();
    std::vector<float> nodes(static_cast<size_t>(nF));
    for (int k = 0; k < nF; ++k)
        nodes[size_t(k)] =
            alphas.Node(0) + (alphas.Node(nA - 1) - alphas.Node(0)) * float(k) / float(nF - 1);
    std::vector<float> fine(size_t(nC) * nF * stride, 0.f);
    for (int c = 0; c < nC; ++c)
        for (int k = 0; k < nF; ++k) {
            float aw[4];
            int first = CubicWeights(alphas, nodes[size_t(k)], aw);
            float* out = &fine[(size_t(c) * nF + k) * stride];
            for (int a = 0; a < 4; ++a)
                for (int r = 0; r < stride; ++r)
                    out[r] += aw[a] * projected[(size_t(c) * nA + first + a) * stride + r];
        }
    projected = std::move(fine);
    fineLogAlphas = TableAxis(std::move(nodes));
}

int ConductorEmissivity::Cells(const TrowbridgeReitzDistribution& d, Vector3f wo, int cell[8],
                               float weight[8], bool projections) const {
    auto [ci, ct] = tables->Cosines().Locate(std::min<Float>(1, AbsCosTheta(wo)));
    int n = 0;
    if (uniformAlpha) {
        int node[4];
        float nodeWeight[4];
        int na = azimuths.Weights(wo, node, nodeWeight);
        for (int c = 0; c < 2; ++c)
            for (int a = 0; a < na; ++a) {
                cell[n] = (ci + c) * azimuths.n + node[a];
                weight[n++] = (c ? ct : 1 - ct) * nodeWeight[a];
            }
    } else if (projections && fineLogAlphas.Size() > 0) {
        // The resampled projections: linear in log alpha
        const int na = fineLogAlphas.Size();
        auto [ai, at] = fineLogAlphas.Locate(std::log(std::max(EquivalentAlpha(d), 1e-4f)));
        for (int c = 0; c < 2; ++c)
            for (int a = 0; a < 2; ++a) {
                cell[n] = (ci + c) * na + ai + a;
                weight[n++] = (c ? ct : 1 - ct) * (a ? at : 1 - at);
            }
    } else {
        // The shared table: cubic in log alpha
        const TableAxis& alphas = tables->LogAlphas();
        float aw[4];
        int first = CubicWeights(alphas, std::log(std::max(EquivalentAlpha(d), 1e-4f)), aw);
        for (int c = 0; c < 2; ++c)
            for (int a = 0; a < 4; ++a) {
                cell[n] = (ci + c) * alphas.Size() + first + a;
                weight[n++] = (c ? ct : 1 - ct) * aw[a];
            }
    }
    return n;
}

SampledSpectrum ConductorEmissivity::Albedo(const ConductorBxDF& bxdf, Vector3f wo,
                                            const SampledWavelengths& lambda,
                                            Float temperature) const {
    const TrowbridgeReitzDistribution& distrib = bxdf.Distribution();
    if (distrib.EffectivelySmooth())
        return FrComplex(std::min<Float>(1, AbsCosTheta(wo)), bxdf.Eta(), bxdf.K());
    int cell[8];
    float cellWeight[8];
    SampledSpectrum A;
    const bool perSample = fresnelAxis == FresnelAxis::PerSample ||
                           (fresnelAxis == FresnelAxis::WavelengthTemperature && temperature < 0);
    if (!perSample) {
        const int cells = Cells(distrib, wo, cell, cellWeight, true);
        Float x[NSpectrumSamples];
        for (int i = 0; i < NSpectrumSamples; ++i) {
            x[i] = lambda[i];
            if (fresnelAxis == FresnelAxis::Reflectance) {
                Float k2 = Sqr(bxdf.K()[i]);  // k = 2 sqrt(r / (1 - r))
                x[i] = k2 / (4 + k2);
            }
        }
        auto lookup = [&](const float* slice) {
            FactorisedLookup l{projected.data(), cell, cellWeight, cells, slice, fresnelNodes, x};
            switch (stride) {
                case 4:
                    return l.Apply<4>();
                case 8:
                    return l.Apply<8>();
                case 12:
                    return l.Apply<12>();
                case 16:
                    return l.Apply<16>();
                case 20:
                    return l.Apply<20>();
                case 24:
                    return l.Apply<24>();
                case 28:
                    return l.Apply<28>();
                default:
                    return l.Apply<32>();
            }
        };
        if (fresnelAxis != FresnelAxis::WavelengthTemperature) return lookup(basis.data());
        // Linear between the two temperature nodes around the surface's
        auto [j, tT] = fresnelTemperatures.Locate(temperature);
        const size_t slice = size_t(fresnelNodes.Size()) * stride;
        SampledSpectrum a0 = lookup(basis.data() + size_t(j) * slice);
        if (tT == 0) return a0;
        SampledSpectrum a1 = lookup(basis.data() + size_t(fresnelTemperatures.Next(j)) * slice);
        return (1 - tT) * a0 + tT * a1;
    }
    // Textured eta and k: W_j at wo, F(mu_j) per wavelength (the cells of the moment weights,
    // where the projections have an axis of their own)
    const int cells = Cells(distrib, wo, cell, cellWeight, false);
    const std::vector<float>& table = moments ? *moments : weights;
    float w[H] = {};
    for (int k = 0; k < cells; ++k)
        for (int j = 0; j < H; ++j) w[j] += cellWeight[k] * table[size_t(cell[k]) * H + j];
    for (int i = 0; i < NSpectrumSamples; ++i) {
        std::complex<Float> eta(bxdf.Eta()[i], bxdf.K()[i]);
        double a = 0;
        for (int j = 0; j < H; ++j)
            a += w[j] * FrComplex(Float(ConductorAlbedoMoments::Node(j)), eta);
        A[i] = Float(a);
    }
    return A;
}

ReflectedPolarization ConductorEmissivity::LinearPolarization(const ConductorBxDF& bxdf,
                                                              Vector3f wo) const {
    ReflectedPolarization r;
    Float cosTheta = std::min<Float>(1, AbsCosTheta(wo));
    auto dF = [&](Float mu, int i) {
        FresnelRsRp R = FrComplexPolarized(mu, std::complex<Float>(bxdf.Eta()[i], bxdf.K()[i]));
        return (R.Rs - R.Rp) / 2;
    };
    const TrowbridgeReitzDistribution& d = bxdf.Distribution();
    if (d.EffectivelySmooth()) {
        for (int i = 0; i < NSpectrumSamples; ++i) r.s1[i] = dF(cosTheta, i);
        return r;
    }
    // The weights at wo, interpolated over the table cells
    float w1[H] = {}, w2[H] = {};
    if (!polarizationWeights.empty()) {
        int cell[8];
        float cellWeight[8];
        const int cells = Cells(d, wo, cell, cellWeight, false);
        for (int k = 0; k < cells; ++k) {
            const float* row = &polarizationWeights[size_t(cell[k]) * 2 * H];
            for (int j = 0; j < H; ++j) {
                w1[j] += cellWeight[k] * row[j];
                w2[j] += cellWeight[k] * row[H + j];
            }
        }
        // The table holds S2 / sin(2 phi) at azimuths folded into [0, pi/2]; S2 changes sign
        // under the mirror images that fold the others onto them, so S2 = sin(2 phi) times it
        float sin2Phi = 2 * CosPhi(wo) * SinPhi(wo);
        for (float& w : w2) w *= sin2Phi;
    } else if (polarizationMoments) {
        // Textured roughness: the shared isotropic table, linear in the cosine, cubic in
        // log alpha (at the root-mean-square alpha)
        const TableAxis& alphas = tables->LogAlphas();
        auto [ci, ct] = tables->Cosines().Locate(cosTheta);
        float aw[4];
        int first = CubicWeights(alphas, std::log(std::max(EquivalentAlpha(d), 1e-4f)), aw);
        for (int c = 0; c < 2; ++c)
            for (int a = 0; a < 4; ++a) {
                float cw = (c ? ct : 1 - ct) * aw[a];
                const float* row =
                    &(*polarizationMoments)[(size_t(ci + c) * alphas.Size() + first + a) * H];
                for (int j = 0; j < H; ++j) w1[j] += cw * row[j];
            }
    } else {
        return r;
    }
    for (int j = 0; j < H; ++j) {
        if (w1[j] == 0 && w2[j] == 0) continue;
        Float mu = Float(ConductorAlbedoMoments::Node(j));
        for (int i = 0; i < NSpectrumSamples; ++i) {
            Float f = dF(mu, i);
            r.s1[i] += w1[j] * f;
            r.s2[i] += w2[j] * f;
        }
    }
    return r;
}

}  // namespace kiln
