// Magnitudes beyond single precision. Lights, emission images and media brighter than
// kMaxEmission (1e30 W m^-2 sr^-1 nm^-1, spectral/planck.h), RGBs whose spectrum overflows,
// lights whose power overflows and media whose extinction overflows used to render black
// images (the light sampler dropped lights of infinite power; NaN samples were discarded) or
// crash (a hair fibre's infinite absorption indexed the RGB-to-spectrum table out of range).
// Each is now an error at the parameter that made it so, or renders finite.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "../temp_dir.h"
#include "core/image/image.h"
#include "image_stats.h"
#include "spectral/color.h"
#include "spectral/spectrum.h"

namespace kiln::hostile_magnitudes {
namespace {

// World lines start at line 8
const char* kView = R"(
Film "rgb" "integer xresolution" 12 "integer yresolution" 12
Sampler "zsobol" "integer pixelsamples" 4
Integrator "volpath" "integer maxdepth" 4
LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
)";

const char* kSphere = "\nMaterial \"diffuse\" Shape \"sphere\" \"float radius\" 0.5\n";

std::string ErrorOf(const std::string& world) {
    try {
        testing::RenderStats(std::string(kView) + world + kSphere, 1, 4);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

void ExpectErrorAt(const std::string& world, const std::string& where, const std::string& text) {
    std::string error = ErrorOf(world);
    EXPECT_NE(error.find("<test>:" + where), std::string::npos) << world << "\n" << error;
    EXPECT_NE(error.find(text), std::string::npos) << world << "\n" << error;
}

void ExpectFiniteAndLit(const std::string& world) {
    testing::ImageStats r = testing::RenderStats(std::string(kView) + world + kSphere, 1, 4);
    EXPECT_EQ(r.nonFinite, 0) << world;
    EXPECT_EQ(r.nonFinitePixels, 0) << world;
    EXPECT_GT(r.meanY, 0) << world;
}

const char* kTooBright = "this light is too bright";

// A sphere of radius 0.7 holding the named medium, from a new line
std::string SphereFilledWith(const std::string& medium) {
    return "\nAttributeBegin MediumInterface \"" + medium +
           "\" \"\" Material \"interface\"\nShape \"sphere\" \"float radius\" 0.7 AttributeEnd";
}

TEST(HostileMagnitudes, LightsBrighterThanRenderableAreErrorsAtTheParameterThatSetsThem) {
    ExpectErrorAt(R"(LightSource "point" "rgb I" [3 3 3] "float scale" 1e38 "point3 from" [0 2 0])",
                  "8:37: error: " + std::string(kTooBright), "(at 'scale')");
    ExpectErrorAt(R"(LightSource "spot" "float power" 1e36 "point3 from" [0 2 0])",
                  "8:20:", "(at 'power')");
    ExpectErrorAt(R"(LightSource "distant" "blackbody L" 3000 "float illuminance" 1e34)",
                  "8:42:", "(at 'illuminance')");
    ExpectErrorAt(R"(LightSource "infinite" "rgb L" [1e31 1e31 1e31])", "8:24:", "(at 'L')");
    ExpectErrorAt(R"(AttributeBegin
AreaLightSource "diffuse" "float scale" 1e32
Translate 0 2 0 Shape "sphere" "float radius" 0.2
AttributeEnd)",
                  "9:27:", "(at 'scale')");
    // Not a number: an RGB beyond float's range as a light's colour
    ExpectErrorAt(R"(LightSource "point" "rgb I" [3e38 1 1] "point3 from" [0 2 0])",
                  "8:21:", "has a component above 1.7e38");
    // Just below the limit: finite and lit
    ExpectFiniteAndLit(
        R"(LightSource "point" "rgb I" [3 3 3] "float scale" 1e27 "point3 from" [0 2 0])");
    ExpectFiniteAndLit(R"(AttributeBegin
AreaLightSource "diffuse" "float scale" 1e27
Translate 0 2 0 Shape "sphere" "float radius" 0.2
AttributeEnd)");
}

TEST(HostileMagnitudes, MediaBrighterThanRenderableAreErrorsAtTheirEmission) {
    const std::string inside = SphereFilledWith("glow");
    ExpectErrorAt(R"(MakeNamedMedium "glow" "string type" "homogeneous" "rgb Le" [1e30 1e30 1e30]
    "float Lescale" 100 "rgb sigma_a" [1 1 1] "rgb sigma_s" [0 0 0])" +
                      inside,
                  "9:5:", "(at 'Lescale')");
    ExpectErrorAt(R"(MakeNamedMedium "glow" "string type" "uniformgrid" "integer nx" 2
    "float density" [1 1] "rgb Le" [1 1 1] "float Lescale" [1 1e33])" +
                      inside,
                  "9:44:", "(at 'Lescale')");
    // pbrt-v4's normalised blackbody grid: peak 1 times CIE_Y_integral (106.9) times Lescale
    ExpectErrorAt(R"(MakeNamedMedium "glow" "string type" "uniformgrid" "integer nx" 2
    "float density" [1 1] "float temperature" [1000 2000] "float Lescale" 1e29)" +
                      inside,
                  "9:59:", "this medium's emission is too bright");
    ExpectErrorAt(R"(MakeNamedMedium "glow" "string type" "rgbgrid" "integer nx" 1
    "rgb sigma_a" [1 1 1] "rgb Le" [2e30 1 1])" +
                      inside,
                  "9:27:", "(at 'Le')");
    ExpectFiniteAndLit(
        R"(MakeNamedMedium "glow" "string type" "homogeneous" "rgb Le" [1e25 1e25 1e25]
    "float Lescale" 100 "rgb sigma_a" [1 1 1] "rgb sigma_s" [0 0 0])" +
        inside);
}

