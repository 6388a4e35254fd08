#include "core/image/polarization_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/image/color_encoding.h"
#include "spectral/color.h"

namespace kiln {

namespace {

// Stores display-encoded value v (clamped to [0, 1]) in an sRGB 8-bit image.
void SetDisplay(Image& image, Point2i p, int c, Float v) {
    image.SetChannel(p, c, SRGBToLinear(std::isfinite(v) ? Clamp(v, 0.f, 1.f) : 0.f));
}

// Fully saturated colour of hue h in [0, 1) at value v (HSV with S = 1).
RGB Hue(Float h, Float v) {
    Float x = 6 * (h - std::floor(h));
    int sector = std::min(5, int(x));
    Float f = x - sector;
    switch (sector) {
        case 0:
            return RGB(v, v * f, 0);
        case 1:
            return RGB(v * (1 - f), v, 0);
        case 2:
            return RGB(0, v, v * f);
        case 3:
            return RGB(0, v * (1 - f), v);
        case 4:
            return RGB(v * f, 0, v);
        default:
            return RGB(v, 0, v * (1 - f));
    }
}

}  // namespace

std::vector<std::pair<std::string, Image>> PolarizationViews(const Image& stokes,
                                                             const RGBColorSpace& colorSpace,
                                                             Float darkFraction) {
    int channel[4][3];
    const char* names[4][3] = {{"S0.R", "S0.G", "S0.B"},
                               {"S1.R", "S1.G", "S1.B"},
                               {"S2.R", "S2.G", "S2.B"},
                               {"S3.R", "S3.G", "S3.B"}};
    // A thermal film's Stokes layers are single channels of in-band radiance, S0 ... S3
    const bool thermal = stokes.ChannelIndex("S0") >= 0 && stokes.ChannelIndex("S1") >= 0 &&
                         stokes.ChannelIndex("S2") >= 0 && stokes.ChannelIndex("S3") >= 0;
    const char* single[4] = {"S0", "S1", "S2", "S3"};
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) {
            channel[k][c] = stokes.ChannelIndex(thermal ? single[k] : names[k][c]);
            if (channel[k][c] < 0)
                throw std::runtime_error(
                    "the image has no Stokes layers (render with Film \"bool stokes\" true or "
                    "kiln --stokes)");
        }
    Point2i res = stokes.Resolution();
    // Luminance (or in-band radiance) Stokes vectors
    std::vector<Float> S(size_t(res.x) * res.y * 4);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int k = 0; k < 4; ++k) {
                RGB rgb(stokes.GetChannel({x, y}, channel[k][0]),
                        stokes.GetChannel({x, y}, channel[k][1]),
                        stokes.GetChannel({x, y}, channel[k][2]));
                S[(size_t(y) * res.x + x) * 4 + k] = thermal ? rgb.r : colorSpace.ToXYZ(rgb).Y;
            }
    std::vector<Float> intensities;
    for (size_t i = 0; i < S.size(); i += 4)
        if (std::isfinite(S[i])) intensities.push_back(S[i]);
    Float bright = 0;
    if (!intensities.empty()) {
        size_t at = std::min(intensities.size() - 1, size_t(0.99 * intensities.size()));
        std::nth_element(intensities.begin(), intensities.begin() + at, intensities.end());
        bright = intensities[at];
    }
    const Float dark = darkFraction * bright;

    std::vector<std::pair<std::string, Image>> out;
    for (const char* name : {"dolp", "aolp", "dop", "aop", "type", "chirality"})
        out.emplace_back(name,
                         Image(PixelFormat::U256, res, {"R", "G", "B"}, ColorEncoding::SRGB()));
    const RGB cyan(22 / 255.f, 247 / 255.f, 247 / 255.f),
        yellow(252 / 255.f, 251 / 255.f, 10 / 255.f);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            const Float* v = &S[(size_t(y) * res.x + x) * 4];
            RGB colour[6] = {};
            if (v[0] > dark && v[0] > 0) {
                Float s1 = v[1] / v[0], s2 = v[2] / v[0], s3 = v[3] / v[0];
                Float dolp = std::min<Float>(1, std::sqrt(s1 * s1 + s2 * s2));
                Float docp = std::min<Float>(1, std::abs(s3));
                Float dop = std::min<Float>(1, std::sqrt(s1 * s1 + s2 * s2 + s3 * s3));
                Float aolp = 0.5f * std::atan2(s2, s1);  // (-pi/2, pi/2]
                if (aolp < 0) aolp += Pi;
                colour[0] = RGB(dolp, dolp, dolp);
                colour[1] = Hue(aolp / Pi, dolp);
                colour[2] = RGB(dop, 0, 0);
                colour[3] =
                    RGB(std::max<Float>(-s1, 0) + std::max<Float>(s2, 0),
                        std::max<Float>(s1, 0) + std::max<Float>(s2, 0), std::max<Float>(-s2, 0));
                colour[4] = cyan * dolp + yellow * docp;
                colour[5] =
                    RGB(std::max<Float>(s3, 0), std::max<Float>(s3, 0), std::max<Float>(-s3, 0)) *
                    docp;
            }
            for (int i = 0; i < 6; ++i)
                for (int c = 0; c < 3; ++c)
                    SetDisplay(out[size_t(i)].second, {x, y}, c, colour[i][c]);
        }
    return out;
}

}  // namespace kiln
