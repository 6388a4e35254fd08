// ColorChecker swatch spectra and CIE daylight spectra from the tables of color_checker_data.cpp.
#include "spectral/color_checker.h"

#include <vector>

namespace kiln {

std::span<const PiecewiseLinearSpectrum> ColorCheckerSwatches() {
    static const std::vector<PiecewiseLinearSpectrum> swatches = [] {
        std::vector<PiecewiseLinearSpectrum> s;
        for (std::span<const float> t : ColorCheckerSwatchTables())
            s.push_back(PiecewiseLinearSpectrum::FromInterleaved(t, false));
        return s;
    }();
    return swatches;
}

Spectrum CIEDaylightSpectrum(Float T) {
    double cct = double(T) * 1.4388 / 1.4380;
    if (cct < 4000) return Spectrum(BlackbodySpectrum(Float(cct)));
    // CIE 015:2018 eq. 4.1-4.3 (daylight locus) and 4.7-4.8 (M1, M2).
    double x =
        cct <= 7000
            ? -4.6070e9 / (cct * cct * cct) + 2.9678e6 / (cct * cct) + 0.09911e3 / cct + 0.244063
            : -2.0064e9 / (cct * cct * cct) + 1.9018e6 / (cct * cct) + 0.24748e3 / cct + 0.237040;
    double y = -3.0 * x * x + 2.870 * x - 0.275;
    double M = 0.0241 + 0.2562 * x - 0.7341 * y;
    double M1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / M;
    double M2 = (0.0300 - 31.4424 * x + 30.0717 * y) / M;
    DaylightBasisTables b = GetDaylightBasisTables();
    std::vector<Float> lambdas(b.S0.size()), values(b.S0.size());
    for (size_t i = 0; i < b.S0.size(); ++i) {
        lambdas[i] = b.lambda0 + b.step * Float(i);
        values[i] = Float((b.S0[i] + M1 * b.S1[i] + M2 * b.S2[i]) * 0.01);
    }
    return Spectrum(PiecewiseLinearSpectrum(lambdas, values));
}

}  // namespace kiln