TEST(HostileMagnitudes, MediaWhoseExtinctionOverflowsAreErrorsAtTheirParameters) {
    const std::string inside = SphereFilledWith("fog");
    // sigma_s below float's largest value, times a density of 5 beyond it
    ExpectErrorAt(R"(MakeNamedMedium "fog" "string type" "uniformgrid" "integer nx" 2
    "float density" [1 5] "rgb sigma_a" [1 1 1] "rgb sigma_s" [1e38 1 1])" +
                      inside,
                  "9:5:", "this medium's extinction");
    ExpectErrorAt(
        R"(MakeNamedMedium "fog" "string type" "homogeneous" "float scale" 1e31)" + inside,
        "8:51:", "(at 'scale')");
    ExpectErrorAt(R"(MakeNamedMedium "fog" "string type" "rgbgrid" "integer nx" 1
    "rgb sigma_a" [1 1 1] "rgb sigma_s" [3e30 1 1])" +
                      inside,
                  "9:27:", "(at 'sigma_s')");
    ExpectErrorAt(
        R"(MakeNamedMedium "fog" "string type" "cloud" "rgb sigma_s" [2e30 2e30 2e30])" + inside,
        "8:45:", "(at 'sigma_s')");
    // Dense but within the limit: finite (and dark, as the light cannot get in)
    testing::ImageStats dense = testing::RenderStats(std::string(kView) + R"(
LightSource "point" "rgb I" [3 3 3] "point3 from" [0 2 -1]
MakeNamedMedium "fog" "string type" "homogeneous" "float scale" 1e20 "rgb sigma_a" [0.1 0.1 0.1])" +
                                                         inside + kSphere,
                                                     1, 4);
    EXPECT_EQ(dense.nonFinite, 0);
    EXPECT_EQ(dense.nonFinitePixels, 0);
}

