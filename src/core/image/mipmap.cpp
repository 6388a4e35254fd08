// MIPMap: pyramid construction and filtered lookups (pbrt-v4 semantics).
#include "core/image/mipmap.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace kiln {

// FilterFunction Function Definitions
std::optional<FilterFunction> ParseFilter(std::string_view s) {
    std::string n(s);
    for (char& c : n) c = char(std::tolower((unsigned char)c));
    if (n == "point") return FilterFunction::Point;
    if (n == "bilinear") return FilterFunction::Bilinear;
    if (n == "trilinear") return FilterFunction::Trilinear;
    if (n == "ewa") return FilterFunction::EWA;
    return std::nullopt;
}

std::string ToString(FilterFunction f) {
    switch (f) {
        case FilterFunction::Point:
            return "point";
        case FilterFunction::Bilinear:
            return "bilinear";
        case FilterFunction::Trilinear:
            return "trilinear";
        case FilterFunction::EWA:
            return "EWA";
    }
    return "unknown";
}

// MIPMap Method Definitions
MIPMap::MIPMap(Image image, const RGBColorSpace* colorSpace, WrapMode wrapMode,
               MIPMapFilterOptions options)
    : colorSpace(colorSpace ? colorSpace : &RGBColorSpace::sRGB()),
      wrapMode(wrapMode),
      options(options) {
    if (!image) throw std::runtime_error("MIPMap: empty image");
    // Keep only the channels lookups use: R, G, B (and A unless it is 1 everywhere, as
    // pbrt-v4: float lookups then return alpha); else Y; else the first one or three.
    std::vector<std::string> keep;
    const auto& names = image.ChannelNames();
    if (image.ChannelIndex("R") >= 0 && image.ChannelIndex("G") >= 0 &&
        image.ChannelIndex("B") >= 0) {
        keep = {"R", "G", "B"};
        if (int a = image.ChannelIndex("A"); a >= 0) {
            Point2i res = image.Resolution();
            bool opaque = true;
            for (int y = 0; y < res.y && opaque; ++y)
                for (int x = 0; x < res.x && opaque; ++x) opaque = image.GetChannel({x, y}, a) == 1;
            if (!opaque) keep.push_back("A");
        }
    } else if (image.ChannelIndex("Y") >= 0)
        keep = {"Y"};
    else if (image.NChannels() >= 3)
        keep = {names[0], names[1], names[2]};
    else
        keep = {names[0]};
    if (keep != names) image = image.SelectChannels(keep);
    if (image.NChannels() >= 3) rgbChannels[1] = 1, rgbChannels[2] = 2;

    // Build the pyramid: each level box-filters 2x2 texels of the previous one (odd sizes
    // round up; the missing texels come from the wrap mode). Levels are computed in floats and
    // stored in the file's pixel format (8-bit levels in its encoding, as pbrt-v4 stores them):
    // an 8-bit texture's pyramid takes a third more memory, not five times.
    const PixelFormat format = image.Format();
    const ColorEncoding encoding = image.Encoding();
    Image prev = image.ConvertToFormat(PixelFormat::Float);
    pyramid.push_back(std::move(image));
    while (true) {
        Point2i r = prev.Resolution();
        if (r.x == 1 && r.y == 1) break;
        Point2i nr(std::max(1, (r.x + 1) / 2), std::max(1, (r.y + 1) / 2));
        Image next(PixelFormat::Float, nr, prev.ChannelNames());
        int sx = r.x > 1 ? 2 : 1, sy = r.y > 1 ? 2 : 1;
        for (int y = 0; y < nr.y; ++y)
            for (int x = 0; x < nr.x; ++x)
                for (int c = 0; c < prev.NChannels(); ++c) {
                    Float sum = 0;
                    for (int dy = 0; dy < sy; ++dy)
                        for (int dx = 0; dx < sx; ++dx)
                            sum += prev.GetChannel({sx * x + dx, sy * y + dy}, c, wrapMode);
                    next.SetChannel({x, y}, c, sum / (sx * sy));
                }
        pyramid.push_back(next.ConvertToFormat(format, encoding));
        prev = std::move(next);
    }
}

