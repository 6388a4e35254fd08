// The sensor of Film "thermal": a band of wavelengths with a flat response, the in-band radiance
// a pixel measures (W m^-2 sr^-1) and the apparent temperature a thermal camera or pyrometer
// reports from it.
//
// Parameters ("string sensor" chooses the band):
//   "lwir"       8-14 um (long-wave infrared: uncooled microbolometer cameras)
//   "mwir"       3-5 um (mid-wave infrared: cooled InSb cameras)
//   "swir"       0.9-1.7 um (short-wave infrared: InGaAs)
//   "nir"        0.75-1.1 um (near infrared: silicon)
//   "pyrometer"  "float wavelength" (nm, required) and "float bandwidth" (nm, default 10): the
//                band of that width centred there
//   "band"       "float lambdamin" and "float lambdamax" (nm)
// Every band lies within 300 nm - 20 um.
//   "float emissivity" (0 < e <= 1, default 1) and "float reflectedtemperature" (K, default 0):
//   the camera's emissivity setting and reflected apparent temperature, as thermal cameras
//   offer them. The reported temperature T solves
//     e Lb(T) + (1 - e) Lb(T_refl) = L,  Lb(T) = integral over the band of B(lambda, T),
//   so a surface of emissivity e surrounded by matter at T_refl reads its own temperature.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/parser/file_loc.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/spectral_range.h"

namespace kiln {

class ParameterDictionary;

class ThermalSensor {
  public:
    // Throws SceneError, located at the offending parameter.
    static ThermalSensor Create(const ParameterDictionary& params, const FileLoc& loc);

    const std::string& Name() const { return name; }
    const SpectralRange& Band() const { return band; }
    Float Emissivity() const { return emissivity; }
    Float ReflectedTemperature() const { return reflectedTemperature; }

    // One path sample's estimate of the in-band radiance, W m^-2 sr^-1: the mean over the
    // wavelengths the path still carries of L / pdf.
    Float InBandRadiance(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
        return SafeDiv(L, lambda.PDF()).Average();
    }
    // The temperature the sensor reports for in-band radiance L, K (0 where L is not more than
    // what the reflected temperature accounts for).
    double ApparentTemperature(double L) const;

    // What ApparentTemperature depends on, as text for an image's metadata ("kiln:thermal":
    // band ends in nm, emissivity, reflected temperature), and back (nullopt if malformed):
    // kiln merge computes the temperature of merged radiance with it.
    std::string Settings() const;
    static std::optional<ThermalSensor> FromSettings(std::string_view settings);

  private:
    std::string name;
    SpectralRange band;
    Float emissivity = 1, reflectedTemperature = 0;
};

}  // namespace kiln