TEST(HostileMagnitudes, ExtinctionsOrdersOfMagnitudeApartAcrossWavelengthsRenderFinite) {
    // The feature scene's smoke (a 12^3 NanoVDB grid) with sigma_s 1e9 in green only: every
    // collision multiplied beta and the rescaled probabilities by up to 5e8 in green, and after
    // a few they overflowed together: 692 NaN samples of 16384 (pbrt-v4's volpath: NaN too).
    const std::string dir = std::string(KILN_SOURCE_DIR) + "/test/regression/pbrt_features/";
    std::ifstream in(dir + "nanovdb.pbrt");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto replace = [&](const std::string& from, const std::string& to) {
        size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("\"nanovdb.nvdb\"", "\"" + dir + "nanovdb.nvdb\"");
    replace("\"rgb sigma_s\" [2 2 2]", "\"rgb sigma_s\" [2 1e9 2]");
    // (Slow: where the hero wavelength is green, tentative collisions 1e-9 apart stall below
    // float's resolution of the ray parameter until SampleT_maj's cap; a part of the image
    // where the NaN were, at 1 sample: before, 10 of them were expected there)
    RenderOptions o;
    o.samplesPerPixel = 1;
    o.cropWindow = Bounds2f{Point2f(0.3f, 0), Point2f(0.65f, 0.32f)};
    testing::RenderedScene r = testing::RenderText(text, 0, o);
    EXPECT_EQ(r.scene->job->film->NonFiniteSampleCount(), 0);
}

TEST(HostileMagnitudes, NoiseOctavesBeyondSinglePrecisionAreAnError) {
    // wrinkled's aliased octaves were summed one by one: octaves 1e38 (2^31) never ended
    for (const char* texture : {"wrinkled", "fbm", "marble"})
        ExpectErrorAt(std::string("Texture \"t\" \"") +
                          (std::string(texture) == "marble" ? "spectrum" : "float") + "\" \"" +
                          texture + "\" \"integer octaves\" 100000",
                      "8:", "(at '100000')");
}

TEST(HostileMagnitudes, LightsWhosePowerOverflowsAreErrorsAtTheirDirective) {
    // Bright, not too bright, but a light source the size of a solar system
    ExpectErrorAt(R"(AttributeBegin
AreaLightSource "diffuse" "float scale" 1e25
Translate 0 0 1e12 Shape "sphere" "float radius" 1e10
AttributeEnd)",
                  "9:1:", "this light emits more power than single precision holds");
    ExpectErrorAt(R"(AttributeBegin
Material "diffuse" "float temperature" 1e26
Translate 0 0 1e13 Shape "sphere" "float radius" 1e12
AttributeEnd)",
                  "10:20:", "this hot shape radiates more power than single precision holds");
}

TEST(HostileMagnitudes, EmissionImagesAboveTheLimitAreErrorsAtTheirFile) {
    test::TempDir dir;
    Image bright(PixelFormat::Float, {4, 4}, {"R", "G", "B"});
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 3; ++c) bright.SetChannel({x, y}, c, 1);
    bright.SetChannel({1, 2}, 1, 3e38f);
    std::string file = (dir.path / "bright.exr").string();
    bright.Write(file);
    // With "power" the image's scale would not matter, but the light's scale would underflow
    for (const char* light : {"goniometric", "projection"})
        ExpectErrorAt(std::string("LightSource \"") + light + "\" \"string filename\" \"" + file +
                          "\" \"float power\" 10",
                      "8:", "image has pixels above 1e30");
    ExpectErrorAt("LightSource \"infinite\" \"string filename\" \"" + file + "\"",
                  "8:24:", "image has pixels above 1e30");
    // Negative values emit nothing, with a warning (as goniometric maps had)
    bright.SetChannel({1, 2}, 1, -2);
    std::string negative = (dir.path / "negative.exr").string();
    bright.Write(negative);
    for (const char* light : {"projection", "infinite"}) {
        testing::ImageStats r =
            testing::RenderStats(std::string(kView) + "LightSource \"" + light +
                                     "\" \"string filename\" \"" + negative + "\"" + kSphere,
                                 1, 1);
        ASSERT_EQ(r.warnings.size(), 1u) << light;
        EXPECT_NE(r.warnings[0].find("image has negative values"), std::string::npos);
    }
}

// A coat of negative thickness is an infinitely thin one: pbrt-v4 clamps the thickness to the
// smallest positive float, as kiln's layered BSDF did, but the hot materials' emissivity tables
// took it as given (a transmittance exp(1e38)), and every sample of a hot sphere with a
// coat of thickness -1e38 was NaN.
TEST(HostileMagnitudes, NegativeCoatThicknessIsAnInfinitelyThinCoatInEmissionToo) {
    for (std::string material : {"coateddiffuse", "coatedconductor"}) {
        auto render = [&](const char* thickness) {
            return testing::RenderStats(std::string(kView) + "Material \"" + material +
                                            "\" \"float roughness\" 0 \"float thickness\" " +
                                            thickness +
                                            "\nShape \"sphere\" \"float radius\" 0.5 "
                                            "\"float temperature\" 1500\n",
                                        1, 4);
        };
        testing::ImageStats negative = render("-1e38"), zero = render("0");
        EXPECT_EQ(negative.nonFinite, 0) << material;
        EXPECT_EQ(negative.nonFinitePixels, 0) << material;
        EXPECT_GT(negative.meanY, 0) << material;
        EXPECT_EQ(negative.meanY, zero.meanY) << material;
    }
}

