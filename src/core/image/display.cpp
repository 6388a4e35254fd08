// Display transform through OpenColorIO (see display.h for the method).
#include "core/image/display.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "base/plugin.h"

namespace OCIO = OCIO_NAMESPACE;

namespace kiln {

namespace {

constexpr const char* kDisplay = "sRGB";

OCIO::ConstConfigRcPtr LoadConfig() {
    std::string path = OCIOConfigPath();
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(path.c_str());
        config->validate();
        return config;
    } catch (const OCIO::Exception& e) {
        throw std::runtime_error(path + ": OpenColorIO: " + e.what());
    }
}

// Applies the colour space conversion from -> to of the config to packed RGB data.
void Apply(const OCIO::ConstConfigRcPtr& config, const char* from, const char* to,
           std::vector<float>& rgb, Point2i res) {
    OCIO::ConstProcessorRcPtr proc = config->getProcessor(from, to);
    OCIO::PackedImageDesc desc(rgb.data(), res.x, res.y, 3);
    proc->getDefaultCPUProcessor()->apply(desc);
}

}  // namespace

std::string OCIOConfigPath() {
    if (const char* env = std::getenv("KILN_OCIO_CONFIG"); env && *env) return env;
    // An installed kiln (its executable or Python module): <prefix>/share/kiln/ocio
    if (std::string prefix = InstallPrefix(); !prefix.empty()) {
        std::filesystem::path installed =
            std::filesystem::path(prefix) / "share" / "kiln" / "ocio" / "config.ocio";
        std::error_code ec;
        if (std::filesystem::exists(installed, ec)) return installed.string();
    }
    return std::string(KILN_OCIO_CONFIG_DIR) + "/config.ocio";
}

std::string UnknownViewMessage(const std::string& view) {
    std::string views;
    for (const std::string& v : DisplayViews()) views += (views.empty() ? "" : ", ") + v;
    return "unknown display view \"" + view + "\" (the views are " + views + ")";
}

std::vector<std::string> DisplayViews() {
    OCIO::ConstConfigRcPtr config = LoadConfig();
    std::vector<std::string> views;
    for (int i = 0; i < config->getNumViews(kDisplay); ++i)
        views.push_back(config->getView(kDisplay, i));
    return views;
}

// Gamut Mapping
RGB MapToDisplayGamut(RGB c, bool scaleAboveOne) {
    if (std::isnan(c.r) || std::isnan(c.g) || std::isnan(c.b)) return RGB(0, 0, 0);
    // Rec.709 luminance weights (the config's luma).
    Float Y = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    if (!(Y > 0)) return RGB(0, 0, 0);
    if (!std::isfinite(Y)) return scaleAboveOne ? RGB(1, 1, 1) : c;
    // Desaturate towards the equal-luminance grey just enough to make every component >= 0.
    Float t = 1;
    for (int i = 0; i < 3; ++i)
        if (c[i] < 0) t = std::min(t, Y / (Y - c[i]));
    if (t < 1) {
        c = RGB(Y, Y, Y) + (c - RGB(Y, Y, Y)) * t;
        for (int i = 0; i < 3; ++i) c[i] = std::max<Float>(0, c[i]);  // rounding only
    }
    if (scaleAboveOne) {
        Float m = std::max({c.r, c.g, c.b});
        if (m > 1) c = c / m;
    }
    return c;
}

RGB FilmicHuePreserving(RGB c, Float toned) {
    Float m = std::max({c.r, c.g, c.b});
    if (!(m > 0)) return RGB(0, 0, 0);
    toned = Clamp(toned, Float(0), Float(1));
    c = c * (toned / m);
    // Path to white: above the tone of scene value 1 (kFilmicKnee), mix with the grey of the
    // same maximum, weight ((toned - knee) / (1 - knee))^3.
    Float w = std::max<Float>(0, (toned - kFilmicKnee) / (1 - kFilmicKnee));
    w = w * w * w;
    return c + (RGB(toned, toned, toned) - c) * w;
}

