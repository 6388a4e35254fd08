#include "materials/emissivity.h"

#include <algorithm>
#include <cmath>

#include "materials/bxdfs/directional_albedo.h"
#include "materials/materials.h"
#include "textures/basic_textures.h"

namespace kiln {

std::optional<EmissionModel> ParseEmissionModel(std::string_view name) {
    if (name == "kirchhoff") return EmissionModel::Kirchhoff;
    if (name == "additive") return EmissionModel::Additive;
    if (name == "diffuse") return EmissionModel::Diffuse;
    if (name == "none") return EmissionModel::None;
    return std::nullopt;
}

std::string_view EmissionModelName(EmissionModel model) {
    switch (model) {
        case EmissionModel::None:
            return "none";
        case EmissionModel::Diffuse:
            return "diffuse";
        case EmissionModel::Additive:
            return "additive";
        case EmissionModel::Kirchhoff:
            return "kirchhoff";
    }
    return "?";
}

SampledSpectrum HemisphericalReflectance(const BSDF& bsdf, Vector3f woRender, int sqrtSamples) {
    if (!bsdf) return SampledSpectrum(1.f);
    if (IsTransmissive(bsdf.Flags())) return SampledSpectrum(1.f);
    const BxDF& bxdf = bsdf.GetBxDF();
    Vector3f wo = bsdf.RenderToLocal(woRender);
    if (wo.z == 0) return SampledSpectrum(1.f);
    return DirectionalAlbedo(bxdf, wo, sqrtSamples);
}

// Uniformity of a material's parameters over the surface
namespace {

bool Constant(const FloatTexture& t) { return t.Is<FloatConstantTexture>(); }
bool Constant(const SpectrumTexture& t) { return t.Is<SpectrumConstantTexture>(); }
bool Constant(const std::optional<SpectrumTexture>& t) { return !t || Constant(*t); }

}  // namespace

bool IsSpatiallyUniform(const Material& material) {
    if (const auto* m = material.GetIf<DiffuseMaterial>()) return Constant(m->Reflectance());
    if (const auto* m = material.GetIf<ConductorMaterial>())
        return Constant(m->Eta()) && Constant(m->K()) && Constant(m->Reflectance()) &&
               Constant(m->URoughness()) && Constant(m->VRoughness());
    if (const auto* m = material.GetIf<DielectricMaterial>())
        return Constant(m->URoughness()) && Constant(m->VRoughness());
    if (material.Is<ThinDielectricMaterial>() || material.IsInterface()) return true;
    if (const auto* m = material.GetIf<CoatedDiffuseMaterial>())
        return Constant(m->Reflectance()) && Constant(m->Albedo()) && Constant(m->URoughness()) &&
               Constant(m->VRoughness()) && Constant(m->Thickness()) && Constant(m->G());
    if (const auto* m = material.GetIf<CoatedConductorMaterial>()) {
        const CoatedConductorMaterial::Params& p = m->Parameters();
        return Constant(p.interfaceURoughness) && Constant(p.interfaceVRoughness) &&
               Constant(p.thickness) && Constant(p.g) && Constant(p.conductorEta) &&
               Constant(p.k) && Constant(p.reflectance) && Constant(p.conductorURoughness) &&
               Constant(p.conductorVRoughness) && Constant(p.albedo);
    }
    return false;  // mix: chosen per point
}

BSDF EmissionBSDF(const Material& material, Point3f p, Normal3f n, Point2f uv, Vector3f wo,
                  SampledWavelengths& lambda) {
    MaterialEvalContext ctx;
    ctx.p = p;
    ctx.n = n;
    ctx.uv = uv;
    ctx.wo = wo;
    ctx.ns = n;
    Vector3f t1, t2;
    CoordinateSystem(Normalize(Vector3f(n)), &t1, &t2);
    ctx.dpdus = t1;
    const Material* m = material.ChooseMaterial(ctx);
    if (!m || m->IsInterface()) return {};
    return m->GetBSDF(ctx, lambda);
}

// ReflectanceTable
std::optional<ReflectanceTable> ReflectanceTable::Build(const Material& material) {
    if (!IsSpatiallyUniform(material) || material.IsInterface()) return std::nullopt;
    ReflectanceTable table;
    table.values.resize(size_t(kThetaCount) * kLambdaCount);
    const Normal3f n(0, 0, 1);
    for (int l = 0; l < kLambdaCount; ++l) {
        // One wavelength at a time (all four samples equal), so dispersive coatings, which
        // only keep the hero wavelength, are tabulated exactly.
        Float lambda_nm = kLambdaMin + kLambdaStep * l;
        for (int t = 0; t < kThetaCount; ++t) {
            Float theta = Radians(Float(2 * t));
            Vector3f wo(std::sin(theta), 0, std::cos(theta));
            if (t == kThetaCount - 1) wo = Vector3f(1, 0, 1e-4f);  // grazing, kept above 0
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(lambda_nm);
            BSDF bsdf = EmissionBSDF(material, Point3f(0, 0, 0), n, Point2f(0.5f, 0.5f),
                                     Normalize(wo), lambda);
            SampledSpectrum R = HemisphericalReflectance(bsdf, Normalize(wo), 32);
            table.values[size_t(t) * kLambdaCount + l] = R[0];
        }
    }
    return table;
}

SampledSpectrum ReflectanceTable::Reflectance(Float absCosTheta,
                                              const SampledWavelengths& lambda) const {
    Float theta = std::acos(Clamp(absCosTheta, 0, 1)) * (180 / Pi) / 2;  // in table steps
    theta = Clamp(theta, 0, kThetaCount - 1);
    int t0 = std::min(int(theta), kThetaCount - 2);
    Float ft = theta - t0;
    SampledSpectrum R;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        Float x = Clamp((lambda[i] - kLambdaMin) / kLambdaStep, 0, kLambdaCount - 1);
        int l0 = std::min(int(x), kLambdaCount - 2);
        Float fl = x - l0;
        auto v = [&](int t, int l) { return values[size_t(t) * kLambdaCount + l]; };
        R[i] = (1 - ft) * ((1 - fl) * v(t0, l0) + fl * v(t0, l0 + 1)) +
               ft * ((1 - fl) * v(t0 + 1, l0) + fl * v(t0 + 1, l0 + 1));
    }
    return R;
}

Float ReflectanceTable::HemisphericalAverage(Float lambda_nm) const {
    // 2 int_0^1 R(mu) mu dmu with the midpoint rule in mu.
    constexpr int n = 64;
    SampledWavelengths lambda = SampledWavelengths::FromWavelength(lambda_nm);
    Float sum = 0;
    for (int i = 0; i < n; ++i) {
        Float mu = (i + 0.5f) / n;
        sum += Reflectance(mu, lambda)[0] * mu;
    }
    return 2 * sum / n;
}

}  // namespace kiln
