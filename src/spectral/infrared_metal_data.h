// Measured optical constants of metals in the infrared, for named metals the Lorentz-Drude model
// (lorentz_drude.h) does not cover: the continuation of their named tables beyond the visible
// (named_spectra.cpp).
#pragma once

#include <complex>
#include <optional>
#include <string_view>

namespace kiln {

// n + i k of the metal `symbol` at lambda_nm, linear in wavelength between the measured points;
// nullopt outside the measurements or for other metals. Iron ("Fe"): 667 nm - 25 um; brass
// ("CuZn", pbrt-v4's metal-CuZn): 290 nm - 20.8 um; magnesia ("MgO", pbrt-v4's metal-MgO):
// 288 nm - 20.6 um (sources in infrared_metal_data.cpp).
std::optional<std::complex<double>> MeasuredInfraredIndex(std::string_view symbol,
                                                          double lambda_nm);

}  // namespace kiln