// A film's iso is its gain: zero or negative gains gave black or negative images, and with
// bright light (a sphere at 1e9 K) -1e38 overflowed to NaN samples. An error at the parameter.
TEST(HostileMagnitudes, FilmSensitivityMustBePositiveAndFinite) {
    for (std::string iso : {"0", "-5", "-1e38", "100"}) {
        std::string text =
            "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
            "    \"float iso\" " +
            iso +
            "\nCamera \"perspective\"\nWorldBegin\n"
            "LightSource \"point\" \"point3 from\" [0 0 -2]\n"
            "Translate 0 0 1.2" +
            kSphere;
        std::string error;
        double meanY = 0;
        try {
            meanY = testing::RenderStats(text, 1, 1).meanY;
        } catch (const SceneError& e) {
            error = e.what();
        }
        if (iso == "100") {
            EXPECT_EQ(error, "");
            EXPECT_GT(meanY, 0);
            continue;
        }
        EXPECT_NE(error.find("<test>:2:"), std::string::npos) << iso << ": " << error;
        EXPECT_NE(error.find("iso must be positive and finite"), std::string::npos) << error;
    }
}

TEST(HostileMagnitudes, InfiniteAndNaNRGBsGiveSpectraWithoutNaN) {
    // A hair fibre of infinite absorption (melanin 3e38) crashed in the RGB-to-spectrum table
    const RGBColorSpace& cs = RGBColorSpace::sRGB();
    const Float inf = std::numeric_limits<Float>::infinity();
    for (RGB rgb : {RGB(inf, 1, 1), RGB(1, inf, 2), RGB(inf, inf, inf), RGB(3e38f, 3e38f, 1)}) {
        RGBUnboundedSpectrum s(cs, rgb);
        for (Float lambda = 360; lambda <= 830; lambda += 10) {
            EXPECT_FALSE(std::isnan(s(lambda))) << rgb.r << " " << rgb.g << " " << rgb.b;
            EXPECT_GT(s(lambda), 0);
        }
    }
    // Not-a-number components (an image texture's NaN pixel) read as 0, not out of the table
    const Float nan = std::numeric_limits<Float>::quiet_NaN();
    for (RGB rgb : {RGB(nan, 0.5f, 0.2f), RGB(nan, nan, nan), RGB(0.3f, nan, 1)}) {
        RGBAlbedoSpectrum s(cs, rgb);
        for (Float lambda = 360; lambda <= 830; lambda += 10) {
            EXPECT_GE(s(lambda), 0);
            EXPECT_LE(s(lambda), 1);
        }
    }
    // Such a fibre renders as one of finite, very strong absorption
    const char* hair = R"(LightSource "point" "rgb I" [3 3 3] "point3 from" [0 2 -1]
Material "hair" "float eumelanin" %s
Shape "curve" "point3 P" [-1 0.5 0 -0.3 0.6 0 0.3 0.4 0 1 0.5 0] "float width" 0.3
)";
    char strong[512], infinite[512];
    std::snprintf(strong, sizeof(strong), hair, "1e6");
    std::snprintf(infinite, sizeof(infinite), hair, "3e38");
    testing::ImageStats a = testing::RenderStats(std::string(kView) + strong, 1, 4);
    testing::ImageStats b = testing::RenderStats(std::string(kView) + infinite, 1, 4);
    EXPECT_EQ(b.nonFinite, 0);
    EXPECT_GT(b.meanY, 0);
    EXPECT_NEAR(b.meanY, a.meanY, 1e-4 * a.meanY);
}

}  // namespace
}  // namespace kiln::hostile_magnitudes