// Display Image
Image ToDisplayEncodedFloat(const Image& linearRGB, const RGBColorSpace& colorSpace,
                            const DisplaySettings& settings) {
    if (linearRGB.NChannels() < 3)
        throw std::runtime_error("ToDisplayImage: needs three RGB channels");
    OCIO::ConstConfigRcPtr config = LoadConfig();
    bool known = false;
    for (int i = 0; i < config->getNumViews(kDisplay); ++i)
        known = known || settings.view == config->getView(kDisplay, i);
    if (!known) throw std::runtime_error(UnknownViewMessage(settings.view));
    bool raw = settings.view == "Raw";
    bool standard = settings.view == "Standard";

    // Exposure, conversion to linear Rec.709 and gamut mapping.
    Point2i res = linearRGB.Resolution();
    ColorMatrix toRec709 = colorSpace.ConvertTo(RGBColorSpace::sRGB());
    Float scale = std::exp2(settings.exposureEV);
    std::vector<float> buf(size_t(res.x) * res.y * 3);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            RGB c(linearRGB.GetChannel({x, y}, 0), linearRGB.GetChannel({x, y}, 1),
                  linearRGB.GetChannel({x, y}, 2));
            c = Mul(toRec709, c * scale);
            if (!raw) c = MapToDisplayGamut(c, standard);
            size_t o = 3 * (size_t(y) * res.x + x);
            buf[o] = c.r, buf[o + 1] = c.g, buf[o + 2] = c.b;
        }

    try {
        if (settings.view == "Filmic" || settings.view == "Glow") {
            // Tone curve of the max norm (display-linear), hue kept.
            bool glow = settings.view == "Glow";
            size_t n = size_t(res.x) * res.y;
            std::vector<float> norm(3 * n);
            for (size_t i = 0; i < n; ++i) {
                float m = std::max({buf[3 * i], buf[3 * i + 1], buf[3 * i + 2]});
                norm[3 * i] = norm[3 * i + 1] = norm[3 * i + 2] = m;
            }
            Apply(config, OCIO::ROLE_SCENE_LINEAR, glow ? "Glow tone" : "Filmic tone", norm, res);
            for (size_t i = 0; i < n; ++i) {
                RGB c(buf[3 * i], buf[3 * i + 1], buf[3 * i + 2]);
                if (glow) {
                    // Scale the colour to the toned max: chromaticity unchanged.
                    Float m = std::max({c.r, c.g, c.b});
                    c = m > 0 ? c * (std::min<Float>(norm[3 * i], 1) / m) : RGB(0, 0, 0);
                } else {
                    c = FilmicHuePreserving(c, norm[3 * i]);
                }
                buf[3 * i] = c.r, buf[3 * i + 1] = c.g, buf[3 * i + 2] = c.b;
            }
            // Then only the sRGB encoding (the Standard view's colour space).
            Apply(config, OCIO::ROLE_SCENE_LINEAR, "sRGB - Standard", buf, res);
        } else {
            // The OCIO view transform.
            OCIO::ConstProcessorRcPtr proc =
                config->getProcessor(OCIO::ROLE_SCENE_LINEAR, kDisplay, settings.view.c_str(),
                                     OCIO::TRANSFORM_DIR_FORWARD);
            OCIO::PackedImageDesc desc(buf.data(), res.x, res.y, 3);
            proc->getDefaultCPUProcessor()->apply(desc);
        }
    } catch (const OCIO::Exception& e) {
        throw std::runtime_error(OCIOConfigPath() + ": OpenColorIO: " + e.what());
    }

    Image out(PixelFormat::Float, res, {"R", "G", "B"});
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < 3; ++c)
                out.SetChannel({x, y}, c, buf[3 * (size_t(y) * res.x + x) + c]);
    return out;
}

Image ToDisplayImage(const Image& linearRGB, const RGBColorSpace& colorSpace,
                     const DisplaySettings& settings) {
    Image encoded = ToDisplayEncodedFloat(linearRGB, colorSpace, settings);
    // Quantisation of the display-encoded values.
    Point2i res = encoded.Resolution();
    Image out(PixelFormat::U256, res, {"R", "G", "B"}, ColorEncoding::SRGB());
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < 3; ++c) {
                float v = encoded.GetChannel({x, y}, c);
                v = std::isnan(v) ? 0 : Clamp(v, 0.f, 1.f);
                // Store the encoded value: SetChannel encodes linear values.
                out.SetChannel({x, y}, c, SRGBToLinear(v));
            }
    return out;
}

}  // namespace kiln
