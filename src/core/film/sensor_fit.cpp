// Least-squares colour fit of a camera sensor over the ColorChecker swatches.
#include "core/film/sensor_fit.h"

#include <algorithm>
#include <cmath>

#include "spectral/color_checker.h"

namespace kiln {

std::array<double, 3> ProjectReflectance(const Spectrum& refl, const Spectrum& illum,
                                         const Spectrum& b1, const Spectrum& b2,
                                         const Spectrum& b3) {
    std::array<double, 3> sum{0, 0, 0};
    double b2Illum = 0;
    for (int l = 360; l <= 830; ++l) {
        double lambda = l, e = illum(Float(lambda)), re = refl(Float(lambda)) * e;
        b2Illum += b2(Float(lambda)) * e;
        sum[0] += b1(Float(lambda)) * re;
        sum[1] += b2(Float(lambda)) * re;
        sum[2] += b3(Float(lambda)) * re;
    }
    for (double& v : sum) v = b2Illum > 0 ? v / b2Illum : 0;
    return sum;
}

std::optional<ColorMatrix> FitXYZFromSensorRGB(const Spectrum& r, const Spectrum& g,
                                               const Spectrum& b, const Spectrum& sensorIllum,
                                               const RGBColorSpace& outputColorSpace) {
    const Spectrum outIllum(outputColorSpace.Illuminant());
    double gIllum = InnerProduct(sensorIllum, g), yIllum = InnerProduct(sensorIllum, spectra::Y());
    if (!(gIllum > 0)) return std::nullopt;
    // Normal equations of min |A M^T - B|: (A^T A) M^T = A^T B, A the swatches' sensor RGB
    // (rows), B their target XYZ (rows).
    double ata[3][3] = {}, atb[3][3] = {};
    for (const PiecewiseLinearSpectrum& swatch : ColorCheckerSwatches()) {
        Spectrum s(swatch);
        std::array<double, 3> a = ProjectReflectance(s, sensorIllum, r, g, b);
        std::array<double, 3> t =
            ProjectReflectance(s, outIllum, spectra::X(), spectra::Y(), spectra::Z());
        for (double& v : t) v *= yIllum / gIllum;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                ata[i][j] += a[i] * a[j];
                atb[i][j] += a[i] * t[j];
            }
    }
    // Inverse of the symmetric A^T A by cofactors.
    double c[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = ata[i1][j1] * ata[i2][j2] - ata[i1][j2] * ata[i2][j1];
        }
    double det = ata[0][0] * c[0][0] + ata[0][1] * c[0][1] + ata[0][2] * c[0][2];
    double scale = 0;
    for (auto& row : ata)
        for (double v : row) scale = std::max(scale, std::abs(v));
    if (!(std::abs(det) > 1e-12 * scale * scale * scale)) return std::nullopt;
    // M^T = (A^T A)^-1 A^T B; the inverse is c^T / det, and c is symmetric here.
    ColorMatrix m{};
    for (int row = 0; row < 3; ++row)        // row of M = column of M^T
        for (int col = 0; col < 3; ++col) {  // column of M = row of M^T
            double v = 0;
            for (int k = 0; k < 3; ++k) v += c[col][k] * atb[k][row];
            m[row][col] = Float(v / det);
        }
    return m;
}

}  // namespace kiln
