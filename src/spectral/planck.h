// Planck's law for a blackbody, with the exact SI constants (CODATA 2018).
//
// Radiance per unit wavelength is in W m^-2 sr^-1 nm^-1, wavelengths in nm, temperatures in
// kelvin. Every function is finite and non-negative for any input (never NaN or Inf): T <= 0
// or NaN gives 0, and so does a wavelength that is not positive.
#pragma once

#include <cstdio>
#include <string>

#include "spectral/sampled_spectrum.h"

namespace kiln {

// CODATA 2018 (Tiesinga et al., Rev. Mod. Phys. 93, 025010 (2021)); exact since the 2019 SI.
inline constexpr double kPlanckConstant = 6.62607015e-34;   // h, J s
inline constexpr double kSpeedOfLight = 299792458.0;        // c, m s^-1
inline constexpr double kBoltzmannConstant = 1.380649e-23;  // k_B, J K^-1
// Derived (exact): second radiation constant c2 = h c / k_B, m K; first radiation constant
// for spectral radiance c1L = 2 h c^2, W m^2 sr^-1; Stefan-Boltzmann sigma, W m^-2 K^-4.
inline constexpr double kSecondRadiationConstant =
    kPlanckConstant * kSpeedOfLight / kBoltzmannConstant;
inline constexpr double kFirstRadiationConstantL =
    2 * kPlanckConstant * kSpeedOfLight * kSpeedOfLight;
inline constexpr double kStefanBoltzmannConstant = 5.670374419184429e-8;
// The hottest temperature kiln renders, kelvin. At 1e27 K, B(360 nm) is 4.9e29
// W m^-2 sr^-1 nm^-1 (Rayleigh-Jeans, 493 T at kiln's shortest wavelength), leaving float
// (3.4e38) nine orders of magnitude for path throughputs, sampling weights and the film's
// sensor response; hotter scene temperatures are errors at their parameter.
inline constexpr double kMaxRenderTemperature = 1e27;
// The brightest emission kiln renders, with the same headroom: spectral radiance in
// W m^-2 sr^-1 nm^-1 (intensity in W sr^-1 nm^-1 for point-like lights) at any wavelength.
// Brighter lights and media are errors at their parameter.
inline constexpr double kMaxEmission = 1e30;
// A temperature for messages: "1e+38", "1500"
inline std::string FormatKelvin(double T) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", T);
    return text;
}
// Wien's displacement constant b = c2 / x5, m K, where x5 solves x = 5 (1 - e^-x).
inline constexpr double kWienX5 = 4.9651142317442763;
inline constexpr double kWienDisplacementConstant = 2.897771955185173e-3;

// Spectral radiance of a blackbody at lambda_nm (nm) and T_kelvin (K), W m^-2 sr^-1 nm^-1.
// Evaluated with expm1 directly where that is exact, in logarithms where the direct form would
// overflow or underflow, so it keeps full double precision over 1 nm - 1 mm and any T >= 0.
double planck_radiance(double lambda_nm, double T_kelvin);

// The same at each of the path's wavelengths, W m^-2 sr^-1 nm^-1 (clamped to the largest
// finite Float), with the exponential in single precision where that is safe: relative error
// below 1e-5 (test/spectral/planck_test.cpp), for speed per sample.
SampledSpectrum planck_radiance(const SampledWavelengths& lambda, double T_kelvin);

// Radiance relative to its peak over wavelength: B(lambda, T) / B(lambda_peak, T), in [0, 1]
// (dimensionless). pbrt-v4's BlackbodySpectrum; computed as a ratio, so it is exact for tiny
// and huge T alike.
double planck_radiance_normalized(double lambda_nm, double T_kelvin);

// The same at each of the path's wavelengths: at 1-1e6 K, planck_radiance's fast path over the
// peak radiance in closed form, c1L T^5 / (b^5 (e^x5 - 1)) (relative error below 2e-5,
// test/spectral/planck_test.cpp); exactly, as above, elsewhere.
SampledSpectrum planck_radiance_normalized(const SampledWavelengths& lambda, double T_kelvin);

// Wavelength of peak spectral radiance per unit wavelength (Wien), nm: b / T. +Inf for T <= 0.
double planck_peak_wavelength_nm(double T_kelvin);

// Radiance integrated over all wavelengths, sigma T^4 / pi, W m^-2 sr^-1 (exitance / pi).
double stefan_boltzmann_radiance(double T_kelvin);

// Radiance integrated over the band [lambda1_nm, lambda2_nm], W m^-2 sr^-1: in x = c2 / (lambda
// T), 2 k^4 T^4 / (h^3 c^2) times the integral of x^3 / (e^x - 1) between the band's ends, by
// its series sum e^(-n x) / n (x^3 + 3 x^2 / n + 6 x / n^2 + 6 / n^3) for x >= 1 and 8-point
// Gauss-Legendre quadrature of the smooth integrand below 1 (relative error below 1e-12), and
// Rayleigh-Jeans where x < 1e-12 throughout. 0 for T <= 0, NaN or an empty band; at most
// DBL_MAX.
double planck_band_radiance(double lambda1_nm, double lambda2_nm, double T_kelvin);

// Radiance temperature (brightness temperature) at lambda_nm: the temperature of the blackbody
// whose spectral radiance there is L (W m^-2 sr^-1 nm^-1), what a narrow-band pyrometer at
// lambda_nm reads (Planck's law inverted: T = c2 / (lambda ln(1 + c1L / (lambda^5 L)))), K.
// 0 for L <= 0 or NaN (or a wavelength that is not positive and finite); huge L gives the
// huge temperature it implies, +Inf for L = +Inf.
double radiance_temperature(double lambda_nm, double L);

// Band radiance temperature: the temperature T with planck_band_radiance(lambda1_nm,
// lambda2_nm, T) = L (W m^-2 sr^-1), what a thermal camera with a flat response over the band
// reads, K. Found by bisection in log T (the band radiance grows strictly with T), to a
// relative 1e-12 between 1e-3 K and kMaxRenderTemperature; 0 for L <= 0, NaN or an empty
// band, kMaxRenderTemperature for L beyond that temperature's band radiance.
double band_radiance_temperature(double lambda1_nm, double lambda2_nm, double L);

}  // namespace kiln
