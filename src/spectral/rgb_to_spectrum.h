// RGB to spectrum upsampling with the sigmoid-polynomial model of Jakob & Hanika (2019), "A
// Low-Dimensional Function Space for Efficient Spectral Upsampling", Computer Graphics Forum
// 38(2): a reflectance s(lambda) = S(c0 lambda^2 + c1 lambda + c2) with the sigmoid
// S(x) = 1/2 + x / (2 sqrt(1 + x^2)), lambda in nm.
//
// The coefficients for a colour space come from a table over RGB in [0,1]^3, generated at
// build time by kiln's own optimiser (gen/rgb2spec_gen.cpp: Levenberg-Marquardt in CIELAB, the
// CIE 1931 observer, the colour space's illuminant) and embedded in the library. The table
// is laid out like pbrt-v4's RGBToSpectrumTable: [3][res][res][res][3] floats indexed by the
// largest component, z (that component, remapped by zNodes = smoothstep(smoothstep(k/(res-1)))),
// then y and x (the other two, in cyclic order, divided by z).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

struct RGB;

// s(lambda) = S(c0 lambda^2 + c1 lambda + c2); dimensionless, in [0, 1].
class RGBSigmoidPolynomial {
  public:
    RGBSigmoidPolynomial() = default;
    RGBSigmoidPolynomial(Float c0, Float c1, Float c2) : c0(c0), c1(c1), c2(c2) {}

    // The polynomial is evaluated in double: its terms nearly cancel (c0 lambda^2 is of order
    // 100 for a value of order 1), which costs float about 1e-5 of absolute accuracy. An RGB
    // says nothing beyond the visible: there the spectrum holds its value at 360 or 830 nm
    // (the fitted quadratic would run to 0 or 1 within a few hundred nm).
    Float operator()(Float lambda_nm) const {
        const double l = std::clamp(lambda_nm, Lambda_min, Lambda_max);
        return Float(Sigmoid((double(c0) * l + double(c1)) * l + double(c2)));
    }
    // Largest value over 360-830 nm.
    Float MaxValue() const;

    Float C0() const { return c0; }
    Float C1() const { return c1; }
    Float C2() const { return c2; }

  private:
    static double Sigmoid(double x) {
        if (std::isinf(x)) return x > 0 ? 1 : 0;
        return 0.5 + x / (2 * std::sqrt(1 + x * x));
    }

    Float c0 = 0, c1 = 0, c2 = 0;
};

class RGBToSpectrumTable {
  public:
    static constexpr int kRes = 64;
    // Floats in one table: kRes z nodes, then 3 x kRes^3 x 3 coefficients (c0, c1, c2).
    static constexpr int kNumFloats = kRes + 3 * kRes * kRes * kRes * 3;

    // data points to the bytes of kNumFloats native floats (z nodes then coefficients), of
    // any alignment; not owned. They are read in place.
    explicit RGBToSpectrumTable(const unsigned char* data)
        : zNodes(data), coeffs(data + kRes * sizeof(float)) {}

    // Sigmoid polynomial of an RGB with components in [0, 1] (clamped), trilinearly
    // interpolated in the table as pbrt-v4 does; greys use the exact closed form.
    RGBSigmoidPolynomial operator()(const RGB& rgb) const;

    // Table of a colour space by its pbrt-v4 name ("srgb", "dci-p3", "rec2020",
    // "aces2065-1"); nullptr if unknown. A colour space whose table was not generated at
    // build time (CMake option KILN_RGB2SPEC_SPACES) gets the sRGB table: see HasOwnTable.
    static const RGBToSpectrumTable* Get(std::string_view colorSpaceName);
    static bool HasOwnTable(std::string_view colorSpaceName);

  private:
    // Float i of an array of native float bytes (memcpy: no alignment or aliasing assumed;
    // compiles to one load)
    static float Load(const unsigned char* bytes, size_t i) {
        float v;
        std::memcpy(&v, bytes + i * sizeof(float), sizeof(float));
        return v;
    }
    float ZNode(int i) const { return Load(zNodes, size_t(i)); }
    float Coeff(int maxc, int z, int y, int x, int c) const {
        return Load(coeffs, size_t((((maxc * kRes + z) * kRes + y) * kRes + x) * 3 + c));
    }

    const unsigned char* zNodes;
    const unsigned char* coeffs;
};

// The embedded raw table of a colour space (the bytes of RGBToSpectrumTable::kNumFloats native
// floats), or nullptr if it was not generated. Defined in the build-time generated
// rgb2spec_tables.cpp (cmake/KilnRGB2Spec.cmake): the bytes are a string literal in the
// executable's read-only data (9.4 MB per space), read in place, so only the pages of the
// colours a scene uses are loaded.
const unsigned char* RGBToSpectrumTableData(std::string_view colorSpaceName);

}  // namespace kiln
