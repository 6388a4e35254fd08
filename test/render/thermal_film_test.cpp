// Film "thermal": infrared cameras and pyrometers. A closed cavity at one temperature is a
// blackbody in every band, whatever it holds (Kirchhoff from each surface's own BSDF, with the
// emissivity tables built over the sensor's band): the in-band radiance must be Planck's
// integral over the band and the reported temperature the cavity's. The camera's emissivity
// setting and reflected temperature recover a grey surface's own temperature.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <sstream>
#include <string>

#include "base/statistics.h"
#include "core/film/thermal_colormap.h"
#include "render_test_util.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// The one warning an infrared render with RGB colours gives (at the first of them), and no other
void ExpectOnlyTheRGBWarning(const testing::RenderedScene& r) {
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].message.find("RGB colours say nothing beyond the visible"),
              std::string::npos)
        << r.warnings[0].message;
    EXPECT_GT(r.warnings[0].loc.line, 0);
}

RunningStats ChannelStats(const testing::RenderedScene& r, const char* channel) {
    return testing::ThermalChannelStats(r, channel);
}

// A closed cavity (a textured diffuse wall) around rough gold, coated diffuse and smooth
// silver, every surface at the ambient temperature T, seen by the film `film`
std::string Cavity(const std::string& film, double T, int spp) {
    std::ostringstream s;
    s << "Option \"float ambienttemperature\" " << T << "\n"
      << film << " \"integer xresolution\" 20 \"integer yresolution\" 20\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"path\" \"integer maxdepth\" 200\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\n"
      << "WorldBegin\n"
      << "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8"
         " \"rgb tex1\" [0.9 0.8 0.7] \"rgb tex2\" [0.1 0.2 0.05]\n"
      << "Material \"diffuse\" \"texture reflectance\" \"checks\"\n"
      << "Shape \"sphere\" \"float radius\" 6\n"
      << "AttributeBegin Translate -0.8 0 0.5\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\""
         " \"float roughness\" 0.2\n"
      << "Shape \"sphere\" \"float radius\" 0.7\nAttributeEnd\n"
      << "AttributeBegin Translate 0.8 0 0.5\n"
      << "Material \"coateddiffuse\" \"rgb reflectance\" [0.3 0.5 0.7] \"float roughness\" 0.1\n"
      << "Shape \"sphere\" \"float radius\" 0.6\nAttributeEnd\n"
      << "AttributeBegin Translate 0 0.9 1\n"
      << "Material \"conductor\" \"spectrum eta\" \"metal-Ag-eta\" \"spectrum k\" \"metal-Ag-k\""
         " \"float roughness\" 0\n"
      << "Shape \"sphere\" \"float radius\" 0.4\nAttributeEnd\n";
    return s.str();
}

struct Band {
    const char* film;
    double lambdaMin, lambdaMax, T;
};

// What ctest prints for a parameter (instead of its bytes)
inline void PrintTo(const Band& b, std::ostream* os) { *os << b.film << " at " << b.T << " K"; }

class ThermalCavity : public ::testing::TestWithParam<Band> {};

TEST_P(ThermalCavity, ReadsTheCavityTemperatureAndPlancksBandRadiance) {
    const Band& band = GetParam();
    testing::RenderedScene r = testing::RenderText(Cavity(band.film, band.T, 512));
    ExpectOnlyTheRGBWarning(r);
    const SpectralRange range = r.scene->spectralRange;
    EXPECT_NEAR(range.min, band.lambdaMin, 1e-3);
    EXPECT_NEAR(range.max, band.lambdaMax, 1e-3);
    const double Lb = planck_band_radiance(band.lambdaMin, band.lambdaMax, band.T);
    RunningStats L = ChannelStats(r, "L"), T = ChannelStats(r, "T");
    const double ratio = L.Mean() / Lb, se = L.StandardError() / Lb;
    // What a 1 % error in radiance makes of the temperature: d ln L / d ln T
    const double dLnL = planck_band_radiance(band.lambdaMin, band.lambdaMax, band.T * 1.001) / Lb;
    const double kelvinPerRelative = band.T * 0.001 / (dLnL - 1);
    std::printf("%s at %.0f K: L %.5f of Planck's (se %.5f), T %.3f K (se %.3f K)\n", band.film,
                band.T, ratio, se, T.Mean(), T.StandardError());
    EXPECT_LT(4 * se, 0.005);  // the test can see a 0.5 % error
    EXPECT_NEAR(ratio, 1, 4 * se + 1e-3);
    EXPECT_NEAR(T.Mean(), band.T, 4 * T.StandardError() + 1e-3 * kelvinPerRelative);
    // The temperature of the mean radiance, as a camera averaging the frame would report
    const ThermalSensor& sensor = *r.scene->job->film->Thermal();
    EXPECT_NEAR(sensor.ApparentTemperature(L.Mean()), band.T, (4 * se + 1e-3) * kelvinPerRelative);
}