MIPMap* MIPMap::CreateFromFile(const std::string& filename, MIPMapFilterOptions options,
                               WrapMode wrap, ColorEncoding encoding, ObjectArena& arena) {
    ImageMetadata metadata;
    Image image = Image::Read(filename, &metadata, encoding, &arena.Budget());
    // pbrt-v4 reads these formats with stb_image, whose alpha it drops
    if (IsPbrtV4SrgbOnlyFormat(filename) && image.ChannelIndex("A") >= 0) {
        std::vector<std::string> opaque;
        for (const std::string& c : image.ChannelNames())
            if (c != "A") opaque.push_back(c);
        image = image.SelectChannels(opaque);
    }
    if (image.Format() == PixelFormat::U256 && !(image.Encoding() == encoding))
        image = image.ConvertToFormat(PixelFormat::U256, encoding);
    // The pyramid's coarser levels: a third more, in the image's own pixel format
    Point2i res = image.Resolution();
    arena.Budget().Charge(double(res.x) * res.y * image.NChannels() * image.BytesPerSample() / 3,
                          "the MIP map of \"" + filename + "\"");
    return arena.New<MIPMap>(std::move(image), metadata.colorSpace, wrap, options);
}

template <>
Float MIPMap::Texel(int level, Point2i st) const {
    return pyramid[level].GetChannel(st, 0, wrapMode);
}

template <>
RGB MIPMap::Texel(int level, Point2i st) const {
    const Image& im = pyramid[level];
    if (im.NChannels() == 1) {
        Float v = im.GetChannel(st, 0, wrapMode);
        return RGB(v, v, v);
    }
    return RGB(im.GetChannel(st, rgbChannels[0], wrapMode),
               im.GetChannel(st, rgbChannels[1], wrapMode),
               im.GetChannel(st, rgbChannels[2], wrapMode));
}

// Float lookups between texels (bilinear and trilinear filtering) as pbrt-v4's: the one channel,
// the mean of R, G and B, or alpha (point and EWA lookups take the first channel, Texel)
template <>
Float MIPMap::Bilerp(int level, Point2f st) const {
    const Image& im = pyramid[level];
    switch (im.NChannels()) {
        case 3:
            return (im.BilerpChannel(st, 0, wrapMode) + im.BilerpChannel(st, 1, wrapMode) +
                    im.BilerpChannel(st, 2, wrapMode)) /
                   3;
        case 4:
            return im.BilerpChannel(st, 3, wrapMode);
        default:
            return im.BilerpChannel(st, 0, wrapMode);
    }
}

template <>
RGB MIPMap::Bilerp(int level, Point2f st) const {
    const Image& im = pyramid[level];
    if (im.NChannels() == 1) {
        Float v = im.BilerpChannel(st, 0, wrapMode);
        return RGB(v, v, v);
    }
    return RGB(im.BilerpChannel(st, rgbChannels[0], wrapMode),
               im.BilerpChannel(st, rgbChannels[1], wrapMode),
               im.BilerpChannel(st, rgbChannels[2], wrapMode));
}

RGB MIPMap::Bilerp(Point2f st) const { return Bilerp<RGB>(0, st); }
Float MIPMap::BilerpFloat(Point2f st) const { return Bilerp<Float>(0, st); }

namespace {

template <typename T>
T LerpT(Float t, const T& a, const T& b) {
    return a * (1 - t) + b * t;
}

}  // namespace

