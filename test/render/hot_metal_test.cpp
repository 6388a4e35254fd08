// Named metals whose optical constants follow the surface's temperature
// (spectral/metal_temperature.h) through whole renders: a pyrometer reads tungsten at its
// melting point as measured, and a temperature field sets the constants point by point. (The
// closed cavities of equilibrium_test.cpp keep hot tungsten and gold at Kirchhoff equilibrium:
// the BSDF scatters and emits with the same constants.)
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "base/statistics.h"
#include "render_test_util.h"
#include "spectral/metal_temperature.h"
#include "spectral/named_spectra.h"
#include "spectral/planck.h"
#include "spectral/spectrum.h"

namespace kiln {
namespace {

// Normal emissivity of tungsten at lambda and T from the model, 1 - R of Fresnel's equations
double TungstenNormalEmissivity(double lambda, double T) {
    std::complex<double> n((*GetNamedSpectrum("metal-W-eta"))(Float(lambda)),
                           (*GetNamedSpectrum("metal-W-k"))(Float(lambda)));
    std::complex<double> N = std::sqrt(MetalPermittivityAt("W", lambda, T, n * n));
    return 4 * N.real() / ((N.real() + 1) * (N.real() + 1) + N.imag() * N.imag());
}

// Emitted in-band radiance of a smooth tungsten plate seen along its normal at T, W m^-2 sr^-1,
// through a pyrometer band [lambda - 5, lambda + 5] nm (midpoint rule, 0.1 nm)
double PlateBandRadiance(double lambda, double T) {
    double sum = 0;
    for (double l = lambda - 4.95; l < lambda + 5; l += 0.1)
        sum += TungstenNormalEmissivity(l, T) * planck_radiance(l, T) * 0.1;
    return sum;
}

// A smooth tungsten plate filling an orthographic pyrometer's view, nothing else in the scene
std::string Plate(const std::string& textures, const std::string& temperature, int width, int spp) {
    std::ostringstream s;
    s << "Film \"thermal\" \"string sensor\" \"pyrometer\" \"float wavelength\" 653"
      << " \"integer xresolution\" " << width << " \"integer yresolution\" 1\n"
      << "PixelFilter \"box\" \"float xradius\" 0.5 \"float yradius\" 0.5\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "LookAt 0 0 -5  0 0 0  0 1 0\n"
      << "Camera \"orthographic\" \"float screenwindow\" [-1 1 -0.05 0.05]\n"
      << "WorldBegin\n"
      << textures << "\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-W-eta\" \"spectrum k\" \"metal-W-k\""
         " \"float roughness\" 0\n"
      << "Shape \"bilinearmesh\" \"point3 P\" [-2 -1 0  2 -1 0  -2 1 0  2 1 0]"
         " "
      << temperature << "\n";
    return s.str();
}

// Issue 26's validation: tungsten at its melting point (3695 K) has a radiance temperature of
// 3208 +- 10 K at 653 nm (Cezairliyan and Miiller, Int. J. Thermophys. 3, 89 (1982)); kiln's
// tungsten, fitted to other measurements (Larrabee 1959), must read it within 15 K
TEST(HotMetal, PyrometerReadsTungstenAtItsMeltingPointAsMeasured) {
    testing::RenderedScene r = testing::RenderText(Plate("", "\"float temperature\" 3695", 4, 16));
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    Image img = r.scene->job->film->GetImage(nullptr);
    RunningStats L, T;
    for (int x = 0; x < 4; ++x) {
        L.Add(img.GetChannel({x, 0}, img.ChannelIndex("L")));
        T.Add(img.GetChannel({x, 0}, img.ChannelIndex("T")));
    }
    const double expected = PlateBandRadiance(653, 3695);
    std::printf(
        "tungsten at 3695 K through 648-658 nm: L %.5f of the model's (se %.5f), T %.1f K "
        "(measured 3208 +- 10 K)\n",
        L.Mean() / expected, L.StandardError() / expected, T.Mean());
    EXPECT_NEAR(L.Mean() / expected, 1, 4 * L.StandardError() / expected + 1e-3);
    EXPECT_NEAR(T.Mean(), 3208, 15);
}

// A temperature field across the plate (2000 K at the left edge of the view to 3600 K at the
// right): each pixel's radiance is the model's at the temperatures under it, so the constants
// follow the field point by point (room-temperature constants would be 17-27 % brighter)
TEST(HotMetal, TemperatureFieldSetsTheConstantsPointByPoint) {
    const int width = 16;
    testing::RenderedScene r = testing::RenderText(
        Plate("Texture \"heat\" \"float\" \"gradient\" \"point3 p0\" [-1 0 0] \"point3 p1\" [1 0 0]"
              " \"float t0\" 2000 \"float t1\" 3600",
              "\"texture temperature\" \"heat\"", width, 64));
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    Image img = r.scene->job->film->GetImage(nullptr);
    double worst = 0;
    for (int x = 0; x < width; ++x) {
        // The pixel's mean over its footprint (raster x 0..width is world x -1..1)
        double expected = 0, roomConstants = 0;
        const int n = 32;
        for (int i = 0; i < n; ++i) {
            double T = 2000 + 1600 * (x + (i + 0.5) / n) / width;
            expected += PlateBandRadiance(653, T) / n;
            roomConstants += TungstenNormalEmissivity(653, 293) / TungstenNormalEmissivity(653, T) *
                             PlateBandRadiance(653, T) / n;
        }
        double L = img.GetChannel({x, 0}, img.ChannelIndex("L"));
        worst = std::max(worst, std::abs(L / expected - 1));
        EXPECT_NEAR(L / expected, 1, 0.01) << "pixel " << x;
        EXPECT_GT(roomConstants / expected, 1.15);
    }
    std::printf(
        "tungsten 2000-3600 K: largest relative difference of a pixel from the model "
        "%.4f\n",
        worst);
}

// A straight incandescent tungsten filament seen across its axis (an abstract in J. Opt. Soc. Am.,
// osapublishing.org id 48025, on W, Mo and Ta): its light is polarised by 19.3 % and its mean
// brightness across the filament is 2.8 % above that at normal emergence. The abstract states
// neither temperature nor uncertainty; kiln's tungsten at 2000 K (Stokes film, luminance) must
// come within 0.01 of both. With room-temperature constants kiln gives 0.18 and 0.7-0.8 %.
TEST(HotMetal, TungstenFilamentPolarisationAndBrightnessAsMeasured) {
    const int width = 120, height = 12;
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" " << width << " \"integer yresolution\" " << height
      << " \"bool stokes\" true\n"
      << "PixelFilter \"box\" \"float xradius\" 0.5 \"float yradius\" 0.5\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
      << "LookAt 0 0 -5  0 0 0  0 1 0\n"
      << "Camera \"orthographic\" \"float screenwindow\" [-0.6 0.6 -0.06 0.06]\n"
      << "WorldBegin\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-W-eta\" \"spectrum k\" \"metal-W-k\""
         " \"float roughness\" 0\n"
      << "AttributeBegin Rotate 90 1 0 0\n"  // the cylinder's axis along y
      << "Shape \"cylinder\" \"float radius\" 0.5 \"float zmin\" -1 \"float zmax\" 1"
         " \"float temperature\" 2000\nAttributeEnd\n";
    testing::RenderedScene r = testing::RenderText(s.str());
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    const RGBFilm& film = *r.scene->job->film;
    const RGBColorSpace* cs = film.ColorSpace();
    // Luminance of each Stokes component summed over the filament (it spans 100 columns), and
    // S0 of the central columns (normal emergence)
    double S[3] = {0, 0, 0}, centre = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int k = 0; k < 3; ++k) {
                double v = cs->ToXYZ(film.GetPixelStokes({x, y}, k)).Y;
                S[k] += v;
                if (k == 0 && (x == width / 2 - 1 || x == width / 2)) centre += v;
            }
    const double dop = std::hypot(S[1], S[2]) / S[0];
    const double brightness = S[0] / 100 / (centre / 2);
    std::printf(
        "tungsten filament at 2000 K: degree of polarisation %.4f (S2/S0 %.4f), mean "
        "brightness %.4f of normal emergence\n",
        dop, S[2] / S[0], brightness);
    EXPECT_NEAR(dop, 0.193, 0.01);
    EXPECT_LT(std::abs(S[2] / S[0]), 1e-3);  // polarised across the filament's axis
    EXPECT_NEAR(brightness, 1.028, 0.01);
}

// "float opticaltemperature" fixes the temperature of the constants (the paper's scenes take
// room temperature): the melting tungsten plate then reads what room-temperature constants
// predict; values that are not kelvin are located errors
TEST(HotMetal, OpticalTemperatureFixesTheConstants) {
    std::string text = Plate("", "\"float temperature\" 3695", 2, 4);
    const std::string material = "\"float roughness\" 0";
    auto with = [&](const std::string& extra) {
        std::string t = text;
        t.replace(t.find(material), material.size(), material + " " + extra);
        return t;
    };
    auto reading = [](const testing::RenderedScene& r) {
        Image img = r.scene->job->film->GetImage(nullptr);
        return img.GetChannel({0, 0}, img.ChannelIndex("T"));
    };
    const double room =
        1 / (1 / 3695.0 - 653 / 1.438776877e7 * std::log(TungstenNormalEmissivity(653, 293)));
    EXPECT_NEAR(reading(testing::RenderText(with("\"float opticaltemperature\" 293"))), room, 2);
    EXPECT_NEAR(reading(testing::RenderText(with("\"float opticaltemperature\" 3695"))), 3200, 2);
    // Fixed at 2000 K while the surface is at 3695 K: the constants of 2000 K
    const double at2000 =
        1 / (1 / 3695.0 - 653 / 1.438776877e7 * std::log(TungstenNormalEmissivity(653, 2000)));
    EXPECT_NEAR(reading(testing::RenderText(with("\"float opticaltemperature\" 2000"))), at2000, 2);
    Diagnostics diag(nullptr);
    try {
        testing::BuildScene(with("\"float opticaltemperature\" -5"), diag);
        ADD_FAILURE() << "a negative optical temperature was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(e.Message().find("opticaltemperature"), std::string::npos) << e.Message();
        EXPECT_EQ(e.Token(), "opticaltemperature");
        EXPECT_GT(e.Loc().line, 0);
    }
}

}  // namespace
}  // namespace kiln
