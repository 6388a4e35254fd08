#include "thermal/coated_emissivity.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "base/rng.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/layered_albedo.h"
#include "materials/bxdfs/layered_bxdf.h"
#include "materials/material.h"
#include "materials/materials.h"
#include "textures/basic_textures.h"
#include "textures/metal_temperature_texture.h"

namespace kiln {

namespace {

// Polynomials up to degree 63 in the base reflectance (maxdepth up to 123)
constexpr int kMaxCoefficients = 64;
// A hot named metal's temperature nodes in the coatedconductor tables: every eighth of its
// table's (200 K apart)
constexpr size_t kCoatedTemperatureStride = 8;

// The layer has no scattering medium: a constant albedo texture that is 0 at every wavelength.
bool NoMedium(const SpectrumTexture& albedo, const TableAxis& lambdas) {
    if (!albedo.Is<SpectrumConstantTexture>()) return false;
    for (float l : lambdas.Nodes())
        if (albedo.Evaluate(TextureEvalContext(), SampledWavelengths::FromWavelength(l))[0] > 0)
            return false;
    return true;
}

// Roughness nodes: the material's alpha when both roughness parameters are one constant,
// otherwise a range covering pbrt-v4's (remapped) roughness values.
TableAxis AlphaAxis(const FloatTexture& u, const FloatTexture& v, bool remap) {
    std::optional<Float> cu = u.ConstantValue(), cv = v.ConstantValue();
    if (cu && cv && *cu == *cv) {
        Float alpha = remap ? TrowbridgeReitzDistribution::RoughnessToAlpha(std::max(*cu, 0.f))
                            : std::max(*cu, 0.f);
        return TableAxis({alpha < 1e-3f ? 0.f : alpha});
    }
    return TableAxis({0.f, 0.01f, 0.02f, 0.04f, 0.07f, 0.1f, 0.15f, 0.2f, 0.3f, 0.45f, 0.6f, 0.8f,
                      1.f, 1.4f, 2.f});
}

// The alpha the tables are looked up with: 0 when smooth, else the isotropic roughness
// projected on wo's azimuth (conductor_emissivity.h).
Float LookupAlpha(const TrowbridgeReitzDistribution& d, Vector3f wo) {
    if (d.EffectivelySmooth()) return 0;
    if (d.AlphaX() == d.AlphaY()) return d.AlphaX();
    return std::sqrt(Sqr(CosPhi(wo)) * Sqr(d.AlphaX()) + Sqr(SinPhi(wo)) * Sqr(d.AlphaY()));
}

std::vector<double> CosineNodes(const EmissivityTables& tables) {
    std::vector<double> mus;
    for (float c : tables.Cosines().Nodes()) mus.push_back(std::max(1e-4, double(c)));
    return mus;
}

}  // namespace

// SampledAlbedoTable
SampledAlbedoTable::SampledAlbedoTable(const Material& material, const EmissivityTables& tables) {
    constexpr int nCos = 16, nLambda = 8, nSamples = 4096;
    std::vector<float> c, l;
    for (int i = 0; i < nCos; ++i) c.push_back(EmissivityTables::CosineNode(i, nCos));
    const SpectralRange& range = tables.Range();
    for (int i = 0; i < nLambda; ++i)
        l.push_back(range.min + (range.max - range.min) * i / (nLambda - 1));
    cosines = TableAxis(std::move(c));
    lambdas = TableAxis(std::move(l));
    albedo.assign(size_t(nCos) * nLambda, 0);
    tbb::parallel_for(0, nCos * nLambda, [&](int cell) {
        int ci = cell / nLambda, li = cell % nLambda;
        SampledWavelengths lambda = SampledWavelengths::FromWavelength(lambdas.Node(li));
        MaterialEvalContext ctx;
        ctx.ns = Normal3f(0, 0, 1);
        ctx.n = Normal3f(0, 0, 1);
        ctx.dpdus = Vector3f(1, 0, 0);
        BSDF bsdf = material.GetBSDF(ctx, lambda);
        if (!bsdf) return;
        Float mu = std::max(1e-4f, cosines.Node(ci));
        Vector3f wo(std::sqrt(1 - mu * mu), 0, mu);
        RNG rng(Hash(ci, li));
        double sum = 0;
        for (int s = 0; s < nSamples; ++s) {
            // Stratified in the two directional dimensions
            Point2f u((s % 64 + rng.UniformFloat()) / 64, (s / 64 + rng.UniformFloat()) / 64);
            std::optional<BSDFSample> bs = bsdf.GetBxDF().Sample_f(wo, rng.UniformFloat(), u);
            if (bs && bs->pdf > 0 && SameHemisphere(wo, bs->wi))
                sum += double(bs->f[0]) * AbsCosTheta(bs->wi) / bs->pdf;
        }
        albedo[size_t(cell)] = float(std::clamp(sum / nSamples, 0.0, 1.0));
    });
}

SampledSpectrum SampledAlbedoTable::Albedo(Vector3f wo, const SampledWavelengths& lambda) const {
    auto [ci, ct] = cosines.Locate(std::min<Float>(1, AbsCosTheta(wo)));
    const int nl = lambdas.Size();
    SampledSpectrum A;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        auto [li, lt] = lambdas.Locate(lambda[i]);
        const float* r0 = &albedo[size_t(ci) * nl];
        const float* r1 = &albedo[size_t(ci + 1) * nl];
        A[i] = (1 - ct) * ((1 - lt) * r0[li] + lt * r0[li + 1]) +
               ct * ((1 - lt) * r1[li] + lt * r1[li + 1]);
    }
    return A;
}

