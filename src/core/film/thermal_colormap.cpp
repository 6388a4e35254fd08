#include "core/film/thermal_colormap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/image/color_encoding.h"
#include "spectral/color.h"

namespace kiln {

namespace {

// The palette's stops (sRGB-encoded), evenly spaced in t
constexpr std::array<std::array<float, 3>, 6> kIronStops = {{{0.00f, 0.00f, 0.00f},
                                                             {0.30f, 0.00f, 0.50f},
                                                             {0.75f, 0.05f, 0.35f},
                                                             {0.95f, 0.40f, 0.00f},
                                                             {1.00f, 0.85f, 0.10f},
                                                             {1.00f, 1.00f, 1.00f}}};

// 3 x 5 glyphs, one row of three bits per entry (top row first)
constexpr int kGlyphWidth = 3, kGlyphHeight = 5;
const std::array<int, kGlyphHeight>* Glyph(char c) {
    static const std::array<int, kGlyphHeight> digits[10] = {
        {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
        {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
    static const std::array<int, kGlyphHeight> kelvin = {5, 5, 6, 5, 5}, point = {0, 0, 0, 0, 2};
    if (c >= '0' && c <= '9') return &digits[c - '0'];
    if (c == 'K') return &kelvin;
    if (c == '.') return &point;
    return nullptr;
}

Float Linear(Float v) { return SRGBToLinear(v); }

// Writes text (digits, '.', 'K') in white on black at (x0, y0), glyphs scaled by `scale`
void DrawText(Image& image, const std::string& text, int x0, int y0, int scale) {
    for (size_t i = 0; i < text.size(); ++i) {
        const std::array<int, kGlyphHeight>* g = Glyph(text[i]);
        int gx = x0 + int(i) * (kGlyphWidth + 1) * scale;
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int col = 0; col < kGlyphWidth; ++col) {
                bool on = g && ((*g)[size_t(row)] >> (kGlyphWidth - 1 - col)) & 1;
                for (int dy = 0; dy < scale; ++dy)
                    for (int dx = 0; dx < scale; ++dx) {
                        Point2i p(gx + col * scale + dx, y0 + row * scale + dy);
                        if (p.x < 0 || p.y < 0 || p.x >= image.Resolution().x ||
                            p.y >= image.Resolution().y)
                            continue;
                        for (int c = 0; c < 3; ++c) image.SetChannel(p, c, on ? 1.f : 0.f);
                    }
            }
    }
}

std::string Kelvin(double T) {
    char text[32];
    std::snprintf(text, sizeof(text), T < 100 ? "%.1fK" : "%.0fK", T);
    return text;
}

}  // namespace

RGB IronPalette(Float t) {
    t = std::clamp(t, Float(0), Float(1));
    Float x = t * (kIronStops.size() - 1);
    size_t i = std::min(size_t(x), kIronStops.size() - 2);
    Float f = x - Float(i);
    const auto &a = kIronStops[i], &b = kIronStops[i + 1];
    return RGB((1 - f) * a[0] + f * b[0], (1 - f) * a[1] + f * b[1], (1 - f) * a[2] + f * b[2]);
}

Image ThermalPicture(const Image& thermal, int temperatureChannel,
                     std::optional<TemperatureScale> fixed) {
    const Point2i res = thermal.Resolution();
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    if (fixed) {
        lo = fixed->lo;
        hi = fixed->hi;
    } else {
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                double T = thermal.GetChannel({x, y}, temperatureChannel);
                if (!(T > 0) || !std::isfinite(T)) continue;
                lo = std::min(lo, T);
                hi = std::max(hi, T);
            }
        if (!(hi > 0)) lo = hi = 0;
        if (hi - lo < 1) {
            double mid = (hi + lo) / 2;
            lo = std::max(0.0, mid - 0.5);
            hi = lo + 1;
        }
    }
    // The scale bar: an eighth of the width (at least 24 pixels) with its labels
    const int scale = std::max(1, std::min(res.x, res.y) / 100);
    const int bar = std::max(24, res.x / 8), labelHeight = (kGlyphHeight + 2) * scale;
    Image picture(PixelFormat::Float, Point2i(res.x + bar, res.y), {"R", "G", "B"});
    auto put = [&](Point2i p, RGB srgb) {
        for (int c = 0; c < 3; ++c) picture.SetChannel(p, c, Linear(srgb[c]));
    };
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            double T = thermal.GetChannel({x, y}, temperatureChannel);
            put({x, y}, IronPalette(Float((T - lo) / (hi - lo))));
        }
    // The bar runs from hi (top) to lo (bottom) between the labels
    const int top = labelHeight, bottom = std::max(top + 1, res.y - labelHeight);
    for (int y = 0; y < res.y; ++y)
        for (int x = res.x; x < res.x + bar; ++x) {
            bool inBar = y >= top && y < bottom && x >= res.x + bar / 4;
            Float t = Float(bottom - 1 - y) / Float(std::max(1, bottom - top - 1));
            put({x, y}, inBar ? IronPalette(t) : RGB(0, 0, 0));
        }
    DrawText(picture, Kelvin(hi), res.x + 1, scale, scale);
    DrawText(picture, Kelvin(lo), res.x + 1, res.y - labelHeight + scale, scale);
    return picture;
}

}  // namespace kiln
