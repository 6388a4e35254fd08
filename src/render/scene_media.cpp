#include "render/scene_media.h"

#include <cmath>

#include "media/homogeneous_medium.h"
#include "spectral/spectral_range.h"
#include "textures/basic_textures.h"

namespace kiln {

MediumIndices CreateMedia(SceneDescription& desc, const NamedTextures& textures,
                          const std::function<const Material*(const ShapeSceneEntity&)>& materialOf,
                          std::optional<EmissionModel> modelOverride, std::vector<Medium>& media,
                          ObjectArena& arena, Diagnostics& diag) {
    MediumIndices indices;
    for (auto& [name, e] : desc.media) {
        std::string type = e.parameters.GetOneString("type", "");
        if (type.empty())
            throw SceneError(
                e.loc, "MakeNamedMedium \"" + name + "\" needs a \"string type\" parameter", name);
        if (desc.ambientTemperature && !e.parameters.Has("temperature") &&
            !e.parameters.Has("Le") &&
            !(type == "uniformgrid" && e.parameters.GetFloatArray("density").size() == 1)) {
            ParsedParameter ambient;
            ambient.type = "float";
            ambient.name = "temperature";
            ambient.loc = desc.ambientTemperatureLoc;
            ambient.floats = {*desc.ambientTemperature};
            e.parameters.AddDefault(std::move(ambient));
        }
        TextureParameterDictionary params(&e.parameters, &textures);
        indices[name] = int(media.size());
        media.push_back(
            Medium::Create(type, params, e.renderFromObject, modelOverride, e.loc, arena, diag));
        e.parameters.ReportUnused(diag);
    }
    // Refractive indices of the bodies the media fill
    std::vector<const ShapeSceneEntity*> boundedBy(media.size(), nullptr);
    auto visit = [&](const ShapeSceneEntity& s) {
        auto it = indices.find(s.insideMedium);
        if (it == indices.end() || s.insideMedium == s.outsideMedium) return;
        std::optional<Spectrum> eta = materialOf(s)->InteriorEta();
        if (!eta) return;
        const ShapeSceneEntity*& first = boundedBy[size_t(it->second)];
        if (!first) {
            first = &s;
            media[size_t(it->second)].SetRefractiveIndex(*eta);
        } else if (materialOf(*first) != materialOf(s)) {
            diag.Warn(s.loc, "medium '" + s.insideMedium +
                                 "' fills bodies of different materials; its thermal emission "
                                 "uses the refractive index of the first, at " +
                                 first->loc.ToString());
        }
    };
    for (const ShapeSceneEntity& s : desc.shapes) visit(s);
    for (const auto& [name, def] : desc.instanceDefinitions)
        for (const ShapeSceneEntity& s : def.shapes) visit(s);
    return indices;
}

// Absorbing glass
namespace {

// 4 pi k(lambda) / lambda per metre, tabulated at k's own points (a piecewise-linear k) and
// steps of 0.5 % over kiln's spectral range
Spectrum AbsorptionOfExtinction(const Spectrum& k) {
    std::vector<Float> lambdas;
    for (double l = kSpectralRangeMin; l < kSpectralRangeMax; l *= 1.005)
        lambdas.push_back(Float(l));
    lambdas.push_back(kSpectralRangeMax);
    if (const PiecewiseLinearSpectrum* table = k.GetIf<PiecewiseLinearSpectrum>())
        for (Float l : table->Lambdas())
            if (l > kSpectralRangeMin && l < kSpectralRangeMax) lambdas.push_back(l);
    std::sort(lambdas.begin(), lambdas.end());
    lambdas.erase(std::unique(lambdas.begin(), lambdas.end()), lambdas.end());
    std::vector<Float> sigma;
    for (Float l : lambdas)
        sigma.push_back(Float(4 * Pi * std::max<double>(0, k(l)) / (double(l) * 1e-9)));
    PiecewiseLinearSpectrum s(lambdas, sigma);
    s.HoldEndsBeyondVisible();
    return s;
}

}  // namespace

void CreateAbsorbingGlassMedia(
    SceneDescription& desc, const NamedTextures& textures,
    const std::function<const Material*(const ShapeSceneEntity&)>& materialOf,
    const std::function<const ThermalProperties&(const ShapeSceneEntity&)>& heatOf,
    std::optional<EmissionModel> modelOverride, std::vector<Medium>& media, MediumIndices& indices,
    ObjectArena& arena) {
    std::map<const Material*, Spectrum> absorption;
    // (material, constant temperature or -1 for none) -> the medium's name
    std::map<std::pair<const Material*, Float>, std::string> shared;
    std::optional<FloatTexture> ambient;
    if (desc.ambientTemperature)
        ambient = FloatTexture(arena.New<FloatConstantTexture>(*desc.ambientTemperature));
    auto visit = [&](ShapeSceneEntity& s) {
        if (s.insideMedium != s.outsideMedium) return;  // the body has its own media
        const Material* material = materialOf(s);
        std::optional<Spectrum> k = material ? material->InteriorExtinction() : std::nullopt;
        if (!k) return;
        // Its temperature and emission model, in the precedence of thermal emitters
        TextureParameterDictionary params(&s.parameters, &textures);
        ThermalProperties own = ReadThermalProperties(params, s.name == "trianglemesh", arena);
        const ThermalProperties& fromMaterial = heatOf(s);
        std::optional<FloatTexture> temperature =
            own.temperature ? own.temperature : fromMaterial.temperature;
        if (!temperature) temperature = ambient;
        EmissionModel model =
            modelOverride
                ? *modelOverride
                : own.model.value_or(fromMaterial.model.value_or(EmissionModel::Kirchhoff));
        Float constant = -1;
        if (temperature) {
            const FloatConstantTexture* c = temperature->GetIf<FloatConstantTexture>();
            constant = c ? c->Evaluate(TextureEvalContext()) : -2;
        }
        std::string& name = shared[{material, constant}];
        if (name.empty() || constant == -2) {
            // Unique (two bodies on one line of a scene may need two media)
            name =
                kAbsorbingGlassMediumPrefix + std::to_string(media.size()) + "@" + s.loc.ToString();
            auto it = absorption.find(material);
            if (it == absorption.end())
                it = absorption.emplace(material, AbsorptionOfExtinction(*k)).first;
            MediumCoefficients c;
            c.sigma_a = it->second;
            c.sigma_s = ConstantSpectrum(0);
            MediumEmission emission =
                temperature ? MediumEmission::Thermal(*temperature, model) : MediumEmission();
            Medium medium(arena.New<HomogeneousMedium>(c, std::move(emission)));
            medium.SetRefractiveIndex(*material->InteriorEta());
            indices[name] = int(media.size());
            media.push_back(medium);
        }
        s.insideMedium = name;
    };
    for (ShapeSceneEntity& s : desc.shapes) visit(s);
    for (auto& [name, def] : desc.instanceDefinitions)
        for (ShapeSceneEntity& s : def.shapes) visit(s);
}

int MediumIndex(const std::string& name, const MediumIndices& media, const FileLoc& loc) {
    if (name.empty()) return -1;
    auto it = media.find(name);
    if (it == media.end()) throw SceneError(loc, "medium '" + name + "' not defined", name);
    return it->second;
}

std::vector<char> ExactEmissionMedia(std::span<const Medium> media) {
    std::vector<char> exact(media.size(), 0);
    for (size_t i = 0; i < media.size(); ++i)
        exact[i] = media[i].IsEmissive() && media[i].IsUniform();
    return exact;
}

std::vector<bool> GlowingInsideDielectrics(std::span<const Medium> media,
                                           std::span<const MediumBoundary> boundaries) {
    std::vector<bool> inside(media.size(), false);
    for (int m = 0; m < int(media.size()); ++m) {
        if (!media[size_t(m)].IsEmissive()) continue;
        bool touched = false, onlyDielectrics = true;
        for (const MediumBoundary& b : boundaries)
            if (b.media.inside == m || b.media.outside == m) {
                touched = true;
                onlyDielectrics &= b.material && !b.material->IsInterface() &&
                                   !b.material->MayPassLightStraightThrough() &&
                                   b.material->InteriorEta().has_value();
            }
        inside[size_t(m)] = touched && onlyDielectrics;
    }
    return inside;
}

std::unique_ptr<MediumEmissionSampler> CreateMediumEmissionSampler(
    std::span<const Medium> media, std::span<const MediumBoundary> boundaries) {
    std::vector<MediumEmissionSampler::Region> regions;
    std::vector<bool> inGlass = GlowingInsideDielectrics(media, boundaries);
    for (int m = 0; m < int(media.size()); ++m) {
        if (!media[size_t(m)].IsEmissive() || inGlass[size_t(m)]) continue;
        Bounds3f touching;
        for (const MediumBoundary& b : boundaries)
            if (b.media.inside == m || b.media.outside == m) touching = Union(touching, b.bounds);
        std::optional<Bounds3f> own = media[size_t(m)].RenderBounds();
        Bounds3f box = touching;
        if (own && touching.IsEmpty()) {
            box = *own;
        } else if (own) {
            box.pMin = Max(own->pMin, touching.pMin);
            box.pMax = Min(own->pMax, touching.pMax);
        }
        if (!box.IsEmpty()) regions.push_back({m, box});
    }
    if (regions.empty()) return nullptr;
    auto sampler = std::make_unique<MediumEmissionSampler>(media, regions);
    if (sampler->Emitters() == 0) return nullptr;
    return sampler;
}

}  // namespace kiln