INSTANTIATE_TEST_SUITE_P(
    Bands, ThermalCavity,
    ::testing::Values(Band{"Film \"thermal\" \"string sensor\" \"lwir\"", 8000, 14000, 300},
                      Band{"Film \"thermal\" \"string sensor\" \"mwir\"", 3000, 5000, 700},
                      Band{"Film \"thermal\" \"string sensor\" \"pyrometer\" "
                           "\"float wavelength\" 653",
                           648, 658, 2000},
                      Band{"Film \"thermal\" \"string sensor\" \"band\" \"float lambdamin\" 300 "
                           "\"float lambdamax\" 20000",
                           300, 20000, 1000}),
    [](const ::testing::TestParamInfo<Band>& info) {
        return std::to_string(int(info.param.lambdaMin)) + "_" +
               std::to_string(int(info.param.lambdaMax)) + "nm";
    });

// A sensor with a spectral response (a triangle over 7-13 um peaking at 10 um): the cavity reads
// the response-weighted Planck integral and its temperature; wavelengths are drawn in
// proportion to the response
TEST(ThermalFilm, ResponseSensorReadsTheCavity) {
    const double T = 300;
    testing::RenderedScene r = testing::RenderText(
        Cavity("Film \"thermal\" \"string sensor\" \"response\" \"spectrum response\" "
               "[7000 0 10000 1 13000 0]",
               T, 256));
    ExpectOnlyTheRGBWarning(r);
    const ThermalSensor& sensor = *r.scene->job->film->Thermal();
    ASSERT_TRUE(sensor.Response());
    EXPECT_EQ(r.scene->spectralRange.min, 7000);
    EXPECT_EQ(r.scene->spectralRange.max, 13000);
    // Drawn in proportion to the response (half) and to the response times Planck at 300 K
    // (half): nothing outside the band, nearly nothing at its ends, where the response is 0
    const WavelengthDistribution& d = r.scene->wavelengths;
    EXPECT_EQ(d.PDF(6000), 0);
    EXPECT_EQ(d.PDF(13500), 0);
    EXPECT_LT(d.PDF(7000.5f), 0.01 * d.PDF(10000));
    EXPECT_GT(d.PDF(8500), 0.3 * d.PDF(10000));
    const double Lb = sensor.Response()->BandRadiance(T);
    RunningStats L = ChannelStats(r, "L"), Tr = ChannelStats(r, "T");
    std::printf(
        "response 7-13 um at %.0f K: L %.5f of the Planck integral (se %.5f), T %.3f K "
        "(se %.3f K)\n",
        T, L.Mean() / Lb, L.StandardError() / Lb, Tr.Mean(), Tr.StandardError());
    EXPECT_LT(4 * L.StandardError() / Lb, 0.005);
    EXPECT_NEAR(L.Mean() / Lb, 1, 4 * L.StandardError() / Lb + 1e-3);
    EXPECT_NEAR(Tr.Mean(), T, 4 * Tr.StandardError() + 0.05);
}

// Wavelengths drawn in proportion to what the hot matter radiates over the band: a black plate
// at 1000 K filling a 300 nm - 20 um view, against uniform wavelengths ("wavelengthsampling"
// "visible"): the same mean, far less noise (measured: pixel standard deviation 0.28 of the
// uniform one at 4 spp)
TEST(ThermalFilm, WavelengthsFollowWhatTheHotMatterRadiates) {
    auto scene = [](const std::string& integrator) {
        return "Film \"thermal\" \"string sensor\" \"band\" \"float lambdamin\" 300 "
               "\"float lambdamax\" 20000 \"integer xresolution\" 32 \"integer yresolution\" 32\n"
               "Sampler \"zsobol\" \"integer pixelsamples\" 4\n" +
               integrator +
               "LookAt 0 0 -5  0 0 0  0 1 0\n"
               "Camera \"orthographic\" \"float screenwindow\" [-0.5 0.5 -0.5 0.5]\n"
               "WorldBegin\n"
               "Material \"diffuse\" \"spectrum reflectance\" [300 0 20000 0]\n"
               "Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0  1 -1 0  -1 1 0  1 1 0]"
               " \"float temperature\" 1000\n";
    };
    RunningStats hot = ChannelStats(testing::RenderText(scene("")), "L");
    RunningStats uniform =
        ChannelStats(testing::RenderText(
                         scene("Integrator \"path\" \"string wavelengthsampling\" \"visible\"\n")),
                     "L");
    const double Lb = planck_band_radiance(300, 20000, 1000);
    std::printf(
        "1000 K plate, 300 nm - 20 um: L %.5f (se %.5f) of Planck's, pixel deviation %.4f; "
        "uniform wavelengths %.5f (se %.5f), %.4f\n",
        hot.Mean() / Lb, hot.StandardError() / Lb, std::sqrt(hot.Variance()) / Lb,
        uniform.Mean() / Lb, uniform.StandardError() / Lb, std::sqrt(uniform.Variance()) / Lb);
    EXPECT_NEAR(hot.Mean() / Lb, 1, 4 * hot.StandardError() / Lb + 1e-3);
    EXPECT_NEAR(uniform.Mean() / Lb, 1, 4 * uniform.StandardError() / Lb + 1e-3);
    EXPECT_LT(std::sqrt(hot.Variance()), 0.5 * std::sqrt(uniform.Variance()));
}