// CoatedDiffuseEmissivity
CoatedDiffuseEmissivity::CoatedDiffuseEmissivity(const CoatedDiffuseMaterial& m,
                                                 const Material& handle, EmissivityTables& t)
    : tables(&t) {
    std::optional<Float> thickness = m.Thickness().ConstantValue();
    if (!thickness || !NoMedium(m.Albedo(), t.Wavelengths()) ||
        m.MaxDepth() / 2 + 2 > kMaxCoefficients) {
        fallback.emplace(handle, t);
        return;
    }
    alphas = AlphaAxis(m.URoughness(), m.VRoughness(), m.RemapRoughness());
    // A dispersive coat: eta at wavelength nodes
    bool dispersive = !m.Eta().Is<ConstantSpectrum>();
    // (over the visible: 360, 420, ..., 720 and 830 nm; beyond it, as many nodes spread over
    // the scene's range in the same proportions)
    const SpectralRange& range = t.Range();
    std::vector<float> nodes;
    for (float l : {360.f, 420.f, 480.f, 540.f, 600.f, 660.f, 720.f, 830.f})
        nodes.push_back(range.IsVisible()
                            ? l
                            : range.min + (range.max - range.min) * (l - 360.f) / (830.f - 360.f));
    lambdas = dispersive ? TableAxis(nodes) : TableAxis({550.f});
    std::vector<double> mus = CosineNodes(t);
    const int nCos = int(mus.size()), nA = alphas.Size(), nL = lambdas.Size();
    nCoefficients = m.MaxDepth() / 2 + 2;
    coefficients.assign(size_t(nL) * nA * nCos * nCoefficients, 0);
    tbb::parallel_for(0, nL * nA, [&](int cell) {
        int li = cell / nA, ai = cell % nA;
        Float eta = m.Eta()(lambdas.Node(li));
        CoatParameters coat{eta == 0 ? 1.0 : double(eta), double(alphas.Node(ai)),
                            double(LayerThickness(*thickness)), m.MaxDepth()};
        std::vector<std::vector<double>> poly = CoatedDiffuseAlbedoPolynomials(coat, mus);
        for (int c = 0; c < nCos; ++c)
            for (int k = 0; k < nCoefficients && k < int(poly[size_t(c)].size()); ++k)
                coefficients[((size_t(cell) * nCos) + c) * nCoefficients + k] =
                    float(poly[size_t(c)][size_t(k)]);
    });
}

