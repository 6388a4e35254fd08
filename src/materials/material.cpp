#include "materials/material.h"

#include <cstdio>

#include "core/parser/suggestions.h"
#include "materials/materials.h"
#include "materials/measured_material.h"
#include "materials/subsurface_material.h"
#include "spectral/named_spectra.h"
#include "textures/basic_textures.h"
#include "textures/metal_temperature_texture.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// Material Method Definitions
const Material* Material::ChooseMaterial(const MaterialEvalContext& ctx) const {
    const Material* m = this;
    for (uint64_t depth = 0; m->IsMix(); ++depth)
        m = m->GetIf<MixMaterial>()->ChooseMaterial(ctx, depth);
    return m;
}

BSDF Material::GetBSDF(const MaterialEvalContext& ctx, SampledWavelengths& lambda) const {
    const Material* m = ChooseMaterial(ctx);
    return m->Dispatch([&](const auto* mtl) -> BSDF {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(mtl)>>;
        if constexpr (std::is_same_v<T, InterfaceMaterial> || std::is_same_v<T, MixMaterial>)
            return BSDF();
        else
            return BSDF(ctx.ns, ctx.dpdus, BxDF(mtl->GetBxDF(ctx, lambda)), ctx.n);
    });
}

const ShadingPerturbation& Material::Perturbation() const {
    return Dispatch([](const auto* m) -> const ShadingPerturbation& { return m->perturbation; });
}

bool Material::UsesFootprint() const {
    return Dispatch([](const auto* m) { return m->usesFootprint; });
}

bool Material::UsesTemperature() const {
    return Dispatch([](const auto* m) { return m->usesTemperature; });
}

bool Material::MayPassLightStraightThrough() const {
    if (const MixMaterial* mix = GetIf<MixMaterial>())
        return mix->GetMaterial(0).MayPassLightStraightThrough() ||
               mix->GetMaterial(1).MayPassLightStraightThrough();
    if (const ThinDielectricMaterial* thin = GetIf<ThinDielectricMaterial>())
        return thin->Eta().Is<ConstantSpectrum>();
    return false;
}

std::optional<Spectrum> Material::InteriorEta() const {
    if (const DielectricMaterial* d = GetIf<DielectricMaterial>()) return d->Eta();
    return std::nullopt;
}

std::optional<Spectrum> Material::InteriorExtinction() const {
    if (const DielectricMaterial* d = GetIf<DielectricMaterial>()) return d->K();
    return std::nullopt;
}