// A grey plate (emissivity 0.4: diffuse reflectance 0.6) at 500 K inside a closed room at 300 K:
// it sends 0.4 Lb(500) of its own and 0.6 Lb(300) of the room's. An LWIR camera set to
// emissivity 0.4 and reflected temperature 300 K reads 500 K; set to emissivity 1 it reads the
// blackbody temperature of what arrives, lower.
TEST(ThermalFilm, EmissivitySettingAndReflectedTemperatureRecoverTheSurfaceTemperature) {
    auto scene = [](const std::string& settings) {
        return "Option \"float ambienttemperature\" 300\n"
               "Film \"thermal\" \"string sensor\" \"lwir\" " +
               settings +
               " \"integer xresolution\" 8 \"integer yresolution\" 8\n"
               "Sampler \"zsobol\" \"integer pixelsamples\" 64\n"
               "Integrator \"path\" \"integer maxdepth\" 100\n"
               "LookAt 0 0 -2  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 10\n"
               "WorldBegin\n"
               "Material \"diffuse\" \"rgb reflectance\" [0.6 0.6 0.6]\n"
               "Shape \"sphere\" \"float radius\" 20\n"
               "AttributeBegin\n"
               "Material \"diffuse\" \"rgb reflectance\" [0.6 0.6 0.6] \"float temperature\" 500\n"
               "Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0  1 -1 0  -1 1 0  1 1 0]\n"
               "AttributeEnd\n";
    };
    testing::RenderedScene set =
        testing::RenderText(scene("\"float emissivity\" 0.4 \"float reflectedtemperature\" 300"));
    ExpectOnlyTheRGBWarning(set);
    RunningStats T = ChannelStats(set, "T"), L = ChannelStats(set, "L");
    const double expected =
        0.4 * planck_band_radiance(8000, 14000, 500) + 0.6 * planck_band_radiance(8000, 14000, 300);
    std::printf("plate: L %.5f of expected (se %.5f), T %.3f K (se %.3f)\n", L.Mean() / expected,
                L.StandardError() / expected, T.Mean(), T.StandardError());
    EXPECT_NEAR(L.Mean() / expected, 1, 4 * L.StandardError() / expected + 1e-3);
    EXPECT_NEAR(T.Mean(), 500, 4 * T.StandardError() + 0.5);
    testing::RenderedScene plain = testing::RenderText(scene(""));
    double apparent = band_radiance_temperature(8000, 14000, expected);
    EXPECT_NEAR(ChannelStats(plain, "T").Mean(), apparent, 1);
    EXPECT_LT(apparent, 450);
}

