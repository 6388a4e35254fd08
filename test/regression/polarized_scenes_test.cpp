// Every scene in scenes/ rendered with polarised transport (--stokes) has the intensity S0 of
// the unpolarised render, within the Monte Carlo noise: K polarised renders with independent
// seeds against one unpolarised render of K x more samples per pixel, compared per pixel by
// noise_comparison.h, over the central part of the image. (Polarisation changes S0 only through
// reflections of polarised light, which these scenes have little of: smooth metals that
// reflect each other's polarised glow.) Scenes with Stokes output are compared with their
// unpolarised render without it; scenes with a polariser (scenes/polarization/fig8-*) have no
// unpolarised counterpart and are skipped here (test/render/polarized_render_test.cpp covers
// them), as are scenes with a thermal film (kept out for the suite's time; their Stokes layers
// are checked in test/render/thermal_film_test.cpp).
#include <gtest/gtest.h>

#include "noise_comparison.h"
#include "scene_window.h"

namespace kiln {
namespace {

// The scene loaded for polarised (Stokes output) or unpolarised transport; nothing if the scene
// selects polarised transport by itself (a polariser) and stokes is false, or has a thermal film.
std::unique_ptr<Scene> LoadPlainOrStokes(const std::string& file, bool stokes) {
    RenderOptions o;
    o.stokes = stokes;  // false: the unpolarised render of a scene that asks for Stokes output
    auto accept = [&](const Scene& scene) {
        if (scene.job->film->Thermal()) return false;
        EXPECT_TRUE(scene.features.polarized || !stokes);
        return stokes || !scene.features.polarized;
    };
    return testing::LoadScene(file, o, {}, accept);
}

}  // namespace

class PolarizedScenes : public ::testing::TestWithParam<std::string> {};

TEST(PolarizedSceneSet, CoversTheBundledScenes) { EXPECT_GE(testing::SceneFiles().size(), 30u); }

// The comparison can see a 10 % error in intensity (most scenes 5 %; lava.pbrt, the noisiest,
// not at these sample counts)
TEST_P(PolarizedScenes, IntensityMatchesTheUnpolarisedRender) {
    if (!testing::CompareScene(GetParam(), LoadPlainOrStokes, 4, 8, 128))
        GTEST_SKIP() << "no counterpart: the scene has a polariser or a thermal film";
}

INSTANTIATE_TEST_SUITE_P(Scenes, PolarizedScenes, ::testing::ValuesIn(testing::SceneFiles()),
                         testing::SceneTestName);

}  // namespace kiln
