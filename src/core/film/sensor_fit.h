// The colour fit of a camera sensor (pbrt-v4's PixelSensor constructor for measured curves):
// the 3x3 matrix taking the sensor's RGB to CIE XYZ, by linear least squares over the 24
// ColorChecker swatches lit by the sensor illuminant.
#pragma once

#include <array>
#include <optional>

#include "spectral/color.h"
#include "spectral/spectrum.h"

namespace kiln {

// Sum over lambda = 360, 361, ..., 830 nm of b(l) refl(l) illum(l) for b = b1, b2, b3, divided
// by the sum of b2(l) illum(l) (pbrt-v4's ProjectReflectance): the response to the reflectance
// relative to the second channel's response to the illuminant itself.
std::array<double, 3> ProjectReflectance(const Spectrum& refl, const Spectrum& illum,
                                         const Spectrum& b1, const Spectrum& b2,
                                         const Spectrum& b3);

// The matrix M minimising sum_i |M rgb_i - xyz_i|^2 over the swatches, where rgb_i is the
// sensor's response to swatch i lit by sensorIllum (ProjectReflectance with r, g, b) and xyz_i
// the swatch's XYZ under the output colour space's illuminant (ProjectReflectance with the CIE
// functions, Y = 1 for a perfect white) times integral(ybar illum) / integral(g illum), so that
// M applied to the raw sensor response integral(rgb L) of any radiance L gives XYZ scaled like
// integral(xyz L) (pbrt-v4's normalisation). nullopt if the normal equations are singular.
std::optional<ColorMatrix> FitXYZFromSensorRGB(const Spectrum& r, const Spectrum& g,
                                               const Spectrum& b, const Spectrum& sensorIllum,
                                               const RGBColorSpace& outputColorSpace);

}  // namespace kiln
