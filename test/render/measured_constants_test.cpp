// A conductor given n and k measured at several temperatures ("string nkfiles", "float
// nktemperatures"): a smooth plate at a temperature between two measurements emits
// (1 - R) B with R the Fresnel reflectance of the permittivity interpolated between them, and
// so scatters; bad input is an error at the parameter. (The closed cavity holds such a metal
// too: equilibrium_test.cpp.) The metal is a made-up one (test/render/data).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "base/statistics.h"
#include "render_test_util.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

const std::string kFiles = "\"string nkfiles\" [\"" KILN_SOURCE_DIR
                           "/test/render/data/fictional_metal_300K.csv\" \"" KILN_SOURCE_DIR
                           "/test/render/data/fictional_metal_1500K.csv\"] "
                           "\"float nktemperatures\" [300 1500]";

// Head-on at 900 K (halfway) through a 600 nm pyrometer, nothing else in the scene
TEST(MeasuredConstants, PlateEmitsWithThePermittivityBetweenItsMeasurements) {
    const double T = 900;
    testing::RenderedScene r = testing::RenderText(
        "Film \"thermal\" \"string sensor\" \"pyrometer\" \"float wavelength\" 600 "
        "\"integer xresolution\" 16 \"integer yresolution\" 16\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
        "LookAt 0 0 -5  0 0 0  0 1 0\n"
        "Camera \"orthographic\" \"float screenwindow\" [-0.5 0.5 -0.5 0.5]\n"
        "WorldBegin\n"
        "Material \"conductor\" " +
        kFiles +
        " \"float roughness\" 0\n"
        "Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0  1 -1 0  -1 1 0  1 1 0] "
        "\"float temperature\" 900\n");
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    // The files' rows at 600 nm: 0.8 + 3.5i at 300 K, 1.1 + 3.0i at 1500 K
    std::complex<double> cold(0.8, 3.5), hot(1.1, 3.0);
    std::complex<double> n = std::sqrt(0.5 * (cold * cold + hot * hot));
    double R = std::norm((n - 1.0) / (n + 1.0));
    double expected = (1 - R) * planck_band_radiance(595, 605, T);
    RunningStats L = testing::ThermalChannelStats(r, "L");
    double ratio = L.Mean() / expected, se = L.StandardError() / expected;
    std::printf("measured constants at 900 K: L %.5f of (1 - R) B (se %.5f), R %.4f\n", ratio, se,
                R);
    EXPECT_LT(4 * se, 0.005);
    // 1e-3 for the table (the band's 10 nm, the wavelength grid)
    EXPECT_NEAR(ratio, 1, 4 * se + 2e-3);
    // Not the constants of either measurement
    for (std::complex<double> m : {cold, hot}) {
        double Rm = std::norm((m - 1.0) / (m + 1.0));
        EXPECT_GT(std::abs((1 - Rm) / (1 - R) - 1), 0.02);
    }
}

TEST(MeasuredConstants, BadInputIsAnErrorAtTheParameter) {
    auto error = [](const std::string& material) -> std::string {
        Diagnostics diag(nullptr);
        try {
            testing::BuildScene(
                "WorldBegin\nMaterial \"conductor\"\n  " + material + "\nShape \"sphere\"\n", diag);
        } catch (const SceneError& e) {
            return e.Message() + " [" + e.Token() + "] line " + std::to_string(e.Loc().line);
        }
        return "";
    };
    const std::string one = "\"string nkfiles\" [\"" KILN_SOURCE_DIR
                            "/test/render/data/fictional_metal_300K.csv\"] "
                            "\"float nktemperatures\" [300]";
    EXPECT_NE(error(one).find("two or more files"), std::string::npos);
    EXPECT_NE(error(one).find("line 3"), std::string::npos);
    std::string swapped = kFiles;
    swapped.replace(swapped.find("[300 1500]"), 10, "[1500 300]");
    EXPECT_NE(error(swapped).find("increasing"), std::string::npos);
    EXPECT_NE(error(kFiles + " \"spectrum eta\" \"metal-Au-eta\"").find("takes no \"eta\""),
              std::string::npos);
    std::string missing = kFiles;
    missing.replace(missing.find("1500K.csv"), 9, "2000K.csv");
    EXPECT_NE(error(missing).find("fictional_metal_2000K.csv"), std::string::npos);
}

}  // namespace
}  // namespace kiln
