// Colour: tristimulus values (CIE XYZ), RGB, and RGB colour spaces defined by primaries and an
// illuminant (pbrt-v4's RGBColorSpace).
//
// XYZ and RGB are linear and carry the unit of what they describe (radiance-weighted for
// emission, dimensionless for reflectance); Y is luminance relative to the convention of
// SpectrumToXYZ (a spectrum of constant 1 has Y = 1).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "base/vecmath.h"
#include "spectral/rgb_to_spectrum.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/spectrum.h"

namespace kiln {

// Linear RGB in some colour space.
struct RGB {
    Float r = 0, g = 0, b = 0;
    RGB() = default;
    RGB(Float r, Float g, Float b) : r(r), g(g), b(b) {}

    Float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    Float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
    RGB operator+(const RGB& o) const { return {r + o.r, g + o.g, b + o.b}; }
    RGB operator-(const RGB& o) const { return {r - o.r, g - o.g, b - o.b}; }
    RGB operator*(const RGB& o) const { return {r * o.r, g * o.g, b * o.b}; }
    RGB operator*(Float s) const { return {r * s, g * s, b * s}; }
    RGB operator/(Float s) const { return {r / s, g / s, b / s}; }
    bool operator==(const RGB& o) const { return r == o.r && g == o.g && b == o.b; }
    Float Average() const { return (r + g + b) / 3; }
};
inline RGB operator*(Float s, const RGB& c) { return c * s; }

// CIE 1931 XYZ tristimulus values.
struct XYZ {
    Float X = 0, Y = 0, Z = 0;
    XYZ() = default;
    XYZ(Float X, Float Y, Float Z) : X(X), Y(Y), Z(Z) {}

    Float operator[](int i) const { return i == 0 ? X : (i == 1 ? Y : Z); }
    XYZ operator+(const XYZ& o) const { return {X + o.X, Y + o.Y, Z + o.Z}; }
    XYZ operator*(Float s) const { return {X * s, Y * s, Z * s}; }
    XYZ operator/(Float s) const { return {X / s, Y / s, Z / s}; }

    // Chromaticity (x, y) = (X, Y) / (X + Y + Z); (0, 0) for black.
    Point2f xy() const {
        Float sum = X + Y + Z;
        return sum != 0 ? Point2f(X / sum, Y / sum) : Point2f(0, 0);
    }
    // From chromaticity xy and luminance Y; black if y = 0.
    static XYZ FromxyY(Point2f xy, Float Y = 1) {
        if (xy.y == 0) return {0, 0, 0};
        return {xy.x * Y / xy.y, Y, (1 - xy.x - xy.y) * Y / xy.y};
    }
};

// Row-major 3x3 matrix for colour conversions.
using ColorMatrix = std::array<std::array<Float, 3>, 3>;

// XYZ of the path's spectral samples: the Monte Carlo estimate average_i(s_i cmf(l_i) / p(l_i))
// divided by CIE_Y_integral (pbrt-v4's SampledSpectrum::ToXYZ).
XYZ SpectrumToXYZ(const SampledSpectrum& s, const SampledWavelengths& lambda);

// An RGB colour space: primaries, white and illuminant, the matrices to and from XYZ, and the
// RGB-to-spectrum table. The white (illuminant) maps to RGB (1, 1, 1).
class RGBColorSpace {
  public:
    // Primaries r, g, b as CIE xy; illuminant is the white's SPD (pbrt normalises it to Y = 1).
    RGBColorSpace(std::string name, Point2f r, Point2f g, Point2f b, const Spectrum& illuminant,
                  const RGBToSpectrumTable* table);

    RGB ToRGB(const XYZ& xyz) const;
    XYZ ToXYZ(const RGB& rgb) const;
    // Sigmoid polynomial of an RGB in [0,1]^3.
    RGBSigmoidPolynomial ToRGBCoeffs(const RGB& rgb) const;
    // Matrix taking RGB in this space to RGB in another.
    ColorMatrix ConvertTo(const RGBColorSpace& to) const;

    const std::string& Name() const { return name; }
    const DenselySampledSpectrum& Illuminant() const { return illuminant; }
    const ColorMatrix& XYZFromRGB() const { return xyzFromRGB; }
    const ColorMatrix& RGBFromXYZ() const { return rgbFromXYZ; }
    // Whether the RGB-to-spectrum table is this space's own (else the sRGB one is used).
    bool HasOwnSpectrumTable() const;

    // pbrt-v4's names, lower-case: "srgb", "dci-p3", "rec2020", "aces2065-1"; nullptr if
    // unknown. The spaces are built once and live for the program's life.
    static const RGBColorSpace* GetNamed(std::string_view name);
    static std::vector<std::string_view> Names();
    static const RGBColorSpace& sRGB();  // the default
    static const RGBColorSpace& DCI_P3();
    static const RGBColorSpace& Rec2020();
    static const RGBColorSpace& ACES2065_1();

    Point2f r, g, b, w;  // chromaticities of primaries and white

  private:
    std::string name;
    DenselySampledSpectrum illuminant;
    ColorMatrix xyzFromRGB, rgbFromXYZ;
    const RGBToSpectrumTable* table;
};

// Matrix-vector products.
RGB Mul(const ColorMatrix& m, const RGB& v);
// The product a b of two colour matrices (b applied first).
ColorMatrix Mul(const ColorMatrix& a, const ColorMatrix& b);
XYZ Mul(const ColorMatrix& m, const XYZ& v);

}  // namespace kiln