// Material creation
namespace {

Spectrum Constant(Float c) { return Spectrum(ConstantSpectrum(c)); }

// "prefix.uroughness"/"prefix.vroughness", each defaulting to "prefix.roughness" (0).
std::pair<FloatTexture, FloatTexture> GetRoughness(const TextureParameterDictionary& params,
                                                   const std::string& prefix, ObjectArena& arena) {
    std::optional<FloatTexture> u = params.GetFloatTextureOrNull(prefix + "uroughness", arena);
    std::optional<FloatTexture> v = params.GetFloatTextureOrNull(prefix + "vroughness", arena);
    std::string uName = prefix + "uroughness", vName = prefix + "vroughness";
    if (!u || !v) {
        FloatTexture r = params.GetFloatTexture(prefix + "roughness", 0, arena);
        if (!u) u = r, uName = prefix + "roughness";
        if (!v) v = r, vName = prefix + "roughness";
    }
    // Roughness is never negative (pbrt-v4 takes the square root of it); textured values are
    // clamped where the distribution is built
    for (auto [t, name] : {std::pair{*u, uName}, {*v, vName}})
        if (const FloatConstantTexture* c = t.GetIf<FloatConstantTexture>(); c && c->Value() < 0) {
            char value[32];
            std::snprintf(value, sizeof(value), "%g", double(c->Value()));
            throw SceneError(params.Loc(name), "\"" + name + "\" must be >= 0, not " + value, name);
        }
    return {*u, *v};
}

// A dielectric's IOR: "float name" or a spectrum (named glass, pairs, file), else def.
Spectrum GetEta(const TextureParameterDictionary& params, const std::string& name, Float def) {
    std::vector<Float> etaArray = params.GetFloatArray(name);
    if (!etaArray.empty()) return Constant(etaArray[0]);
    std::optional<Spectrum> eta =
        params.GetOneSpectrum(name, std::nullopt, SpectrumType::Unbounded);
    return eta ? *eta : Constant(def);
}

// The chemical symbol X of "spectrum eta" "metal-X-eta" with "spectrum k" "metal-X-k", when
// X's optical constants follow temperature (spectral/metal_temperature.h); "" otherwise.
std::string MetalWithTemperatureModel(const TextureParameterDictionary& params,
                                      const std::string& prefix) {
    std::string eta = params.GetSpectrumName(prefix + "eta"),
                k = params.GetSpectrumName(prefix + "k");
    if (!eta.starts_with("metal-") || !eta.ends_with("-eta")) return "";
    std::string symbol = eta.substr(6, eta.size() - 10);
    if (k != "metal-" + symbol + "-k" || !HasMetalTemperatureModel(symbol)) return "";
    return symbol;
}

// "float opticaltemperature" (kelvin; 0 if absent): the temperature of the constants wherever
// the surface is
Float OpticalTemperature(const TextureParameterDictionary& params) {
    if (!params.Has("opticaltemperature")) return 0;
    Float fixed = params.GetOneFloat("opticaltemperature", 0);
    if (!(fixed >= 0 && fixed < 1e5f))
        throw SceneError(params.Loc("opticaltemperature"),
                         "\"opticaltemperature\" must be kelvin from 0 to 1e5",
                         "opticaltemperature");
    return fixed;
}

// "string nkfiles" and "float nktemperatures": n and k measured at several temperatures
// (spectral/nk_file.h), one file per temperature
const MetalTemperatureTable* ReadMeasuredConstants(const TextureParameterDictionary& params,
                                                   const FileLoc& loc, ObjectArena& arena) {
    std::vector<std::string> files = params.GetFilenameArray("nkfiles");
    std::vector<Float> temperatures = params.GetFloatArray("nktemperatures");
    FileLoc at = params.Loc("nkfiles", loc);
    if (files.size() < 2 || temperatures.size() != files.size())
        throw SceneError(at,
                         "\"nkfiles\" takes two or more files, and \"nktemperatures\" one "
                         "temperature (kelvin) for each",
                         "nkfiles");
    for (const char* other : {"eta", "k", "reflectance"})
        if (params.Has(other))
            throw SceneError(
                params.Loc(other, loc),
                std::string("\"nkfiles\" gives the conductor's n and k; it takes no \"") + other +
                    "\"",
                other);
    for (size_t i = 0; i < temperatures.size(); ++i)
        if (!(temperatures[i] > 0 && temperatures[i] < 1e5f) ||
            (i > 0 && !(temperatures[i] > temperatures[i - 1])))
            throw SceneError(params.Loc("nktemperatures", loc),
                             "\"nktemperatures\" must be kelvin from 0 to 1e5, increasing",
                             "nktemperatures");
    std::vector<std::pair<Float, NkTable>> measurements;
    for (size_t i = 0; i < files.size(); ++i) {
        try {
            measurements.emplace_back(temperatures[i], ReadNkFile(files[i]));
        } catch (const std::exception& e) {
            throw SceneError(at, e.what(), files[i]);
        }
    }
    return arena.New<MetalTemperatureTable>(MetalTemperatureTable::FromMeasurements(measurements));
}

// A conductor's eta/k (Cu by default) or "reflectance"; SceneError when both are given. The
// named metals with a temperature model (a conductor's, or a coatedconductor's "conductor."
// ones) become textures that follow the surface's temperature, or the temperature "float
// opticaltemperature" fixes (kelvin; at or below room temperature: the named tables); so do
// constants measured at several temperatures ("nkfiles", conductor only).
struct ConductorSpec {
    std::optional<SpectrumTexture> eta, k, reflectance;
};
ConductorSpec GetConductor(const TextureParameterDictionary& params, const std::string& prefix,
                           const FileLoc& loc, ObjectArena& arena) {
    ConductorSpec c;
    using Part = SpectrumMetalTemperatureTexture::Part;
    if (prefix.empty() && params.Has("nkfiles")) {
        const MetalTemperatureTable* table = ReadMeasuredConstants(params, loc, arena);
        Float fixed = OpticalTemperature(params);
        c.eta = arena.New<SpectrumMetalTemperatureTexture>(table, Part::Eta, fixed);
        c.k = arena.New<SpectrumMetalTemperatureTexture>(table, Part::K, fixed);
        return c;
    }
    if (std::string symbol = MetalWithTemperatureModel(params, prefix);
        !symbol.empty() && !params.Has("reflectance")) {
        const MetalTemperatureTable* table = MetalTemperatureTable::Find(symbol);
        Float fixed = OpticalTemperature(params);
        if (!params.Has("opticaltemperature") || fixed > table->RoomTemperature()) {
            // (looked up, so that they are not reported unused)
            params.GetSpectrumTextureOrNull(prefix + "eta", SpectrumType::Unbounded, arena);
            params.GetSpectrumTextureOrNull(prefix + "k", SpectrumType::Unbounded, arena);
            c.eta = arena.New<SpectrumMetalTemperatureTexture>(table, Part::Eta, fixed);
            c.k = arena.New<SpectrumMetalTemperatureTexture>(table, Part::K, fixed);
            return c;
        }
        // At or below room temperature: the named tables, as constant textures (below)
    }
    c.eta = params.GetSpectrumTextureOrNull(prefix + "eta", SpectrumType::Unbounded, arena);
    c.k = params.GetSpectrumTextureOrNull(prefix + "k", SpectrumType::Unbounded, arena);
    c.reflectance = params.GetSpectrumTextureOrNull("reflectance", SpectrumType::Albedo, arena);
    if (c.reflectance && (c.eta || c.k))
        throw SceneError(params.Loc("reflectance"),
                         "both \"reflectance\" and \"" + prefix + "eta\"/\"" + prefix +
                             "k\" given for a conductor",
                         "reflectance");
    if (!c.reflectance) {
        if (!c.eta) c.eta = arena.New<SpectrumConstantTexture>(*GetNamedSpectrum("metal-Cu-eta"));
        if (!c.k) c.k = arena.New<SpectrumConstantTexture>(*GetNamedSpectrum("metal-Cu-k"));
    }
    return c;
}

// pbrt-v4's spectra given as wavelength-value pairs are 0 outside the wavelengths they list: a
// conductor whose "eta" and "k" are both 0 at a wavelength the render samples is a perfect
// mirror there in kiln (FrComplex's eta = 0 limit), where pbrt-v4's complex Fresnel divides by
// zero and drops every sample that meets it. Warned once, at the first such wavelength.
void WarnZeroConductorConstants(const ConductorSpec& c, const TextureParameterDictionary& params,
                                const std::string& prefix, const FileLoc& loc, Diagnostics& diag) {
    auto constant = [](const std::optional<SpectrumTexture>& t) -> const Spectrum* {
        const auto* texture = t ? t->GetIf<SpectrumConstantTexture>() : nullptr;
        return texture ? &texture->Value() : nullptr;
    };
    const Spectrum *eta = constant(c.eta), *k = constant(c.k);
    if (!eta || !k) return;
    for (int nm = int(Lambda_min); nm <= int(Lambda_max); ++nm)
        if ((*eta)(Float(nm)) == 0 && (*k)(Float(nm)) == 0) {
            diag.Warn(params.Loc(prefix + "eta", loc),
                      "a conductor's \"" + prefix + "eta\" and \"" + prefix + "k\" are both 0 at " +
                          std::to_string(nm) +
                          " nm (a spectrum is 0 outside the wavelengths it lists): kiln "
                          "reflects all light there; pbrt-v4 drops those samples as "
                          "not-a-number");
            return;
        }
}

}  // namespace

