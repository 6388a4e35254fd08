#include "materials/conductor_emissivity.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "materials/bxdfs/conductor_albedo.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/materials.h"
#include "textures/basic_textures.h"

namespace kiln {

namespace {

constexpr int H = ConductorAlbedoMoments::kNodes;

// The value of a constant float texture, or nullopt.
std::optional<Float> ConstantValue(const FloatTexture& t) {
    if (const FloatConstantTexture* c = t.GetIf<FloatConstantTexture>()) return c->Value();
    return std::nullopt;
}
bool IsConstant(const std::optional<SpectrumTexture>& t) {
    return !t || t->Is<SpectrumConstantTexture>();
}

// Isotropic alpha standing in for an anisotropic distribution (textured anisotropic roughness
// only): the root mean square of the two, which came closest to the anisotropic albedo among
// the simple choices tried (projected on wo's azimuth, geometric mean, blends of the two).
Float EquivalentAlpha(const TrowbridgeReitzDistribution& d) {
    if (d.AlphaX() == d.AlphaY()) return d.AlphaX();
    return std::sqrt((Sqr(d.AlphaX()) + Sqr(d.AlphaY())) / 2);
}

// W_j at (mu, alpha) from the scene-wide table, bilinear in cos and log(alpha).
void SharedWeights(const EmissivityTables& tables, const std::vector<float>& moments, Float mu,
                   Float alpha, float* w) {
    auto [ci, ct] = tables.Cosines().Locate(mu);
    auto [ai, at] = tables.LogAlphas().Locate(std::log(std::max(alpha, 1e-4f)));
    const int nAlpha = tables.LogAlphas().Size();
    const float* w00 = &moments[(size_t(ci) * nAlpha + ai) * H];
    const float* w01 = &moments[(size_t(ci) * nAlpha + ai + 1) * H];
    const float* w10 = &moments[(size_t(ci + 1) * nAlpha + ai) * H];
    const float* w11 = &moments[(size_t(ci + 1) * nAlpha + ai + 1) * H];
    for (int j = 0; j < H; ++j)
        w[j] =
            (1 - ct) * ((1 - at) * w00[j] + at * w01[j]) + ct * ((1 - at) * w10[j] + at * w11[j]);
}

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
    std::optional<Float> u = ConstantValue(m.URoughness()), v = ConstantValue(m.VRoughness());
    uniformSpectra = IsConstant(m.Eta()) && IsConstant(m.K()) && IsConstant(m.Reflectance());
    auto remap = [&](Float r) {
        return std::max(0.f,
                        m.RemapRoughness() ? TrowbridgeReitzDistribution::RoughnessToAlpha(r) : r);
    };
    if (u && v) {
        uniformAlpha = true;
        alphaX = remap(*u);
        alphaY = remap(*v);
    } else {
        // Textured roughness: exact when both directions share one texture
        exact = m.URoughness().Variant() == m.VRoughness().Variant();
    }
    const TableAxis& cosines = t.Cosines();
    const TableAxis& lambdas = t.FineWavelengths();
    if (uniformAlpha && std::max(alphaX, alphaY) >= 1e-3f) {
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
    } else if (!uniformAlpha) {
        moments = &t.ConductorMoments();
    }
    if (uniformSpectra) {
        // F(mu_j) at every table wavelength, from the material's constant optical constants
        fresnel.resize(size_t(lambdas.Size()) * H);
        MaterialEvalContext ctx;
        for (int l = 0; l < lambdas.Size(); ++l) {
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(lambdas.Node(l));
            ConductorBxDF b = m.GetBxDF(ctx, lambda);
            for (int j = 0; j < H; ++j)
                fresnel[size_t(l) * H + j] =
                    float(FrComplex(Float(ConductorAlbedoMoments::Node(j)),
                                    std::complex<Float>(b.Eta()[0], b.K()[0])));
        }
        auto apply = [&](const float* w, int l) {
            double sum = 0;
            for (int j = 0; j < H; ++j) sum += double(w[j]) * fresnel[size_t(l) * H + j];
            return float(sum);
        };
        const int nl = lambdas.Size();
        if (moments) {
            // Textured roughness: A over the scene-wide cosine x log-alpha grid
            const int cells = cosines.Size() * t.LogAlphas().Size();
            albedoByAlpha.resize(size_t(cells) * nl);
            for (int cell = 0; cell < cells; ++cell)
                for (int l = 0; l < nl; ++l)
                    albedoByAlpha[size_t(cell) * nl + l] = apply(&(*moments)[size_t(cell) * H], l);
        }
        if (!weights.empty()) {
            const int cells = cosines.Size() * azimuths.n;
            albedo.resize(size_t(cells) * nl);
            for (int cell = 0; cell < cells; ++cell)
                for (int l = 0; l < nl; ++l)
                    albedo[size_t(cell) * nl + l] = apply(&weights[size_t(cell) * H], l);
        }
    }
}

SampledSpectrum ConductorEmissivity::Albedo(const ConductorBxDF& bxdf, Vector3f wo,
                                            const SampledWavelengths& lambda) const {
    Float mu = std::min<Float>(1, AbsCosTheta(wo));
    const TrowbridgeReitzDistribution& distrib = bxdf.Distribution();
    if (distrib.EffectivelySmooth()) return FrComplex(mu, bxdf.Eta(), bxdf.K());
    const TableAxis& lambdas = tables->FineWavelengths();
    const int nl = lambdas.Size();
    SampledSpectrum A;
    if (!albedoByAlpha.empty()) {
        // Uniform optical constants, textured roughness: one trilinear lookup per wavelength
        auto [ci, ct] = tables->Cosines().Locate(mu);
        auto [ai, at] =
            tables->LogAlphas().Locate(std::log(std::max(EquivalentAlpha(distrib), 1e-4f)));
        const int na = tables->LogAlphas().Size();
        auto row = [&](int c, int a) { return &albedoByAlpha[(size_t(c) * na + a) * nl]; };
        const float* r00 = row(ci, ai);
        const float* r01 = row(ci, ai + 1);
        const float* r10 = row(ci + 1, ai);
        const float* r11 = row(ci + 1, ai + 1);
        for (int i = 0; i < NSpectrumSamples; ++i) {
            auto [li, lt] = lambdas.Locate(lambda[i]);
            auto lerpL = [&](const float* r) { return (1 - lt) * r[li] + lt * r[li + 1]; };
            A[i] = (1 - ct) * ((1 - at) * lerpL(r00) + at * lerpL(r01)) +
                   ct * ((1 - at) * lerpL(r10) + at * lerpL(r11));
        }
        return A;
    }
    // Table cells around wo: two cosines times the azimuth nodes, with their weights
    int cells = 0, cell[8];
    float cellWeight[8];
    if (!weights.empty()) {
        auto [ci, ct] = tables->Cosines().Locate(mu);
        int node[4];
        float nodeWeight[4];
        int n = azimuths.Weights(wo, node, nodeWeight);
        for (int c = 0; c < 2; ++c)
            for (int a = 0; a < n; ++a) {
                cell[cells] = (ci + c) * azimuths.n + node[a];
                cellWeight[cells++] = (c ? ct : 1 - ct) * nodeWeight[a];
            }
    }
    if (!albedo.empty()) {
        // Uniform material: one lookup per wavelength
        for (int i = 0; i < NSpectrumSamples; ++i) {
            auto [li, lt] = lambdas.Locate(lambda[i]);
            float a = 0;
            for (int k = 0; k < cells; ++k) {
                const float* r = &albedo[size_t(cell[k]) * nl];
                a += cellWeight[k] * ((1 - lt) * r[li] + lt * r[li + 1]);
            }
            A[i] = a;
        }
        return A;
    }
    // Moment weights at this point's direction and roughness
    float w[H];
    if (!weights.empty()) {
        for (int j = 0; j < H; ++j) {
            w[j] = 0;
            for (int k = 0; k < cells; ++k)
                w[j] += cellWeight[k] * weights[size_t(cell[k]) * H + j];
        }
    } else {
        // Textured roughness (the shared table was built by the constructor)
        SharedWeights(*tables, *moments, mu, EquivalentAlpha(distrib), w);
    }
    for (int i = 0; i < NSpectrumSamples; ++i) {
        double a = 0;
        if (!fresnel.empty()) {
            auto [li, lt] = lambdas.Locate(lambda[i]);
            const float* f0 = &fresnel[size_t(li) * H];
            const float* f1 = &fresnel[size_t(li + 1) * H];
            for (int j = 0; j < H; ++j) a += w[j] * ((1 - lt) * f0[j] + lt * f1[j]);
        } else {
            std::complex<Float> eta(bxdf.Eta()[i], bxdf.K()[i]);
            for (int j = 0; j < H; ++j)
                a += w[j] * FrComplex(Float(ConductorAlbedoMoments::Node(j)), eta);
        }
        A[i] = Float(a);
    }
    return A;
}

}  // namespace kiln
