// Colour spaces and the conversion of spectral samples to XYZ.
#include "spectral/color.h"

#include <memory>
#include <stdexcept>

#include "spectral/cie.h"
#include "spectral/color_space_defs.h"
#include "spectral/named_spectra.h"

namespace kiln {

namespace {

using Matrix3d = std::array<std::array<double, 3>, 3>;

// The product a b of 3x3 matrices (double for the fits below, Float for ColorMatrix)
template <typename T>
std::array<std::array<T, 3>, 3> Multiply(const std::array<std::array<T, 3>, 3>& a,
                                         const std::array<std::array<T, 3>, 3>& b) {
    std::array<std::array<T, 3>, 3> r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

Matrix3d Inverse(const Matrix3d& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (det == 0) throw std::invalid_argument("RGBColorSpace: singular primaries");
    Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // Cofactor of (j, i) over the determinant
            int a0 = (j + 1) % 3, a1 = (j + 2) % 3, b0 = (i + 1) % 3, b1 = (i + 2) % 3;
            r[i][j] = (m[a0][b0] * m[a1][b1] - m[a0][b1] * m[a1][b0]) / det;
        }
    return r;
}

ColorMatrix ToFloat(const Matrix3d& m) {
    ColorMatrix r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = Float(m[i][j]);
    return r;
}

}  // namespace

RGB Mul(const ColorMatrix& m, const RGB& v) {
    return {m[0][0] * v.r + m[0][1] * v.g + m[0][2] * v.b,
            m[1][0] * v.r + m[1][1] * v.g + m[1][2] * v.b,
            m[2][0] * v.r + m[2][1] * v.g + m[2][2] * v.b};
}

ColorMatrix Mul(const ColorMatrix& a, const ColorMatrix& b) { return Multiply(a, b); }

XYZ Mul(const ColorMatrix& m, const XYZ& v) {
    return {m[0][0] * v.X + m[0][1] * v.Y + m[0][2] * v.Z,
            m[1][0] * v.X + m[1][1] * v.Y + m[1][2] * v.Z,
            m[2][0] * v.X + m[2][1] * v.Y + m[2][2] * v.Z};
}

XYZ SpectrumToXYZ(const SampledSpectrum& s, const SampledWavelengths& lambda) {
    SampledSpectrum X, Y, Z;
    for (int i = 0; i < NSpectrumSamples; ++i) {
        X[i] = CIE_X(lambda[i]);
        Y[i] = CIE_Y(lambda[i]);
        Z[i] = CIE_Z(lambda[i]);
    }
    SampledSpectrum pdf = lambda.PDF();
    return XYZ(SafeDiv(X * s, pdf).Average(), SafeDiv(Y * s, pdf).Average(),
               SafeDiv(Z * s, pdf).Average()) /
           CIE_Y_integral;
}

// RGBColorSpace
RGBColorSpace::RGBColorSpace(std::string name, Point2f r, Point2f g, Point2f b,
                             const Spectrum& illum, const RGBToSpectrumTable* table)
    : r(r), g(g), b(b), name(std::move(name)), illuminant(illum), table(table) {
    // White point from the illuminant; primaries at unit luminance
    XYZ W = SpectrumToXYZ(illum);
    w = W.xy();
    XYZ R = XYZ::FromxyY(r), G = XYZ::FromxyY(g), B = XYZ::FromxyY(b);

    // Scale the primaries so that they sum to the white (in double precision)
    Matrix3d rgb = {{{R.X, G.X, B.X}, {R.Y, G.Y, B.Y}, {R.Z, G.Z, B.Z}}};
    Matrix3d inv = Inverse(rgb);
    double C[3];
    for (int i = 0; i < 3; ++i) C[i] = inv[i][0] * W.X + inv[i][1] * W.Y + inv[i][2] * W.Z;
    Matrix3d xyzFromRGBd = Multiply(rgb, {{{C[0], 0, 0}, {0, C[1], 0}, {0, 0, C[2]}}});
    xyzFromRGB = ToFloat(xyzFromRGBd);
    rgbFromXYZ = ToFloat(Inverse(xyzFromRGBd));
}

RGB RGBColorSpace::ToRGB(const XYZ& xyz) const {
    XYZ v = Mul(rgbFromXYZ, xyz);
    return {v.X, v.Y, v.Z};
}

XYZ RGBColorSpace::ToXYZ(const RGB& rgb) const {
    RGB v = Mul(xyzFromRGB, rgb);
    return {v.r, v.g, v.b};
}

RGBSigmoidPolynomial RGBColorSpace::ToRGBCoeffs(const RGB& rgb) const { return (*table)(rgb); }

ColorMatrix RGBColorSpace::ConvertTo(const RGBColorSpace& to) const {
    Matrix3d a, bm;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            a[i][j] = to.rgbFromXYZ[i][j];
            bm[i][j] = xyzFromRGB[i][j];
        }
    return ToFloat(Multiply(a, bm));
}

bool RGBColorSpace::HasOwnSpectrumTable() const { return RGBToSpectrumTable::HasOwnTable(name); }

const RGBColorSpace* RGBColorSpace::GetNamed(std::string_view n) {
    // The standard spaces, built once on first use
    static const auto spaces = [] {
        std::vector<std::unique_ptr<RGBColorSpace>> v;
        for (const ColorSpaceDefinition& d : kColorSpaceDefinitions) {
            const Spectrum* illum = GetNamedSpectrum(d.illuminant);
            v.push_back(std::make_unique<RGBColorSpace>(
                std::string(d.name), Point2f(Float(d.rx), Float(d.ry)),
                Point2f(Float(d.gx), Float(d.gy)), Point2f(Float(d.bx), Float(d.by)), *illum,
                RGBToSpectrumTable::Get(d.name)));
        }
        return v;
    }();
    for (const auto& cs : spaces)
        if (cs->Name() == n) return cs.get();
    return nullptr;
}

std::vector<std::string_view> RGBColorSpace::Names() {
    std::vector<std::string_view> names;
    for (const ColorSpaceDefinition& d : kColorSpaceDefinitions) names.push_back(d.name);
    return names;
}

const RGBColorSpace& RGBColorSpace::sRGB() { return *GetNamed("srgb"); }
const RGBColorSpace& RGBColorSpace::DCI_P3() { return *GetNamed("dci-p3"); }
const RGBColorSpace& RGBColorSpace::Rec2020() { return *GetNamed("rec2020"); }
const RGBColorSpace& RGBColorSpace::ACES2065_1() { return *GetNamed("aces2065-1"); }

}  // namespace kiln
