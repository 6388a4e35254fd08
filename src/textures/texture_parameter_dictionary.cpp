#include "textures/texture_parameter_dictionary.h"

#include "textures/basic_textures.h"

namespace kiln {

// TextureParameterDictionary Method Definitions
TextureParameterDictionary::TextureParameterDictionary(const ParameterDictionary* dict,
                                                       const NamedTextures* textures)
    : dict(dict), textures(textures) {}

Float TextureParameterDictionary::GetOneFloat(const std::string& name, Float def) const {
    return dict->GetOneFloat(name, def);
}
int TextureParameterDictionary::GetOneInt(const std::string& name, int def) const {
    return dict->GetOneInt(name, def);
}
bool TextureParameterDictionary::GetOneBool(const std::string& name, bool def) const {
    return dict->GetOneBool(name, def);
}
std::string TextureParameterDictionary::GetOneString(const std::string& name,
                                                     const std::string& def) const {
    return dict->GetOneString(name, def);
}
std::string TextureParameterDictionary::GetOneFilename(const std::string& name,
                                                       const std::string& def) const {
    return dict->GetOneFilename(name, def);
}
Point3f TextureParameterDictionary::GetOnePoint3f(const std::string& name, Point3f def) const {
    return dict->GetOnePoint3f(name, def);
}
Vector3f TextureParameterDictionary::GetOneVector3f(const std::string& name, Vector3f def) const {
    return dict->GetOneVector3f(name, def);
}
std::optional<Spectrum> TextureParameterDictionary::GetOneSpectrum(const std::string& name,
                                                                   std::optional<Spectrum> def,
                                                                   SpectrumType type) const {
    return dict->GetOneSpectrum(name, std::move(def), type);
}
std::vector<Float> TextureParameterDictionary::GetFloatArray(const std::string& name) const {
    return dict->GetFloatArray(name);
}
std::vector<std::string> TextureParameterDictionary::GetFilenameArray(
    const std::string& name) const {
    return dict->GetFilenameArray(name);
}
std::vector<std::string> TextureParameterDictionary::GetStringArray(const std::string& name) const {
    return dict->GetStringArray(name);
}
std::string TextureParameterDictionary::TypeOf(const std::string& name) const {
    return dict->TypeOf(name);
}
bool TextureParameterDictionary::Has(const std::string& name) const { return dict->Has(name); }
std::string TextureParameterDictionary::GetSpectrumName(const std::string& name) const {
    return dict->GetSpectrumName(name);
}
FileLoc TextureParameterDictionary::Loc(const std::string& name) const { return dict->Loc(name); }
FileLoc TextureParameterDictionary::Loc(const std::string& name, const FileLoc& absent) const {
    return dict->Loc(name, absent);
}
const RGBColorSpace* TextureParameterDictionary::ColorSpace() const { return dict->ColorSpace(); }

// Float textures
FloatTexture TextureParameterDictionary::GetFloatTexture(const std::string& name, Float def,
                                                         ObjectArena& arena) const {
    if (std::optional<FloatTexture> tex = GetFloatTextureOrNull(name, arena)) return *tex;
    return arena.New<FloatConstantTexture>(def);
}

std::optional<FloatTexture> TextureParameterDictionary::GetFloatTextureOrNull(
    const std::string& name, ObjectArena& arena) const {
    std::string type = dict->TypeOf(name);
    if (type == "texture") {
        std::string texName = dict->GetTexture(name);
        if (textures) {
            auto it = textures->floatTextures.find(texName);
            if (it != textures->floatTextures.end()) return it->second;
        }
        throw SceneError(dict->Loc(name), "no float texture named \"" + texName + "\"", texName);
    }
    if (type == "float")
        return FloatTexture(arena.New<FloatConstantTexture>(dict->GetOneFloat(name, 0)));
    return std::nullopt;
}

// Spectrum textures
SpectrumTexture TextureParameterDictionary::GetSpectrumTexture(const std::string& name,
                                                               std::optional<Spectrum> def,
                                                               SpectrumType type,
                                                               ObjectArena& arena) const {
    if (std::optional<SpectrumTexture> tex = GetSpectrumTextureOrNull(name, type, arena))
        return *tex;
    if (!def) def = Spectrum(ConstantSpectrum(0));
    return arena.New<SpectrumConstantTexture>(*def);
}

std::optional<SpectrumTexture> TextureParameterDictionary::GetSpectrumTextureOrNull(
    const std::string& name, SpectrumType type, ObjectArena& arena) const {
    std::string ptype = dict->TypeOf(name);
    if (ptype == "texture") {
        std::string texName = dict->GetTexture(name);
        if (textures) {
            const auto& named = textures->SpectrumTextures(type);
            auto it = named.find(texName);
            if (it != named.end()) return it->second;
        }
        throw SceneError(dict->Loc(name), "no spectrum texture named \"" + texName + "\"", texName);
    }
    if (ptype == "rgb" || ptype == "spectrum" || ptype == "blackbody") {
        std::optional<Spectrum> s = dict->GetOneSpectrum(name, std::nullopt, type);
        if (s) return SpectrumTexture(arena.New<SpectrumConstantTexture>(*s));
    }
    return std::nullopt;
}

}  // namespace kiln
