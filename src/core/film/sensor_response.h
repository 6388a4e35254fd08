// A thermal sensor's relative spectral response R(lambda) (Film "thermal" "string sensor"
// "response", thermal_sensor.h): piecewise linear between its points, 0 beyond them. What the
// sensor measures is the response-weighted radiance integral R(lambda) L(lambda) dlambda, W m^-2
// sr^-1 when R is dimensionless; the temperature it reports inverts the same integral of
// Planck's radiance, Lb(T) = integral R(lambda) B(lambda, T) dlambda.
//
// Lb(T) is summed over steps built once: every interval of the response divided into steps of at
// most 0.2 % of its wavelength; over each step R is linear and B taken as the exponential through
// its ends, integrated exactly (so also where B falls by orders of magnitude across a step, as in
// Wien's regime), in logarithms, so that no temperature underflows. Its inverse interpolates ln T
// linearly in ln Lb over 2048 temperatures from 1 K to 1e6 K spaced evenly in ln T (relative
// error of T below 2e-5: test/film/sensor_response_test.cpp).
#pragma once

#include <span>
#include <vector>

#include "spectral/spectral_range.h"

namespace kiln {

class SensorResponse {
  public:
    // lambdas: nm, strictly increasing, within 300 nm - 20 um; values >= 0 and finite, some >
    // 0, as many as lambdas. Throws std::invalid_argument (saying what is wrong) otherwise.
    SensorResponse(std::span<const float> lambdas, std::span<const float> values);

    // R at lambda (0 beyond the table)
    float operator()(float lambda) const;
    // The wavelengths where R may be non-zero: from the last zero point before the first
    // positive value to the first zero point after the last one (the table's ends otherwise)
    SpectralRange Support() const { return support; }
    std::span<const float> Lambdas() const { return lambdas; }
    std::span<const float> Values() const { return values; }
    // The integral of R over [a, b] (nm), exact for the piecewise-linear R
    double Integral(double a, double b) const;

    // Lb(T) = integral R B(lambda, T) dlambda, W m^-2 sr^-1 (R dimensionless); 0 for T <= 0
    double BandRadiance(double T) const;
    // The T with BandRadiance(T) = L: 0 for L <= 0 or below Lb(1 K); 1e6 K at most
    double Temperature(double L) const;

  private:
    double LogBandRadiance(double T) const;

    std::vector<float> lambdas, values;
    SpectralRange support;
    std::vector<double> nodeLambda, nodeR;  // the steps' ends: lambda (nm), R
    std::vector<double> logT, logL;         // the inversion table
};

}  // namespace kiln