// A picture format gets the temperature colour-mapped, with a scale bar on the right: the
// hottest pixel white, the coldest black, the bar's top white and its bottom black
TEST(ThermalFilm, PicturesMapTemperatureToColourWithAScaleBar) {
    testing::RenderedScene r = testing::RenderText(
        "Film \"thermal\" \"string sensor\" \"mwir\" \"integer xresolution\" 64 "
        "\"integer yresolution\" 32\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"orthographic\" \"float screenwindow\" [-2 2 -1 1]\n"
        "WorldBegin\n"
        "Material \"diffuse\" \"rgb reflectance\" [0 0 0]\n"
        "Shape \"bilinearmesh\" \"point3 P\" [-2 -1 0  0 -1 0  -2 1 0  0 1 0] "
        "\"float temperature\" 400\n"
        "Shape \"bilinearmesh\" \"point3 P\" [0 -1 0  2 -1 0  0 1 0  2 1 0] "
        "\"float temperature\" 900\n");
    namespace fs = std::filesystem;
    fs::path dir = fs::path(KILN_BINARY_DIR) / "test-output";
    fs::create_directories(dir);
    fs::path png = dir / "thermal-picture.png";
    r.scene->job->film->WriteImage(png.string(), ImageMetadata());
    Image picture = Image::Read(png.string());
    ASSERT_GT(picture.Resolution().x, 64);  // the bar
    EXPECT_EQ(picture.Resolution().y, 32);
    auto luminance = [&](int x, int y) {
        return picture.GetChannel({x, y}, 0) + picture.GetChannel({x, y}, 1) +
               picture.GetChannel({x, y}, 2);
    };
    EXPECT_LT(luminance(16, 16), 0.05f);  // 400 K: the coldest
    EXPECT_GT(luminance(48, 16), 2.9f);   // 900 K: the hottest
    int barX = picture.Resolution().x - 2;
    EXPECT_GT(luminance(barX, 8), luminance(barX, 16));
    EXPECT_GT(luminance(barX, 16), luminance(barX, 23));
}

// "scalemin" and "scalemax" fix the palette's span, as a camera's span and level: the same two
// plates then map inside it (neither black nor white), and the EXR carries the span so that
// kiln convert draws the same picture
TEST(ThermalFilm, PicturesKeepAFixedScale) {
    testing::RenderedScene r = testing::RenderText(
        "Film \"thermal\" \"string sensor\" \"mwir\" \"integer xresolution\" 64 "
        "\"integer yresolution\" 32 \"float scalemin\" 300 \"float scalemax\" 1000\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"orthographic\" \"float screenwindow\" [-2 2 -1 1]\n"
        "WorldBegin\n"
        "Material \"diffuse\" \"spectrum reflectance\" [300 0 20000 0]\n"
        "Shape \"bilinearmesh\" \"point3 P\" [-2 -1 0  0 -1 0  -2 1 0  0 1 0] "
        "\"float temperature\" 400\n"
        "Shape \"bilinearmesh\" \"point3 P\" [0 -1 0  2 -1 0  0 1 0  2 1 0] "
        "\"float temperature\" 900\n");
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    namespace fs = std::filesystem;
    fs::path dir = fs::path(KILN_BINARY_DIR) / "test-output";
    fs::create_directories(dir);
    fs::path png = dir / "thermal-picture-scale.png", exr = dir / "thermal-picture-scale.exr";
    r.scene->job->film->WriteImage(png.string(), ImageMetadata());
    r.scene->job->film->WriteImage(exr.string(), ImageMetadata());
    Image picture = Image::Read(png.string());
    auto luminance = [&](int x, int y) {
        return picture.GetChannel({x, y}, 0) + picture.GetChannel({x, y}, 1) +
               picture.GetChannel({x, y}, 2);
    };
    // 400 K at 1/7 of the span, 900 K at 6/7: the palette there, not its ends
    auto palette = [](Float t) {
        RGB c = IronPalette(t);
        Float sum = 0;
        for (int i = 0; i < 3; ++i)
            sum += c[i] <= 0.04045f ? c[i] / 12.92f : std::pow((c[i] + 0.055f) / 1.055f, 2.4f);
        return sum;
    };
    EXPECT_NEAR(luminance(16, 16), palette(100.f / 700), 0.02f);
    EXPECT_NEAR(luminance(48, 16), palette(600.f / 700), 0.02f);
    EXPECT_GT(luminance(16, 16), 0.05f);
    EXPECT_LT(luminance(48, 16), 2.9f);
    ImageMetadata m;
    Image fromExr = Image::Read(exr.string(), &m);
    ASSERT_TRUE(m.strings.count("kiln:thermalscale"));
    std::optional<TemperatureScale> scale =
        ThermalSensor::ScaleFromSettings(m.strings["kiln:thermalscale"]);
    ASSERT_TRUE(scale);
    EXPECT_EQ(scale->lo, 300);
    EXPECT_EQ(scale->hi, 1000);
    Image again = ThermalPicture(fromExr, fromExr.ChannelIndex("T"), scale);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(again.GetChannel({16, 16}, c), picture.GetChannel({16, 16}, c), 0.01f);
}