Material Material::Create(const std::string& type, const TextureParameterDictionary& params,
                          const std::map<std::string, Material>& namedMaterials, const FileLoc& loc,
                          ObjectArena& arena, Diagnostics& diag, LayeredMIS layeredMIS,
                          BSSRDFTableCache* bssrdfTables) {
    ShadingPerturbation perturbation;
    auto make = [&](auto* m) {
        m->perturbation = perturbation;
        Material material(m);
        m->usesFootprint = ComputeUsesFootprint(material);
        m->usesTemperature = ComputeUsesTemperature(material);
        return material;
    };
    if (type.empty() || type == "none" || type == "interface")
        return make(arena.New<InterfaceMaterial>());
    if (type == "mix") {
        std::vector<std::string> names = params.GetStringArray("materials");
        FileLoc at = params.Loc("materials", loc);
        if (names.size() != 2)
            throw SceneError(at, "mix material needs two values for \"string materials\"",
                             "materials");
        std::optional<Material> m[2];
        for (int i = 0; i < 2; ++i) {
            if (names[i].empty() || names[i] == "none" || names[i] == "interface") {
                m[i] = arena.New<InterfaceMaterial>();
                continue;
            }
            auto it = namedMaterials.find(names[i]);
            if (it == namedMaterials.end())
                throw SceneError(at, "named material \"" + names[i] + "\" not defined", names[i]);
            m[i] = it->second;
        }
        return make(
            arena.New<MixMaterial>(*m[0], *m[1], params.GetFloatTexture("amount", 0.5f, arena)));
    }

    // Bump or normal map, for every material that scatters (pbrt-v4: not mix or interface)
    perturbation = ShadingPerturbation::Read(params, arena);

    auto remap = [&] { return params.GetOneBool("remaproughness", true); };
    if (type == "diffuse")
        return make(arena.New<DiffuseMaterial>(
            params.GetSpectrumTexture("reflectance", Constant(0.5f), SpectrumType::Albedo, arena)));
    if (type == "conductor") {
        ConductorSpec c = GetConductor(params, "", loc, arena);
        WarnZeroConductorConstants(c, params, "", loc, diag);
        auto [u, v] = GetRoughness(params, "", arena);
        return make(arena.New<ConductorMaterial>(c.eta, c.k, c.reflectance, u, v, remap()));
    }
    if (type == "dielectric") {
        Spectrum eta = GetEta(params, "eta", 1.5f);
        auto [u, v] = GetRoughness(params, "", arena);
        // kiln: an absorbing dielectric (glass through the infrared)
        std::optional<Spectrum> k;
        if (params.Has("k")) {
            k = GetEta(params, "k", 0);
            if (k->Is<ConstantSpectrum>() && !(k->MaxValue() >= 0 && k->MaxValue() < 1e10f))
                throw SceneError(params.Loc("k"), "\"k\" must be 0 or more and finite", "k");
            if (k->Is<ConstantSpectrum>() && k->MaxValue() == 0) k.reset();
        }
        return make(arena.New<DielectricMaterial>(eta, u, v, remap(), k));
    }
    if (type == "thindielectric")
        return make(arena.New<ThinDielectricMaterial>(GetEta(params, "eta", 1.5f)));
    if (type == "coateddiffuse") {
        SpectrumTexture reflectance =
            params.GetSpectrumTexture("reflectance", Constant(0.5f), SpectrumType::Albedo, arena);
        auto [u, v] = GetRoughness(params, "", arena);
        FloatTexture thickness = params.GetFloatTexture("thickness", 0.01f, arena);
        Spectrum eta = GetEta(params, "eta", 1.5f);
        int maxDepth = params.GetOneInt("maxdepth", 10);
        int nSamples = params.GetOneInt("nsamples", 1);
        FloatTexture g = params.GetFloatTexture("g", 0, arena);
        SpectrumTexture albedo =
            params.GetSpectrumTexture("albedo", Constant(0), SpectrumType::Albedo, arena);
        return make(arena.New<CoatedDiffuseMaterial>(reflectance, albedo, u, v, thickness, g, eta,
                                                     maxDepth, nSamples, remap(), layeredMIS));
    }
    if (type == "coatedconductor") {
        auto [iu, iv] = GetRoughness(params, "interface.", arena);
        ConductorSpec c = GetConductor(params, "conductor.", loc, arena);
        WarnZeroConductorConstants(c, params, "conductor.", loc, diag);
        auto [cu, cv] = GetRoughness(params, "conductor.", arena);
        CoatedConductorMaterial::Params p{
            iu,
            iv,
            params.GetFloatTexture("thickness", 0.01f, arena),
            params.GetFloatTexture("g", 0, arena),
            GetEta(params, "interface.eta", 1.5f),
            c.eta,
            c.k,
            c.reflectance,
            cu,
            cv,
            params.GetSpectrumTexture("albedo", Constant(0), SpectrumType::Albedo, arena),
            params.GetOneInt("maxdepth", 10),
            params.GetOneInt("nsamples", 1),
            remap(),
            layeredMIS};
        return make(arena.New<CoatedConductorMaterial>(std::move(p)));
    }
    if (type == "polarizer" || type == "retarder") {
        Float angle = params.GetOneFloat("angle", 0);
        Float retardance = type == "retarder" ? params.GetOneFloat("retardance", 90) : 0;
        if (!std::isfinite(angle) || !std::isfinite(retardance))
            throw SceneError(params.Has("angle") && !std::isfinite(angle)
                                 ? params.Loc("angle")
                                 : params.Loc("retardance"),
                             "\"" + type + "\" angles must be finite (degrees)", type);
        return make(arena.New<PolarizingFilterMaterial>(
            type == "polarizer" ? PolarizingFilterBxDF::Kind::LinearPolarizer
                                : PolarizingFilterBxDF::Kind::Retarder,
            Radians(angle), Radians(retardance)));
    }
    if (type == "hair") return make(HairMaterial::Create(params, arena, diag));
    if (type == "diffusetransmission") {
        Float scale = params.GetOneFloat("scale", 1);
        if (!std::isfinite(scale) || scale < 0)
            throw SceneError(params.Loc("scale"), "\"scale\" must be finite and not negative",
                             "scale");
        return make(arena.New<DiffuseTransmissionMaterial>(
            params.GetSpectrumTexture("reflectance", Constant(0.25f), SpectrumType::Albedo, arena),
            params.GetSpectrumTexture("transmittance", Constant(0.25f), SpectrumType::Albedo,
                                      arena),
            scale));
    }
    if (type == "measured") return make(MeasuredMaterial::Create(params, loc, arena));
    if (type == "subsurface") {
        if (!bssrdfTables) bssrdfTables = arena.New<BSSRDFTableCache>();
        return make(SubsurfaceMaterial::Create(params, *bssrdfTables, arena, diag));
    }
    static constexpr std::string_view kMaterials[] = {
        "diffuse",         "conductor", "dielectric", "thindielectric", "coateddiffuse",
        "coatedconductor", "mix",       "interface",  "none",           "hair",
        "polarizer",       "retarder",  "measured",   "subsurface",     "diffusetransmission"};
    throw SceneError(loc, "unknown material type \"" + type + "\"" + DidYouMean(type, kMaterials),
                     type);
}

}  // namespace kiln
