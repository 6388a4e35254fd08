// PixelSensor (pbrt-v4's "cie1931" and named camera sensors), daylight chromaticity and white
// balance.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/film/film.h"
#include "core/film/sensor_fit.h"
#include "core/parser/parameter_dictionary.h"
#include "spectral/cie.h"
#include "spectral/color_checker.h"
#include "spectral/named_spectra.h"

namespace kiln {

namespace {

ColorMatrix Identity3() { return ColorMatrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; }

}  // namespace

// CIE 015:2018, section 4.1: the CIE daylight locus.
Point2f DaylightChromaticity(Float T) {
    double t = Clamp(double(T), 4000.0, 25000.0);
    double x = t <= 7000 ? -4.6070e9 / (t * t * t) + 2.9678e6 / (t * t) + 0.09911e3 / t + 0.244063
                         : -2.0064e9 / (t * t * t) + 1.9018e6 / (t * t) + 0.24748e3 / t + 0.237040;
    double y = -3.000 * x * x + 2.870 * x - 0.275;
    return Point2f(Float(x), Float(y));
}

// Bradford cone response matrix (Lam 1985, as used by pbrt-v4's WhiteBalance) and its inverse.
ColorMatrix WhiteBalance(Point2f srcW, Point2f dstW) {
    const ColorMatrix lmsFromXYZ{
        {{0.8951f, 0.2664f, -0.1614f}, {-0.7502f, 1.7135f, 0.0367f}, {0.0389f, -0.0685f, 1.0296f}}};
    const ColorMatrix xyzFromLMS{{{0.986993f, -0.147054f, 0.159963f},
                                  {0.432305f, 0.51836f, 0.0492912f},
                                  {-0.00852866f, 0.0400428f, 0.968487f}}};
    XYZ src = Mul(lmsFromXYZ, XYZ::FromxyY(srcW)), dst = Mul(lmsFromXYZ, XYZ::FromxyY(dstW));
    ColorMatrix d{{{dst.X / src.X, 0, 0}, {0, dst.Y / src.Y, 0}, {0, 0, dst.Z / src.Z}}};
    return Mul(xyzFromLMS, Mul(d, lmsFromXYZ));
}

// PixelSensor Method Definitions
PixelSensor::PixelSensor(const RGBColorSpace* outputColorSpace, Float whiteBalanceTemp,
                         Float imagingRatio)
    : XYZFromSensorRGB(Identity3()), imagingRatio(imagingRatio) {
    if (whiteBalanceTemp > 0) {
        const RGBColorSpace* cs = outputColorSpace ? outputColorSpace : &RGBColorSpace::sRGB();
        // pbrt-v4: the source white is the chromaticity of its daylight spectrum of T.
        XYZFromSensorRGB =
            WhiteBalance(SpectrumToXYZ(CIEDaylightSpectrum(whiteBalanceTemp)).xy(), cs->w);
    }
}

PixelSensor::PixelSensor(const Spectrum* r, const Spectrum* g, const Spectrum* b,
                         const RGBColorSpace* outputColorSpace, const Spectrum& sensorIllum,
                         Float imagingRatio)
    : imagingRatio(imagingRatio), r_bar(r), g_bar(g), b_bar(b) {
    const RGBColorSpace& cs = outputColorSpace ? *outputColorSpace : RGBColorSpace::sRGB();
    std::optional<ColorMatrix> m = FitXYZFromSensorRGB(*r, *g, *b, sensorIllum, cs);
    if (!m) throw std::runtime_error("sensor XYZ-from-RGB matrix could not be solved");
    XYZFromSensorRGB = *m;
}

PixelSensor PixelSensor::Create(const ParameterDictionary& params, const RGBColorSpace* colorSpace,
                                Float exposureTime, const FileLoc& loc, Diagnostics& diag) {
    Float iso = params.GetOneFloat("iso", 100);
    Float whiteBalance = params.GetOneFloat("whitebalance", 0);
    std::string sensorName = params.GetOneString("sensor", "cie1931");
    if (whiteBalance < 0)
        throw SceneError(params.Loc("whitebalance", loc), "whitebalance must be >= 0 K",
                         "whitebalance");
    // The sensor's gain: a film of zero, negative or infinite sensitivity records nothing
    // meaningful (negative radiance, or infinities and NaN where bright light overflows it)
    if (!(iso > 0 && std::isfinite(iso)))
        throw SceneError(params.Loc("iso", loc), "iso must be positive and finite", "iso");
    // pbrt-v4: camera sensors white balance for 6500 K unless told otherwise.
    if (sensorName != "cie1931" && whiteBalance == 0) whiteBalance = 6500;
    Float imagingRatio = exposureTime * iso / 100;
    if (sensorName == "cie1931") return PixelSensor(colorSpace, whiteBalance, imagingRatio);

    const Spectrum* r = GetNamedSpectrum(sensorName + "_r");
    const Spectrum* g = GetNamedSpectrum(sensorName + "_g");
    const Spectrum* b = GetNamedSpectrum(sensorName + "_b");
    if (r && g && b) {
        Spectrum illum = CIEDaylightSpectrum(whiteBalance);
        try {
            return PixelSensor(r, g, b, colorSpace, illum, imagingRatio);
        } catch (const std::runtime_error& e) {
            throw SceneError(loc, std::string("sensor \"") + sensorName + "\": " + e.what(),
                             "sensor");
        }
    }
    if (!IsPbrtSensorWithoutData(sensorName))
        throw SceneError(loc, "\"" + sensorName + "\": unknown sensor type", "sensor");
    diag.Warn(loc, "sensor \"" + sensorName +
                       "\": pbrt-v4's measured curves for this camera are not available to kiln "
                       "from any public source; using \"cie1931\" white balanced for " +
                       std::to_string(int(whiteBalance)) + " K");
    return PixelSensor(colorSpace, whiteBalance, imagingRatio);
}

RGB PixelSensor::ToSensorRGB(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
    if (!r_bar) {
        XYZ xyz = SpectrumToXYZ(L, lambda) * imagingRatio;
        return RGB(xyz.X, xyz.Y, xyz.Z);
    }
    SampledSpectrum Lp = SafeDiv(L, lambda.PDF());
    Float s = imagingRatio / CIE_Y_integral;
    return RGB((r_bar->Sample(lambda) * Lp).Average() * s,
               (g_bar->Sample(lambda) * Lp).Average() * s,
               (b_bar->Sample(lambda) * Lp).Average() * s);
}

}  // namespace kiln
