#include "materials/conductor_emissivity.h"

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

// Isotropic alpha standing in for the distribution seen from wo.
Float ProjectedAlpha(const TrowbridgeReitzDistribution& d, Vector3f wo) {
    if (d.AlphaX() == d.AlphaY()) return d.AlphaX();
    Float c2 = Sqr(CosPhi(wo)), s2 = Sqr(SinPhi(wo));
    return std::sqrt(c2 * Sqr(d.AlphaX()) + s2 * Sqr(d.AlphaY()));
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

ConductorEmissivity::ConductorEmissivity(const ConductorMaterial& m, EmissivityTables& t)
    : tables(&t) {
    std::optional<Float> u = ConstantValue(m.URoughness()), v = ConstantValue(m.VRoughness());
    uniformSpectra = IsConstant(m.Eta()) && IsConstant(m.K()) && IsConstant(m.Reflectance());
    if (u && v && *u == *v) {
        uniformAlpha = true;
        alpha = m.RemapRoughness() ? TrowbridgeReitzDistribution::RoughnessToAlpha(*u) : *u;
        alpha = std::max(alpha, 0.f);
    }
    const TableAxis& cosines = t.Cosines();
    const TableAxis& lambdas = t.Wavelengths();
    if (uniformAlpha && alpha >= 1e-3f) {
        weights.resize(size_t(cosines.Size()) * H);
        for (int c = 0; c < cosines.Size(); ++c) {
            ConductorAlbedoMoments::Weights w =
                ConductorAlbedoMoments::Compute(alpha, std::max(1e-4, double(cosines.Node(c))));
            for (int j = 0; j < H; ++j) weights[size_t(c) * H + j] = float(w[size_t(j)]);
        }
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
        if (moments) {
            // Textured roughness: A over the scene-wide cosine x log-alpha grid
            const int nc = cosines.Size(), na = t.LogAlphas().Size(), nl = lambdas.Size();
            albedoByAlpha.resize(size_t(nc) * na * nl);
            for (int c = 0; c < nc; ++c)
                for (int a = 0; a < na; ++a) {
                    const float* w = &(*moments)[(size_t(c) * na + a) * H];
                    for (int l = 0; l < nl; ++l) {
                        double sum = 0;
                        for (int j = 0; j < H; ++j)
                            sum += double(w[j]) * fresnel[size_t(l) * H + j];
                        albedoByAlpha[(size_t(c) * na + a) * nl + l] = float(sum);
                    }
                }
        }
        if (!weights.empty()) {
            albedo.resize(size_t(cosines.Size()) * lambdas.Size());
            for (int c = 0; c < cosines.Size(); ++c)
                for (int l = 0; l < lambdas.Size(); ++l) {
                    double a = 0;
                    for (int j = 0; j < H; ++j)
                        a += double(weights[size_t(c) * H + j]) * fresnel[size_t(l) * H + j];
                    albedo[size_t(c) * lambdas.Size() + l] = float(a);
                }
        }
    }
}

SampledSpectrum ConductorEmissivity::Albedo(const ConductorBxDF& bxdf, Vector3f wo,
                                            const SampledWavelengths& lambda) const {
    Float mu = std::min<Float>(1, AbsCosTheta(wo));
    const TrowbridgeReitzDistribution& distrib = bxdf.Distribution();
    if (distrib.EffectivelySmooth()) return FrComplex(mu, bxdf.Eta(), bxdf.K());
    const TableAxis& lambdas = tables->Wavelengths();
    SampledSpectrum A;
    if (!albedo.empty()) {
        // Uniform material: one bilinear lookup per wavelength
        auto [ci, ct] = tables->Cosines().Locate(mu);
        const int nl = lambdas.Size();
        for (int i = 0; i < NSpectrumSamples; ++i) {
            auto [li, lt] = lambdas.Locate(lambda[i]);
            const float* r0 = &albedo[size_t(ci) * nl];
            const float* r1 = &albedo[size_t(ci + 1) * nl];
            A[i] = (1 - ct) * ((1 - lt) * r0[li] + lt * r0[li + 1]) +
                   ct * ((1 - lt) * r1[li] + lt * r1[li + 1]);
        }
        return A;
    }
    if (!albedoByAlpha.empty()) {
        // Uniform optical constants, textured roughness: one trilinear lookup per wavelength
        auto [ci, ct] = tables->Cosines().Locate(mu);
        auto [ai, at] =
            tables->LogAlphas().Locate(std::log(std::max(ProjectedAlpha(distrib, wo), 1e-4f)));
        const int na = tables->LogAlphas().Size(), nl = lambdas.Size();
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
    // Moment weights at this point's cosine and roughness
    float w[H];
    if (!weights.empty()) {
        auto [ci, ct] = tables->Cosines().Locate(mu);
        for (int j = 0; j < H; ++j)
            w[j] = (1 - ct) * weights[size_t(ci) * H + j] + ct * weights[size_t(ci + 1) * H + j];
    } else {
        // Textured roughness (the shared table was built by the constructor)
        SharedWeights(*tables, *moments, mu, ProjectedAlpha(distrib, wo), w);
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
