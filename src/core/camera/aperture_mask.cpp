#include "core/camera/aperture_mask.h"

#include <cmath>
#include <vector>

namespace kiln {

namespace {

constexpr int kBuiltinResolution = 256;

// A mask with f evaluated at each pixel centre, p in [-1,1]^2, row y at p.y = -1 + 2 (y + 1/2)
// / resolution.
template <typename F>
Image Rasterize(F f) {
    Image mask(PixelFormat::Float, Point2i(kBuiltinResolution, kBuiltinResolution), {"Y"});
    for (int y = 0; y < kBuiltinResolution; ++y)
        for (int x = 0; x < kBuiltinResolution; ++x) {
            Point2f p(-1 + 2 * (x + 0.5f) / kBuiltinResolution,
                      -1 + 2 * (y + 0.5f) / kBuiltinResolution);
            mask.SetChannel({x, y}, 0, f(p));
        }
    return mask;
}

// Whether p lies inside the simple polygon (even-odd rule).
bool InsidePolygon(const std::vector<Point2f>& v, Point2f p) {
    bool inside = false;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        if ((v[i].y > p.y) != (v[j].y > p.y)) {
            Float xCross = v[j].x + (p.y - v[j].y) / (v[i].y - v[j].y) * (v[i].x - v[j].x);
            if (p.x < xCross) inside = !inside;
        }
    }
    return inside;
}

}  // namespace

std::optional<Image> BuiltinApertureMask(const std::string& name) {
    if (name == "gaussian")
        return Rasterize([](Point2f p) {
            return std::max<Float>(0, std::exp(-(Sqr(p.x) + Sqr(p.y))) - std::exp(-1.f));
        });
    if (name == "square")
        return Rasterize([](Point2f p) {
            return std::abs(p.x) < 0.5f && std::abs(p.y) < 0.5f ? Float(1) : Float(0);
        });
    std::vector<Point2f> polygon;
    if (name == "pentagon") {
        for (int k = 0; k < 5; ++k) {
            Float phi = Radians(90.f - 72.f * k);
            polygon.push_back(Point2f(0.8f * std::cos(phi), 0.8f * std::sin(phi)));
        }
    } else if (name == "star") {
        Float inner = std::cos(Radians(72.f)) / std::cos(Radians(36.f));
        for (int i = 0; i < 10; ++i) {
            Float r = (i & 1) ? 1 : inner, phi = Pi * i / 5;
            polygon.push_back(Point2f(r * std::cos(phi), r * std::sin(phi)));
        }
    } else
        return std::nullopt;
    return Rasterize([&](Point2f p) { return InsidePolygon(polygon, p) ? Float(1) : Float(0); });
}

std::optional<Image> ApertureMaskFromImage(const Image& image, std::string* error) {
    Point2i res = image.Resolution();
    Image mask(PixelFormat::Float, res, {"Y"});
    int r = image.ChannelIndex("R"), g = image.ChannelIndex("G"), b = image.ChannelIndex("B");
    if (image.NChannels() > 1 && (r < 0 || g < 0 || b < 0)) {
        if (error) *error = "aperture image has several channels but not R, G and B";
        return std::nullopt;
    }
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            mask.SetChannel({x, y}, 0,
                            image.NChannels() == 1
                                ? image.GetChannel({x, y}, 0)
                                : (image.GetChannel({x, y}, r) + image.GetChannel({x, y}, g) +
                                   image.GetChannel({x, y}, b)) /
                                      3);
    return mask;
}

bool NormalizeApertureMask(Image* mask) {
    Point2i res = mask->Resolution();
    double sum = 0;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) sum += mask->GetChannel({x, y}, 0);
    double mean = sum / (double(res.x) * res.y);
    if (!(mean > 0) || !std::isfinite(mean)) return false;
    mask->FlipY();
    Float scale = Float(PiOver4 / mean);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            mask->SetChannel({x, y}, 0, mask->GetChannel({x, y}, 0) * scale);
    return true;
}

}  // namespace kiln
