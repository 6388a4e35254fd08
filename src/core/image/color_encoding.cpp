// ColorEncoding: parsing and the transfer functions.
#include "core/image/color_encoding.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace kiln {

namespace {

std::string Lower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = char(std::tolower((unsigned char)c));
    return r;
}

}  // namespace

// ColorEncoding Method Definitions
std::optional<ColorEncoding> ColorEncoding::Parse(std::string_view name) {
    std::string n = Lower(name);
    if (n == "linear") return Linear();
    if (n == "srgb") return SRGB();
    if (n.rfind("gamma ", 0) == 0) {
        std::string g = n.substr(6);
        char* end = nullptr;
        double gamma = std::strtod(g.c_str(), &end);
        if (end == g.c_str() || *end != '\0' || !(gamma > 0) || !std::isfinite(gamma))
            return std::nullopt;
        return Gamma(Float(gamma));
    }
    return std::nullopt;
}

std::string ColorEncoding::ToString() const {
    switch (kind) {
        case Kind::Linear:
            return "linear";
        case Kind::SRGB:
            return "sRGB";
        case Kind::Gamma: {
            std::ostringstream s;
            s << "gamma " << gamma;
            return s.str();
        }
    }
    return "unknown";
}

Float ColorEncoding::ToLinear(Float encoded) const {
    Float v = Clamp(encoded, Float(0), Float(1));
    switch (kind) {
        case Kind::Linear:
            return v;
        case Kind::SRGB:
            return SRGBToLinear(v);
        case Kind::Gamma:
            return std::pow(v, gamma);
    }
    return v;
}

Float ColorEncoding::FromLinear(Float linear) const {
    Float v = std::isnan(linear) ? 0 : Clamp(linear, Float(0), Float(1));
    switch (kind) {
        case Kind::Linear:
            return v;
        case Kind::SRGB:
            return LinearToSRGB(v);
        case Kind::Gamma:
            return std::pow(v, 1 / gamma);
    }
    return v;
}

}  // namespace kiln
