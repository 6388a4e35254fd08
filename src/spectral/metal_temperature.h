// Optical constants of named metals that follow temperature (issue 26): metal-W, metal-Au and
// metal-Ag's n and k at the surface's temperature. Without a temperature, and at or below room
// temperature, they are the named tables (pbrt-v4's values in the visible); above it the
// permittivity eps = (n + i k)^2 changes as follows.
//
// Tungsten: the Lorentz-Drude model of Rakic et al. (1998; lorentz_drude.h) with the Drude damping
// scaled by tungsten's electrical resistivity rho(T) / rho(293 K), the Lorentz dampings by
// 1 + a (T - 293 K) and the Lorentz strengths by 1 + b (T - 293 K), a = 3.0e-4 / K and
// b = 2.96e-4 / K fitted to Larrabee's measured normal spectral emissivity of tungsten at
// 1600-2800 K and 310-800 nm (gen/hot_tungsten_fit.py: RMS 0.007 in emissivity). From 1600 K
// up, eps is the model's; between 293 and 1600 K the named table's difference from the model
// at 293 K fades out linearly in T. Up to the melting point, 3695 K; held above (no data on the
// liquid).
//
// Gold and silver: eps(T) = eps_named + (eps_measured(T) - eps_measured(room)), the change of
// measured permittivity between room temperature and T (metal_temperature_data.cpp: gold at 298,
// 498 and 623 K; silver at 298, 404, 501 and 600 K; 245-958 nm), linear in T between the
// measured temperatures and beyond the last one along the least-squares slope through all of
// them (the free-electron damping, which dominates the change, follows the resistivity, linear
// in T for these metals), up to the melting point (gold 1337 K, silver 1235 K), held above.
// Beyond the measurements' longest wavelength the change is the Lorentz-Drude model's with its
// Drude damping and strength scaled so that the model's change matches the measured one (Im
// and Re eps, means over the measurements' last 15 % of wavelength; the factors found at each
// measured temperature and the melting point, linear in T between); over that last 15 % the
// two go over linearly.
//
// Each metal's change is tabulated on first use (as the named spectra are built) over 300 nm -
// 20 um (1 % geometric steps) and temperature (25 K steps): eps(lambda, T) = w(T)
// eps_named(lambda) + C(lambda, T), bilinear in (log lambda, T).
// test/spectral/metal_temperature_test.cpp bounds the table's error against direct evaluation.
#pragma once

#include <complex>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "base/table_axis.h"
#include "spectral/nk_file.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

class Spectrum;

// Whether the named metal (chemical symbol, "W") has a temperature model.
bool HasMetalTemperatureModel(std::string_view symbol);

// The permittivity of `symbol` at lambda_nm and T (kelvin) given its named table's permittivity
// there (eps_named): the direct evaluation of the model above (slow: for tables and tests).
std::complex<double> MetalPermittivityAt(std::string_view symbol, double lambda_nm, double T,
                                         std::complex<double> epsNamed);

// Tungsten's resistivity ratio rho(T) / rho(293 K) (the Drude damping's factor above).
double TungstenResistivityRatio(double T);

// MetalTemperatureTable Definition
// The model of one metal tabulated over wavelength and temperature, with its named eta and k
class MetalTemperatureTable {
  public:
    // The table of W, Au or Ag (built on first use, for the program's life); nullptr for
    // metals without a temperature model.
    static const MetalTemperatureTable* Find(std::string_view symbol);
    // A metal measured at several temperatures (K, strictly increasing, at least two; a
    // conductor's "nkfiles"): at and below the first, its table (the "named" eta and k here);
    // between two, the permittivity (n + i k)^2 linear in T; above the last, the last's. Each
    // table holds its end values beyond its wavelengths. Tabulated as the named metals, over
    // 300 nm - 20 um and from the first to the last temperature in steps of at most 25 K.
    static MetalTemperatureTable FromMeasurements(
        const std::vector<std::pair<Float, NkTable>>& measurements);

    // n and k at the wavelengths lambda and temperature T (kelvin; <= room temperature, or 0
    // for none: the named tables' values).
    void Evaluate(const SampledWavelengths& lambda, Float T, SampledSpectrum* eta,
                  SampledSpectrum* k) const;
    // The temperature nodes (K): room temperature to the melting point in 25 K steps
    const TableAxis& Temperatures() const { return temperatures; }
    // Room temperature (K): the first temperature node.
    Float RoomTemperature() const { return temperatures.Node(0); }
    // The named tables (metal-X-eta, metal-X-k)
    const Spectrum& NamedEta() const { return *namedEta; }
    const Spectrum& NamedK() const { return *namedK; }

  private:
    MetalTemperatureTable() = default;
    static std::optional<MetalTemperatureTable> Create(std::string_view symbol);
    std::string_view symbol;
    const Spectrum* namedEta = nullptr;
    const Spectrum* namedK = nullptr;
    std::shared_ptr<const Spectrum> ownEta, ownK;  // measured tables: the first's
    TableAxis logLambdas, temperatures;
    std::vector<float> w;                     // [T]
    std::vector<std::complex<float>> change;  // C as [T][lambda]
};

}  // namespace kiln
