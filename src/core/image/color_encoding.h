// Transfer functions of integer-valued image files: how 8- and 16-bit pixel values relate to
// linear light (pbrt-v4's ColorEncoding: "linear", "sRGB", "gamma g").
//
// Encoded values are normalised to [0, 1] (8-bit value / 255, 16-bit value / 65535); linear
// values are relative linear light in [0, 1]. Floating-point images are always linear.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "base/vecmath.h"

namespace kiln {

class ColorEncoding {
  public:
    enum class Kind { Linear, SRGB, Gamma };

    // sRGB is the default, as for pbrt-v4's 8-bit image textures.
    ColorEncoding() = default;
    static ColorEncoding Linear() { return ColorEncoding(Kind::Linear, 1); }
    static ColorEncoding SRGB() { return ColorEncoding(Kind::SRGB, 1); }
    // value = linear^(1/gamma); gamma must be positive and finite.
    static ColorEncoding Gamma(Float gamma) { return ColorEncoding(Kind::Gamma, gamma); }
    // Parses pbrt-v4's names: "linear", "sRGB" (any case) and "gamma <g>" with g > 0.
    static std::optional<ColorEncoding> Parse(std::string_view name);

    Kind GetKind() const { return kind; }
    Float GammaValue() const { return gamma; }
    std::string ToString() const;

    // Encoded value in [0, 1] -> linear value in [0, 1] (monotone; clamps to [0, 1] first).
    Float ToLinear(Float encoded) const;
    // Linear value -> encoded value in [0, 1] (inputs outside [0, 1] are clamped).
    Float FromLinear(Float linear) const;

    bool operator==(const ColorEncoding& o) const { return kind == o.kind && gamma == o.gamma; }

  private:
    ColorEncoding(Kind k, Float g) : kind(k), gamma(g) {}
    Kind kind = Kind::SRGB;
    Float gamma = 1;
};

// The sRGB transfer function (IEC 61966-2-1), on values in [0, 1].
inline Float SRGBToLinear(Float v) {
    if (v <= 0.04045f) return v * (1 / 12.92f);
    return std::pow((v + 0.055f) * (1 / 1.055f), 2.4f);
}
inline Float LinearToSRGB(Float v) {
    if (v <= 0.0031308f) return 12.92f * v;
    return 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

}  // namespace kiln