// "stokes": the in-band Stokes components. A smooth metal plate (n = k = 3 at every
// wavelength) at 1000 K turned 60 degrees about the vertical, seen through a 2 um pyrometer
// with nothing else in the scene, emits (1 - Rs) and (1 - Rp) of Planck's radiance polarised
// across and along its plane of emission (horizontal here): S1 / S0 = (Rs - Rp) / (2 - Rs -
// Rp), S2 = S3 = 0, S0 = L.
TEST(ThermalFilm, StokesLayersHoldThePolarisedEmission) {
    testing::RenderedScene r = testing::RenderText(
        "Film \"thermal\" \"string sensor\" \"pyrometer\" \"float wavelength\" 2000 "
        "\"integer xresolution\" 8 \"integer yresolution\" 8 \"bool stokes\" true\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
        "Integrator \"path\" \"integer maxdepth\" 1\n"
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"orthographic\" \"float screenwindow\" [-0.2 0.2 "
        "-0.2 0.2]\n"
        "WorldBegin\n"
        "Rotate 60 0 1 0\n"
        "Material \"conductor\" \"spectrum eta\" [300 3 20000 3] \"spectrum k\" [300 3 20000 3] "
        "\"float roughness\" 0\n"
        "Shape \"bilinearmesh\" \"point3 P\" [-2 -2 0  2 -2 0  -2 2 0  2 2 0] "
        "\"float temperature\" 1000\n");
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    ASSERT_TRUE(r.scene->features.polarized);
    Image img = r.scene->job->film->GetImage(nullptr);
    int S[4], L = img.ChannelIndex("L");
    for (int k = 0; k < 4; ++k) {
        S[k] = img.ChannelIndex("S" + std::to_string(k));
        ASSERT_GE(S[k], 0) << k;
    }
    std::complex<double> eta(3, 3);
    double cosI = 0.5, sin2 = 0.75;
    std::complex<double> cosT = std::sqrt(1.0 - sin2 / (eta * eta));
    double Rs = std::norm((cosI - eta * cosT) / (cosI + eta * cosT));
    double Rp = std::norm((eta * cosI - cosT) / (eta * cosI + cosT));
    double expected = (Rs - Rp) / (2 - Rs - Rp);
    RunningStats s1, s2, s3;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            double s0 = img.GetChannel({x, y}, S[0]);
            EXPECT_EQ(s0, img.GetChannel({x, y}, L));
            s1.Add(img.GetChannel({x, y}, S[1]) / s0);
            s2.Add(img.GetChannel({x, y}, S[2]) / s0);
            s3.Add(img.GetChannel({x, y}, S[3]) / s0);
        }
    std::printf("stokes at 60 degrees: s1 %.5f (expected %.5f), s2 %.5f, s3 %.5f\n", s1.Mean(),
                expected, s2.Mean(), s3.Mean());
    EXPECT_NEAR(s1.Mean(), expected, 1e-3);
    EXPECT_GT(expected, 0.1);
    EXPECT_NEAR(s2.Mean(), 0, 1e-3);
    EXPECT_NEAR(s3.Mean(), 0, 1e-3);
}

// The parameters are checked where they are written
TEST(ThermalFilm, BadParametersAreLocatedErrors) {
    auto error = [](const std::string& film) -> std::string {
        Diagnostics diag(nullptr);
        try {
            testing::BuildScene(film + "\nWorldBegin\n", diag);
        } catch (const SceneError& e) {
            return e.Message() + " [" + e.Token() + "] line " + std::to_string(e.Loc().line);
        }
        return "";
    };
    EXPECT_NE(error("Film \"thermal\" \"string sensor\" \"xray\"").find("unknown thermal sensor"),
              std::string::npos);
    EXPECT_NE(error("Film \"thermal\" \"string sensor\" \"pyrometer\"").find("wavelength"),
              std::string::npos);
    EXPECT_NE(error("Film \"thermal\" \"string sensor\" \"pyrometer\" \"float wavelength\" 100")
                  .find("300 nm - 20 um"),
              std::string::npos);
    EXPECT_NE(error("Film \"thermal\" \"float emissivity\" 0").find("emissivity"),
              std::string::npos);
    EXPECT_NE(error("Film \"thermal\" \"string filename\" \"a.pfm\"").find("EXR"),
              std::string::npos);
    EXPECT_NE(error("Film \"thermal\" \"string sensor\" \"band\" \"float lambdamin\" 900 "
                    "\"float lambdamax\" 800")
                  .find("lambdamin"),
              std::string::npos);
    EXPECT_NE(error("Film \"thermal\"\n  \"bool writeaovs\" true").find("line 2"),
              std::string::npos);
    EXPECT_NE(error("Film \"thermal\" \"float scalemin\" 300").find("both"), std::string::npos);
    EXPECT_NE(error("Film \"thermal\" \"float scalemin\" 300 \"float scalemax\" 300")
                  .find("scalemin < scalemax"),
              std::string::npos);
}

}  // namespace
}  // namespace kiln
