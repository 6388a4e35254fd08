// Misspelled names stop the scene with the nearest name, as pbrt-v4 stops at them, instead of
// rendering a cold or empty scene: a parameter nobody knows ("temprature"), a shape
// ("spheer"), a material ("condutor"), an integrator ("volpth"). pbrt-v4 names kiln does not
// implement stay warnings.
#include <gtest/gtest.h>

#include "core/parser/parser.h"
#include "render/scene.h"
#include "render/scene_builder.h"

namespace kiln {
namespace {

// The error creating the scene gives ("" if none), and the warnings in *warnings
std::string ErrorOf(const std::string& world, std::string* warnings = nullptr,
                    const std::string& options = "") {
    std::ostringstream log;
    Diagnostics diag(&log);
    try {
        SceneBuilder builder(diag);
        ParseString(builder,
                    options +
                        "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                        "Camera \"perspective\"\nWorldBegin\n" +
                        world,
                    diag, "<test>");
        Scene::Create(builder.Description(), RenderOptions{}, diag);
    } catch (const SceneError& e) {
        return e.what();
    }
    if (warnings) *warnings = log.str();
    return "";
}

TEST(Misspellings, StopTheSceneWithTheNearestName) {
    EXPECT_EQ(ErrorOf("Material \"diffuse\" \"float temprature\" 1400\nShape \"sphere\"\n"),
              "<test>:4:20: error: unknown parameter 'float temprature'; did you mean "
              "\"temperature\"? (at 'temprature')");
    EXPECT_EQ(ErrorOf("Shape \"spheer\"\n"),
              "<test>:4:1: error: unknown shape \"spheer\"; did you mean \"sphere\"? (at "
              "'spheer')");
    EXPECT_NE(
        ErrorOf("Material \"condutor\"\nShape \"sphere\"\n").find("did you mean \"conductor\"?"),
        std::string::npos);
    EXPECT_NE(ErrorOf("Shape \"sphere\"\n", nullptr, "Integrator \"volpth\"\n")
                  .find("unknown integrator \"volpth\"; did you mean \"volpath\"?"),
              std::string::npos);
    EXPECT_NE(ErrorOf("Shape \"sphere\" \"float radiuss\" 2\n").find("did you mean \"radius\"?"),
              std::string::npos);
}

TEST(Misspellings, PbrtV4NamesKilnLacksStayWarnings) {
    std::string warnings;
    // lightpath renders as volpath; "diagonal" is a film parameter used in the wrong place here
    EXPECT_EQ(ErrorOf("Shape \"sphere\" \"float diagonal\" 35\n", &warnings,
                      "Integrator \"lightpath\"\n"),
              "");
    EXPECT_NE(warnings.find("integrator \"lightpath\" is not supported"), std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("unused parameter 'float diagonal'"), std::string::npos) << warnings;
}

}  // namespace
}  // namespace kiln
