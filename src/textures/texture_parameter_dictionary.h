// TextureParameterDictionary: a directive's parameters together with the named textures they
// may refer to (pbrt-v4's TextureParameterDictionary). Parameters that may be textures are
// read as textures: "float name" / "rgb name" / "spectrum name" / "blackbody name" values give
// constant textures, "texture name" refers to a texture declared earlier.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/object_arena.h"
#include "core/parser/parameter_dictionary.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"

namespace kiln {

class TextureParameterDictionary {
  public:
    // Neither pointer is owned; `textures` may be nullptr (no named textures).
    TextureParameterDictionary(const ParameterDictionary* dict, const NamedTextures* textures);

    const ParameterDictionary& Dict() const { return *dict; }
    const NamedTextures* Textures() const { return textures; }

    // Forwarding to the ParameterDictionary.
    Float GetOneFloat(const std::string& name, Float def) const;
    int GetOneInt(const std::string& name, int def) const;
    bool GetOneBool(const std::string& name, bool def) const;
    std::string GetOneString(const std::string& name, const std::string& def) const;
    std::string GetOneFilename(const std::string& name, const std::string& def) const;
    std::vector<std::string> GetFilenameArray(const std::string& name) const;
    Point3f GetOnePoint3f(const std::string& name, Point3f def) const;
    Vector3f GetOneVector3f(const std::string& name, Vector3f def) const;
    std::optional<Spectrum> GetOneSpectrum(const std::string& name, std::optional<Spectrum> def,
                                           SpectrumType type) const;
    std::vector<Float> GetFloatArray(const std::string& name) const;
    std::vector<std::string> GetStringArray(const std::string& name) const;
    std::string TypeOf(const std::string& name) const;
    bool Has(const std::string& name) const;
    std::string GetSpectrumName(const std::string& name) const;
    FileLoc Loc(const std::string& name) const;
    FileLoc Loc(const std::string& name, const FileLoc& absent) const;
    const RGBColorSpace* ColorSpace() const;

    // "float name" gives a constant texture, "texture name" the named float texture (SceneError
    // if there is none), absence a constant texture of value def.
    FloatTexture GetFloatTexture(const std::string& name, Float def, ObjectArena& arena) const;
    std::optional<FloatTexture> GetFloatTextureOrNull(const std::string& name,
                                                      ObjectArena& arena) const;

    // "rgb", "spectrum" or "blackbody" values give a constant texture of that spectrum (as
    // `type` interprets it), "texture name" the named spectrum texture of that type (SceneError
    // if there is none), absence a constant texture of def (nullopt def: constant 0).
    SpectrumTexture GetSpectrumTexture(const std::string& name, std::optional<Spectrum> def,
                                       SpectrumType type, ObjectArena& arena) const;
    std::optional<SpectrumTexture> GetSpectrumTextureOrNull(const std::string& name,
                                                            SpectrumType type,
                                                            ObjectArena& arena) const;

  private:
    const ParameterDictionary* dict;
    const NamedTextures* textures;
};

}  // namespace kiln
