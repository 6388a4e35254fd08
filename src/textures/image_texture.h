// Image textures (pbrt-v4's "imagemap"): MIP-mapped lookups of an image file through a 2D
// mapping. As in pbrt-v4, t is flipped (st.t = 1 - t) so that t = 0 is the bottom row of the
// image. Values are scale * image (1 - that, clamped at 0, when inverted); 8-bit files are
// decoded with "encoding" (sRGB for PNG, else linear, by default).
#pragma once

#include <map>
#include <mutex>
#include <string>

#include "core/image/color_encoding.h"
#include "spectral/color.h"
#include "textures/texture.h"
#include "textures/texture_mapping.h"

namespace kiln {

class MIPMap;
class Image;

// ImageTextureCache Definition
// MIP maps shared by image textures with the same file and lookup options (filter, maximum
// anisotropy, wrap mode, encoding). Thread-safe. The MIP maps live in the ObjectArena they
// were created in; so do the images.
class ImageTextureCache {
  public:
    const MIPMap* Find(const std::string& key) const;
    void Insert(const std::string& key, const MIPMap* mipmap);
    // Plain images by file name (materials' normal maps).
    const Image* FindImage(const std::string& filename) const;
    void InsertImage(const std::string& filename, const Image* image);

  private:
    mutable std::mutex mutex;
    std::map<std::string, const MIPMap*> mipmaps;
    std::map<std::string, const Image*> images;
};

// ImageTextureBase Definition
// What float and spectrum image textures share.
class ImageTextureBase {
  public:
    ImageTextureBase(TextureMapping2D mapping, const MIPMap* mipmap, Float scale, bool invert)
        : mapping(mapping), mipmap(mipmap), scale(scale), invert(invert) {}
    const MIPMap* GetMIPMap() const { return mipmap; }
    Float Scale() const { return scale; }
    bool Invert() const { return invert; }
    bool UsesFootprint() const { return true; }  // MIP-map filtering

    // Reads "string filename" (SceneError if missing or unreadable), "string filter"
    // (bilinear), "float maxanisotropy" (8), "string wrap" (repeat) and "string encoding"
    // (sRGB for PNG files, else linear); MIP maps are shared through the NamedTextures'
    // imageCache when the dictionary has named textures.
    static const MIPMap* GetOrCreateMIPMap(const TextureParameterDictionary& params,
                                           const FileLoc& loc, ObjectArena& arena);

  protected:
    TextureMapping2D mapping;
    const MIPMap* mipmap;
    Float scale;
    bool invert;
};

// FloatImageTexture Definition
// Dimensionless; RGB images give their channel average (the MIP map's Float lookup).
class FloatImageTexture : public ImageTextureBase {
  public:
    using ImageTextureBase::ImageTextureBase;
    Float Evaluate(const TextureEvalContext& ctx) const;

    // The imagemap parameters above plus "float scale" (1), "bool invert" (false) and the
    // mapping parameters.
    static FloatImageTexture* Create(const TextureParameterDictionary& params,
                                     const Transform& renderFromTexture, const FileLoc& loc,
                                     ObjectArena& arena);
};

// SpectrumImageTexture Definition
// The filtered RGB, turned into a spectrum of `spectrumType` in the colour space
// `colorSpace` (the file's when known, else the scene's; albedo RGB is clamped to [0, 1]).
class SpectrumImageTexture : public ImageTextureBase {
  public:
    SpectrumImageTexture(TextureMapping2D mapping, const MIPMap* mipmap, Float scale, bool invert,
                         const RGBColorSpace* colorSpace, SpectrumType spectrumType)
        : ImageTextureBase(mapping, mipmap, scale, invert),
          colorSpace(colorSpace),
          spectrumType(spectrumType) {}
    SampledSpectrum Evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const;
    // Filtered RGB (after scale and invert) at the point.
    RGB EvaluateRGB(const TextureEvalContext& ctx) const;

    static SpectrumImageTexture* Create(const TextureParameterDictionary& params,
                                        const Transform& renderFromTexture, SpectrumType type,
                                        const FileLoc& loc, ObjectArena& arena);

  private:
    const RGBColorSpace* colorSpace;
    SpectrumType spectrumType;
};

}  // namespace kiln
