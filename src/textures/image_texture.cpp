#include "textures/image_texture.h"

#include <sstream>
#include <stdexcept>

#include "core/image/image.h"
#include "textures/texture_parameter_dictionary.h"

#include "core/image/mipmap.h"

namespace kiln {

// ImageTextureCache Method Definitions
const MIPMap* ImageTextureCache::Find(const std::string& key) const {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = mipmaps.find(key);
    return it == mipmaps.end() ? nullptr : it->second;
}

void ImageTextureCache::Insert(const std::string& key, const MIPMap* mipmap) {
    std::lock_guard<std::mutex> lock(mutex);
    mipmaps.emplace(key, mipmap);
}

const Image* ImageTextureCache::FindImage(const std::string& filename) const {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = images.find(filename);
    return it == images.end() ? nullptr : it->second;
}

void ImageTextureCache::InsertImage(const std::string& filename, const Image* image) {
    std::lock_guard<std::mutex> lock(mutex);
    images.emplace(filename, image);
}

// ImageTextureBase Method Definitions
const MIPMap* ImageTextureBase::GetOrCreateMIPMap(const TextureParameterDictionary& params,
                                                  const FileLoc& loc, ObjectArena& arena) {
    std::string filename = params.GetOneFilename("filename", "");
    if (filename.empty()) throw SceneError(loc, "\"filename\" must be given for imagemap");
    auto at = [&](const char* name) { return params.Has(name) ? params.Loc(name) : loc; };

    Float maxAniso = params.GetOneFloat("maxanisotropy", 8);
    std::string filterName = params.GetOneString("filter", "bilinear");
    std::string wrapName = params.GetOneString("wrap", "repeat");
    std::optional<WrapMode> wrap = ParseWrapMode(wrapName);
    if (!wrap) throw SceneError(at("wrap"), "unknown wrap mode \"" + wrapName + "\"", wrapName);
    std::string defEncoding = FileExtension(filename) == "png" ? "sRGB" : "linear";
    std::string encodingName = params.GetOneString("encoding", defEncoding);
    std::optional<ColorEncoding> encoding = ColorEncoding::Parse(encodingName);
    if (!encoding)
        throw SceneError(at("encoding"), "unknown color encoding \"" + encodingName + "\"",
                         encodingName);

    auto filter = ParseFilter(filterName);
    if (!filter)
        throw SceneError(at("filter"), "unknown image filter \"" + filterName + "\"", filterName);
    MIPMapFilterOptions options;
    options.filter = *filter;
    options.maxAnisotropy = maxAniso;

    std::ostringstream key;
    key << filename << '\n'
        << filterName << '\n'
        << maxAniso << '\n'
        << ToString(*wrap) << '\n'
        << encoding->ToString();
    ImageTextureCache* cache = params.Textures() ? params.Textures()->imageCache.get() : nullptr;
    if (cache)
        if (const MIPMap* m = cache->Find(key.str())) return m;
    const MIPMap* mipmap = nullptr;
    try {
        mipmap = MIPMap::CreateFromFile(filename, options, *wrap, *encoding, arena);
    } catch (const std::exception& e) {
        throw SceneError(at("filename"), std::string("cannot read image texture: ") + e.what(),
                         filename);
    }
    if (!mipmap) throw SceneError(at("filename"), "cannot read image texture", filename);
    if (cache) cache->Insert(key.str(), mipmap);
    return mipmap;
}

// FloatImageTexture Method Definitions
Float FloatImageTexture::Evaluate(const TextureEvalContext& ctx) const {
    TexCoord2D c = mapping.Map(ctx);
    // pbrt-v4: t = 0 is the bottom of the image
    c.st.y = 1 - c.st.y;
    Float v =
        scale * mipmap->Filter<Float>(c.st, Vector2f(c.dsdx, -c.dtdx), Vector2f(c.dsdy, -c.dtdy));
    return invert ? std::max<Float>(0, 1 - v) : v;
}

FloatImageTexture* FloatImageTexture::Create(const TextureParameterDictionary& params,
                                             const Transform& renderFromTexture, const FileLoc& loc,
                                             ObjectArena& arena) {
    TextureMapping2D mapping = TextureMapping2D::Create(params, renderFromTexture, loc);
    Float scale = params.GetOneFloat("scale", 1);
    bool invert = params.GetOneBool("invert", false);
    const MIPMap* mipmap = GetOrCreateMIPMap(params, loc, arena);
    return arena.New<FloatImageTexture>(mapping, mipmap, scale, invert);
}

// SpectrumImageTexture Method Definitions
RGB SpectrumImageTexture::EvaluateRGB(const TextureEvalContext& ctx) const {
    TexCoord2D c = mapping.Map(ctx);
    c.st.y = 1 - c.st.y;
    RGB rgb =
        scale * mipmap->Filter<RGB>(c.st, Vector2f(c.dsdx, -c.dtdx), Vector2f(c.dsdy, -c.dtdy));
    if (invert) rgb = RGB(1, 1, 1) - rgb;
    return RGB(std::max<Float>(0, rgb.r), std::max<Float>(0, rgb.g), std::max<Float>(0, rgb.b));
}

SampledSpectrum SpectrumImageTexture::Evaluate(const TextureEvalContext& ctx,
                                               const SampledWavelengths& lambda) const {
    RGB rgb = EvaluateRGB(ctx);
    // Grey pixels need no upsampling
    if (rgb.r == rgb.g && rgb.g == rgb.b && spectrumType != SpectrumType::Illuminant)
        return SampledSpectrum(spectrumType == SpectrumType::Albedo ? std::min<Float>(rgb.r, 1)
                                                                    : rgb.r);
    switch (spectrumType) {
        case SpectrumType::Albedo:
            return RGBAlbedoSpectrum(*colorSpace,
                                     RGB(std::min<Float>(rgb.r, 1), std::min<Float>(rgb.g, 1),
                                         std::min<Float>(rgb.b, 1)))
                .Sample(lambda);
        case SpectrumType::Unbounded:
            return RGBUnboundedSpectrum(*colorSpace, rgb).Sample(lambda);
        default:
            return RGBIlluminantSpectrum(*colorSpace, rgb).Sample(lambda);
    }
}

SpectrumImageTexture* SpectrumImageTexture::Create(const TextureParameterDictionary& params,
                                                   const Transform& renderFromTexture,
                                                   SpectrumType type, const FileLoc& loc,
                                                   ObjectArena& arena) {
    TextureMapping2D mapping = TextureMapping2D::Create(params, renderFromTexture, loc);
    Float scale = params.GetOneFloat("scale", 1);
    bool invert = params.GetOneBool("invert", false);
    const MIPMap* mipmap = GetOrCreateMIPMap(params, loc, arena);
    // The file's colour space when known, else the scene's
    const RGBColorSpace* cs = mipmap->GetRGBColorSpace();
    if (!cs) cs = params.ColorSpace();
    if (!cs) cs = &RGBColorSpace::sRGB();
    return arena.New<SpectrumImageTexture>(mapping, mipmap, scale, invert, cs, type);
}

}  // namespace kiln
