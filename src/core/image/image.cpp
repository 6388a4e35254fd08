// Image: pixel storage, wrap modes and lookups (file input/output is in image_io.cpp).
#include "core/image/image.h"

#include <Imath/half.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace kiln {

// WrapMode Function Definitions
std::optional<WrapMode> ParseWrapMode(std::string_view s) {
    std::string n(s);
    for (char& c : n) c = char(std::tolower((unsigned char)c));
    if (n == "repeat") return WrapMode::Repeat;
    if (n == "clamp") return WrapMode::Clamp;
    if (n == "black") return WrapMode::Black;
    if (n == "octahedralsphere") return WrapMode::OctahedralSphere;
    return std::nullopt;
}

std::string ToString(WrapMode mode) {
    switch (mode) {
        case WrapMode::Repeat:
            return "repeat";
        case WrapMode::Clamp:
            return "clamp";
        case WrapMode::Black:
            return "black";
        case WrapMode::OctahedralSphere:
            return "octahedralsphere";
    }
    return "unknown";
}

std::string ToString(PixelFormat format) {
    switch (format) {
        case PixelFormat::U256:
            return "U256";
        case PixelFormat::Half:
            return "Half";
        case PixelFormat::Float:
            return "Float";
    }
    return "unknown";
}

bool RemapPixelCoords(Point2i* pp, Point2i res, WrapMode wrapMode) {
    Point2i& p = *pp;
    if (wrapMode == WrapMode::OctahedralSphere) {
        // Mirror across the edge: the octahedral map's border folds onto itself. Pixel -1 maps
        // to pixel 0 (pbrt-v4 maps it to 1 on the low side but to res - 1 on the high side;
        // kiln mirrors both sides the same way, which is what the sphere's seam needs).
        if (p.x < 0) {
            p.x = -p.x - 1;
            p.y = res.y - 1 - p.y;
        } else if (p.x >= res.x) {
            p.x = 2 * res.x - 1 - p.x;
            p.y = res.y - 1 - p.y;
        }
        if (p.y < 0) {
            p.x = res.x - 1 - p.x;
            p.y = -p.y - 1;
        } else if (p.y >= res.y) {
            p.x = res.x - 1 - p.x;
            p.y = 2 * res.y - 1 - p.y;
        }
        // Far outside (more than one image away) or tiny images: clamp.
        p.x = Clamp(p.x, 0, res.x - 1);
        p.y = Clamp(p.y, 0, res.y - 1);
        return true;
    }
    for (int c = 0; c < 2; ++c) {
        if (p[c] >= 0 && p[c] < res[c]) continue;
        switch (wrapMode) {
            case WrapMode::Repeat:
                p[c] = ((p[c] % res[c]) + res[c]) % res[c];
                break;
            case WrapMode::Clamp:
                p[c] = Clamp(p[c], 0, res[c] - 1);
                break;
            case WrapMode::Black:
                return false;
            default:
                break;
        }
    }
    return true;
}

std::string FileExtension(std::string_view path) {
    size_t slash = path.find_last_of('/');
    size_t dot = path.find_last_of('.');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash))
        return "";
    std::string ext(path.substr(dot + 1));
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    return ext;
}

namespace {

// Decoded 8-bit sRGB values (an immutable table built once; texture lookups are hot).
Float SRGB8ToLinear(uint8_t v) {
    static const std::array<Float, 256> table = [] {
        std::array<Float, 256> t;
        for (int i = 0; i < 256; ++i) t[i] = SRGBToLinear(i / 255.f);
        return t;
    }();
    return table[v];
}

}  // namespace

// Image Method Definitions
Image::Image(PixelFormat format, Point2i resolution, std::vector<std::string> channelNames,
             ColorEncoding encoding)
    : format(format),
      resolution(resolution),
      channelNames(std::move(channelNames)),
      encoding(encoding) {
    if (resolution.x < 0 || resolution.y < 0)
        throw std::invalid_argument("Image: negative resolution");
    size_t n = size_t(resolution.x) * size_t(resolution.y) * this->channelNames.size();
    switch (format) {
        case PixelFormat::U256:
            p8.assign(n, 0);
            break;
        case PixelFormat::Half:
            p16.assign(n, 0);
            break;
        case PixelFormat::Float:
            p32.assign(n, 0.f);
            break;
    }
}

int Image::ChannelIndex(std::string_view name) const {
    for (size_t i = 0; i < channelNames.size(); ++i)
        if (channelNames[i] == name) return int(i);
    return -1;
}

Float Image::GetChannel(Point2i p, int c, WrapMode wrap) const {
    if (!RemapPixelCoords(&p, resolution, wrap)) return 0;
    size_t i = PixelOffset(p) + c;
    switch (format) {
        case PixelFormat::U256:
            if (encoding.GetKind() == ColorEncoding::Kind::SRGB) return SRGB8ToLinear(p8[i]);
            return encoding.ToLinear(p8[i] * (1 / 255.f));
        case PixelFormat::Half: {
            Imath::half h;
            h.setBits(p16[i]);
            return float(h);
        }
        case PixelFormat::Float:
            return p32[i];
    }
    return 0;
}