SampledSpectrum CoatedDiffuseEmissivity::Albedo(const CoatedDiffuseBxDF& bxdf, Vector3f wo,
                                                const SampledWavelengths& lambda) const {
    if (fallback) return fallback->Albedo(wo, lambda);
    // (plain variables: lambdas may not capture structured bindings in clang 14)
    const auto [ci, ct] = tables->Cosines().Locate(std::min<Float>(1, AbsCosTheta(wo)));
    const auto [ai, at] = alphas.Locate(LookupAlpha(bxdf.Top().Distribution(), wo));
    const int nCos = tables->Cosines().Size(), nA = alphas.Size(), K = nCoefficients;
    const SampledSpectrum& r = bxdf.Bottom().Reflectance();
    // Coefficients interpolated at the wavelength node li (+ lt towards the next)
    auto interpolate = [&, ci = ci, ct = ct, ai = ai, at = at](int li, float lt, float* a) {
        for (int k = 0; k < K; ++k) a[k] = 0;
        for (int dl = 0; dl < 2; ++dl)
            for (int da = 0; da < 2; ++da)
                for (int dc = 0; dc < 2; ++dc) {
                    float w = (dl ? lt : 1 - lt) * (da ? at : 1 - at) * (dc ? ct : 1 - ct);
                    if (w == 0) continue;
                    int l = dl ? lambdas.Next(li) : li, al = da ? alphas.Next(ai) : ai;
                    const float* row =
                        &coefficients[((size_t(l) * nA + al) * nCos + ci + dc) * size_t(K)];
                    for (int k = 0; k < K; ++k) a[k] += w * row[k];
                }
    };
    float a[kMaxCoefficients];
    const bool dispersive = lambdas.Size() > 1;
    if (!dispersive) interpolate(0, 0, a);  // the same for every wavelength
    SampledSpectrum A;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        if (dispersive) {
            auto [li, lt] = lambdas.Locate(lambda[i]);
            interpolate(li, lt, a);
        }
        // Horner in r
        Float v = 0;
        for (int k = K - 1; k >= 0; --k) v = v * r[i] + a[k];
        A[i] = v;
    }
    return A;
}

