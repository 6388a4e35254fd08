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
//   "response"   "spectrum response": a relative spectral response (wavelength-value pairs in nm,
//                or a spectrum file), piecewise linear, 0 beyond its points
//                (sensor_response.h); the band is where it is not 0. The pixel measures
//                integral R L dlambda and the reported temperature inverts integral R B.
// Every band lies within 300 nm - 20 um.
//   "float emissivity" (0 < e <= 1, default 1) and "float reflectedtemperature" (K, default 0):
//   the camera's emissivity setting and reflected apparent temperature, as thermal cameras
//   offer them. The reported temperature T solves
//     e Lb(T) + (1 - e) Lb(T_refl) = L,  Lb(T) = integral over the band of B(lambda, T),
//   so a surface of emissivity e surrounded by matter at T_refl reads its own temperature
//   (Lb weighted by the response for "response").
//   "float scalemin", "float scalemax" (K, both or neither): the temperatures the picture's
//   palette spans (thermal_colormap.h), as a camera's fixed span; default: each frame's own
//   range.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/film/sensor_response.h"
#include "core/film/thermal_colormap.h"
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
    // The picture's fixed palette span (nullopt: the frame's range)
    const std::optional<TemperatureScale>& PictureScale() const { return pictureScale; }
    // The span as text for an image's metadata ("kiln:thermalscale": "lo hi"), and back
    // (nullopt if absent or malformed): kiln convert draws the same picture from the EXR.
    static std::string ScaleSettings(const TemperatureScale& s);
    static std::optional<TemperatureScale> ScaleFromSettings(std::string_view settings);

    // The response ("response" sensors; nullptr for a flat band)
    const SensorResponse* Response() const { return response ? &*response : nullptr; }

    // One path sample's estimate of the in-band radiance, W m^-2 sr^-1: the mean over the
    // wavelengths the path still carries of R L / pdf (R = 1 for a flat band).
    Float InBandRadiance(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
        if (!response) return SafeDiv(L, lambda.PDF()).Average();
        SampledSpectrum r;
        for (int i = 0; i < NSpectrumSamples; ++i) r[i] = (*response)(lambda[i]);
        return SafeDiv(L * r, lambda.PDF()).Average();
    }
    // What a blackbody at T gives, Lb(T), W m^-2 sr^-1.
    double BlackbodyRadiance(double T) const;
    // The temperature the sensor reports for in-band radiance L, K (0 where L is not more than
    // what the reflected temperature accounts for).
    double ApparentTemperature(double L) const;

    // What ApparentTemperature depends on, as text for an image's metadata ("kiln:thermal":
    // band ends in nm, emissivity, reflected temperature, then "response" and the response's
    // wavelength-value pairs when it has one), and back (nullopt if malformed):
    // kiln merge computes the temperature of merged radiance with it.
    std::string Settings() const;
    static std::optional<ThermalSensor> FromSettings(std::string_view settings);

  private:
    std::string name;
    SpectralRange band;
    Float emissivity = 1, reflectedTemperature = 0;
    std::optional<SensorResponse> response;
    std::optional<TemperatureScale> pictureScale;
};

}  // namespace kiln