void Image::SetChannel(Point2i p, int c, Float value) {
    if (std::isnan(value)) value = 0;
    size_t i = PixelOffset(p) + c;
    switch (format) {
        case PixelFormat::U256:
            p8[i] = uint8_t(std::lround(encoding.FromLinear(value) * 255));
            break;
        case PixelFormat::Half:
            p16[i] = Imath::half(value).bits();
            break;
        case PixelFormat::Float:
            p32[i] = value;
            break;
    }
}

Float Image::BilerpChannel(Point2f st, int c, WrapMode wrap) const {
    Float x = st.x * resolution.x - 0.5f, y = st.y * resolution.y - 0.5f;
    int xi = int(std::floor(x)), yi = int(std::floor(y));
    Float dx = x - xi, dy = y - yi;
    return (1 - dx) * (1 - dy) * GetChannel({xi, yi}, c, wrap) +
           dx * (1 - dy) * GetChannel({xi + 1, yi}, c, wrap) +
           (1 - dx) * dy * GetChannel({xi, yi + 1}, c, wrap) +
           dx * dy * GetChannel({xi + 1, yi + 1}, c, wrap);
}

Image Image::SelectChannels(const std::vector<std::string>& names) const {
    std::vector<int> idx;
    for (const std::string& n : names) {
        int i = ChannelIndex(n);
        if (i < 0) throw std::runtime_error("Image::SelectChannels: no channel '" + n + "'");
        idx.push_back(i);
    }
    Image r(format, resolution, names, encoding);
    int nIn = NChannels(), nOut = int(names.size());
    size_t nPixels = size_t(resolution.x) * size_t(resolution.y);
    for (size_t p = 0; p < nPixels; ++p)
        for (int c = 0; c < nOut; ++c) {
            size_t from = p * nIn + idx[c], to = p * nOut + c;
            if (format == PixelFormat::U256) r.p8[to] = p8[from];
            if (format == PixelFormat::Half) r.p16[to] = p16[from];
            if (format == PixelFormat::Float) r.p32[to] = p32[from];
        }
    return r;
}

Image Image::Crop(const Bounds2i& b) const {
    Point2i res(b.pMax.x - b.pMin.x, b.pMax.y - b.pMin.y);
    Image r(format, res, channelNames, encoding);
    int nc = NChannels();
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            size_t from = PixelOffset({x + b.pMin.x, y + b.pMin.y}), to = r.PixelOffset({x, y});
            for (int c = 0; c < nc; ++c) {
                if (format == PixelFormat::U256) r.p8[to + c] = p8[from + c];
                if (format == PixelFormat::Half) r.p16[to + c] = p16[from + c];
                if (format == PixelFormat::Float) r.p32[to + c] = p32[from + c];
            }
        }
    return r;
}

Image Image::ConvertToFormat(PixelFormat to, ColorEncoding enc) const {
    if (to == format && (to != PixelFormat::U256 || enc == encoding)) return *this;
    Image r(to, resolution, channelNames, to == PixelFormat::U256 ? enc : ColorEncoding::Linear());
    for (int y = 0; y < resolution.y; ++y)
        for (int x = 0; x < resolution.x; ++x)
            for (int c = 0; c < NChannels(); ++c) r.SetChannel({x, y}, c, GetChannel({x, y}, c));
    return r;
}

Float Image::Average(int c) const {
    if (!*this) return 0;
    double sum = 0;
    for (int y = 0; y < resolution.y; ++y)
        for (int x = 0; x < resolution.x; ++x) sum += GetChannel({x, y}, c);
    return Float(sum / (double(resolution.x) * resolution.y));
}

std::vector<Float> Image::GetSamplingDistribution(const std::function<Float(Point2f)>& dxdA,
                                                  const Bounds2f& domain) const {
    std::vector<Float> dist(size_t(resolution.x) * size_t(resolution.y));
    int nc = std::max(1, NChannels());
    for (int y = 0; y < resolution.y; ++y)
        for (int x = 0; x < resolution.x; ++x) {
            Float value = 0;
            for (int c = 0; c < NChannels(); ++c) value += std::abs(GetChannel({x, y}, c));
            value /= nc;
            // The Jacobian is taken as constant over the pixel: evaluate it at the centre.
            Point2f u((x + 0.5f) / resolution.x, (y + 0.5f) / resolution.y);
            Point2f p(Lerp(u.x, domain.pMin.x, domain.pMax.x),
                      Lerp(u.y, domain.pMin.y, domain.pMax.y));
            dist[size_t(y) * resolution.x + x] = value * dxdA(p);
        }
    return dist;
}

void Image::FlipY() {
    size_t row = size_t(resolution.x) * NChannels();
    for (int y = 0; y < resolution.y / 2; ++y) {
        size_t a = row * y, b = row * (resolution.y - 1 - y);
        for (size_t i = 0; i < row; ++i) {
            if (format == PixelFormat::U256) std::swap(p8[a + i], p8[b + i]);
            if (format == PixelFormat::Half) std::swap(p16[a + i], p16[b + i]);
            if (format == PixelFormat::Float) std::swap(p32[a + i], p32[b + i]);
        }
    }
}

}  // namespace kiln