// CoatedConductorEmissivity
CoatedConductorEmissivity::CoatedConductorEmissivity(const CoatedConductorMaterial& m,
                                                     const Material& handle, EmissivityTables& t)
    : tables(&t) {
    const CoatedConductorMaterial::Params& p = m.Parameters();
    // (a named metal's constants at a fixed temperature, or following the surface's: below)
    auto uniform = [](const std::optional<SpectrumTexture>& s) {
        return !s || s->Is<SpectrumConstantTexture>() || s->Is<SpectrumMetalTemperatureTexture>();
    };
    std::optional<Float> thickness = p.thickness.ConstantValue();
    if (!thickness || !NoMedium(p.albedo, t.Wavelengths()) ||
        !p.interfaceEta.Is<ConstantSpectrum>() || !uniform(p.conductorEta) || !uniform(p.k) ||
        !uniform(p.reflectance)) {
        fallback.emplace(handle, t);
        return;
    }
    coatAlphas = AlphaAxis(p.interfaceURoughness, p.interfaceVRoughness, p.remapRoughness);
    baseAlphas = AlphaAxis(p.conductorURoughness, p.conductorVRoughness, p.remapRoughness);
    Float eta = p.interfaceEta(550.f);
    if (eta == 0) eta = 1;
    // A named metal whose constants follow the surface's temperature: every eighth of its
    // table's temperature nodes (200 K apart; the last one too)
    const auto* hot =
        p.conductorEta ? p.conductorEta->GetIf<SpectrumMetalTemperatureTexture>() : nullptr;
    if (hot && hot->FollowsSurface()) {
        const std::vector<float>& all = hot->Table().Temperatures().Nodes();
        std::vector<float> nodes;
        for (size_t i = 0; i < all.size(); i += kCoatedTemperatureStride) nodes.push_back(all[i]);
        if (nodes.back() != all.back()) nodes.push_back(all.back());
        temperatures = TableAxis(std::move(nodes));
    } else {
        temperatures = TableAxis({0.f});
    }
    // The conductor's Fresnel reflectance relative to the coat, per table temperature and
    // wavelength
    const TableAxis& lambdas = t.Wavelengths();
    std::vector<std::function<double(double)>> fresnels;
    for (float T : temperatures.Nodes())
        for (float l : lambdas.Nodes()) {
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(l);
            MaterialEvalContext ctx;
            ctx.temperature = T;
            CoatedConductorBxDF b = m.GetBxDF(ctx, lambda);
            std::complex<Float> ce(b.Bottom().Eta()[0], b.Bottom().K()[0]);
            fresnels.push_back([ce](double mu) { return double(FrComplex(Float(mu), ce)); });
        }
    std::vector<double> mus = CosineNodes(t);
    const int nCos = int(mus.size()), nL = lambdas.Size() * temperatures.Size(),
              nB = baseAlphas.Size();
    albedo.assign(size_t(coatAlphas.Size()) * nB * nCos * nL, 0);
    tbb::parallel_for(0, coatAlphas.Size() * nB, [&](int cell) {
        int ca = cell / nB, ba = cell % nB;
        CoatParameters coat{double(eta), double(coatAlphas.Node(ca)),
                            double(LayerThickness(*thickness)), p.maxDepth};
        std::vector<std::vector<double>> A =
            CoatedConductorAlbedo(coat, baseAlphas.Node(ba), fresnels, mus);
        for (int c = 0; c < nCos; ++c)
            for (int l = 0; l < nL; ++l)
                albedo[((size_t(cell) * nCos) + c) * nL + l] = float(A[size_t(l)][size_t(c)]);
    });
}

SampledSpectrum CoatedConductorEmissivity::Albedo(const CoatedConductorBxDF& bxdf, Vector3f wo,
                                                  const SampledWavelengths& lambda,
                                                  Float temperature) const {
    if (fallback) return fallback->Albedo(wo, lambda);
    const TableAxis& cosines = tables->Cosines();
    const TableAxis& lambdas = tables->Wavelengths();
    auto [ci, ct] = cosines.Locate(std::min<Float>(1, AbsCosTheta(wo)));
    auto [ai, at] = coatAlphas.Locate(LookupAlpha(bxdf.Top().Distribution(), wo));
    auto [bi, bt] = baseAlphas.Locate(LookupAlpha(bxdf.Bottom().Distribution(), wo));
    // (one node, weight 1, without a temperature axis)
    auto [ti, tt] = temperatures.Locate(temperature);
    const int nCos = cosines.Size(), nL = lambdas.Size(), nT = temperatures.Size(),
              nB = baseAlphas.Size();
    const size_t nX = size_t(nL) * nT;
    SampledSpectrum A;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        auto [li, lt] = lambdas.Locate(lambda[i]);
        Float v = 0;
        for (int dt = 0; dt < 2; ++dt) {
            float wt = dt ? tt : 1 - tt;
            if (wt == 0) continue;
            const size_t x = size_t(dt ? temperatures.Next(ti) : ti) * nL + li;
            for (int da = 0; da < 2; ++da)
                for (int db = 0; db < 2; ++db)
                    for (int dc = 0; dc < 2; ++dc) {
                        float w = wt * (da ? at : 1 - at) * (db ? bt : 1 - bt) * (dc ? ct : 1 - ct);
                        if (w == 0) continue;
                        int a = da ? coatAlphas.Next(ai) : ai, b = db ? baseAlphas.Next(bi) : bi;
                        const float* row =
                            &albedo[((size_t(a) * nB + b) * nCos + ci + dc) * nX + x];
                        v += w * ((1 - lt) * row[0] + lt * row[1]);
                    }
        }
        A[i] = v;
    }
    return A;
}

}  // namespace kiln