template <typename T>
T MIPMap::Filter(Point2f st, Vector2f dst0, Vector2f dst1) const {
    // Level whose texel spacing matches a filter width w (in st units): level 0 texels are
    // 1 / res0 wide and each level doubles them.
    Point2i res0 = LevelResolution(0);
    Float maxRes = Float(std::max(res0.x, res0.y));
    if (options.filter != FilterFunction::EWA) {
        Float width =
            2 * std::max({std::abs(dst0.x), std::abs(dst0.y), std::abs(dst1.x), std::abs(dst1.y)});
        Float level = std::log2(std::max<Float>(width * maxRes, 1e-8f));
        if (level >= Levels() - 1) return Texel<T>(Levels() - 1, {0, 0});
        int iLevel = std::max(0, int(std::floor(level)));
        switch (options.filter) {
            case FilterFunction::Point: {
                Point2i r = LevelResolution(iLevel);
                Point2i sti(int(std::round(st.x * r.x - 0.5f)), int(std::round(st.y * r.y - 0.5f)));
                return Texel<T>(iLevel, sti);
            }
            case FilterFunction::Bilinear:
                return Bilerp<T>(iLevel, st);
            default:                                       // Trilinear
                if (iLevel == 0) return Bilerp<T>(0, st);  // (pbrt-v4: no blend below level 1)
                return LerpT(level - iLevel, Bilerp<T>(iLevel, st), Bilerp<T>(iLevel + 1, st));
        }
    }
    // EWA: make dst0 the major axis, clamp the eccentricity, pick the level from the minor.
    if (dst0.x * dst0.x + dst0.y * dst0.y < dst1.x * dst1.x + dst1.y * dst1.y)
        std::swap(dst0, dst1);
    Float longer = std::sqrt(dst0.x * dst0.x + dst0.y * dst0.y);
    Float shorter = std::sqrt(dst1.x * dst1.x + dst1.y * dst1.y);
    if (shorter * options.maxAnisotropy < longer && shorter > 0) {
        Float scale = longer / (shorter * options.maxAnisotropy);
        dst1 = dst1 * scale;
        shorter *= scale;
    }
    if (shorter == 0) return Bilerp<T>(0, st);
    Float lod = std::max<Float>(0, std::log2(shorter * maxRes));
    int ilod = int(std::floor(lod));
    if (ilod >= Levels() - 1) return Texel<T>(Levels() - 1, {0, 0});
    return LerpT(lod - ilod, EWA<T>(ilod, st, dst0, dst1), EWA<T>(ilod + 1, st, dst0, dst1));
}

template <typename T>
T MIPMap::EWA(int level, Point2f st, Vector2f dst0, Vector2f dst1) const {
    if (level >= Levels()) return Texel<T>(Levels() - 1, {0, 0});
    // Ellipse in texel coordinates of the level.
    Point2i r = LevelResolution(level);
    Float s = st.x * r.x - 0.5f, t = st.y * r.y - 0.5f;
    dst0 = Vector2f(dst0.x * r.x, dst0.y * r.y);
    dst1 = Vector2f(dst1.x * r.x, dst1.y * r.y);
    // Implicit ellipse A s^2 + B s t + C t^2 < 1 (Heckbert 1989), widened by one texel.
    Float A = dst0.y * dst0.y + dst1.y * dst1.y + 1;
    Float B = -2 * (dst0.x * dst0.y + dst1.x * dst1.y);
    Float C = dst0.x * dst0.x + dst1.x * dst1.x + 1;
    Float invF = 1 / (A * C - B * B * 0.25f);
    A *= invF, B *= invF, C *= invF;
    Float det = -B * B + 4 * A * C, invDet = 1 / det;
    Float uSqrt = SafeSqrt(det * C), vSqrt = SafeSqrt(A * det);
    int s0 = int(std::ceil(s - 2 * invDet * uSqrt)), s1 = int(std::floor(s + 2 * invDet * uSqrt));
    int t0 = int(std::ceil(t - 2 * invDet * vSqrt)), t1 = int(std::floor(t + 2 * invDet * vSqrt));
    // Gaussian weights exp(-alpha r^2) - exp(-alpha), alpha = 2 (pbrt-v4's MIPFilterLUT).
    constexpr Float alpha = 2;
    const Float tail = std::exp(-alpha);
    T sum{};
    Float sumWts = 0;
    for (int it = t0; it <= t1; ++it) {
        Float tt = it - t;
        for (int is = s0; is <= s1; ++is) {
            Float ss = is - s;
            Float r2 = A * ss * ss + B * ss * tt + C * tt * tt;
            if (r2 < 1) {
                Float w = std::exp(-alpha * r2) - tail;
                sum = sum + Texel<T>(level, {is, it}) * w;
                sumWts += w;
            }
        }
    }
    if (sumWts <= 0) return Bilerp<T>(level, st);
    return sum / sumWts;
}

template Float MIPMap::Filter<Float>(Point2f, Vector2f, Vector2f) const;
template RGB MIPMap::Filter<RGB>(Point2f, Vector2f, Vector2f) const;

}  // namespace kiln
