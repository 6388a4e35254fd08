// Every scene in scenes/ rendered with polarised transport (--stokes) has the intensity S0 of
// the unpolarised render, within the Monte Carlo noise: K polarised renders with independent
// seeds against one unpolarised render of K x more samples per pixel, compared per pixel by
// noise_comparison.h, over the central part of the image. (Polarisation changes S0 only through
// reflections of polarised light, which these scenes have little of: smooth metals that
// reflect each other's polarised glow.) Scenes with Stokes output are compared with their
// unpolarised render without it; scenes with a polariser (scenes/polarization/fig8-*) have no
// unpolarised counterpart and are skipped here (test/render/polarized_render_test.cpp covers
// them).
#include <gtest/gtest.h>

#include "noise_comparison.h"
#include "scene_window.h"

namespace kiln {
namespace {

constexpr int kSeeds = 8, kSpp = 4, kReferenceSpp = 128;

// The render of a window of the scene, polarised (Stokes output) or not; nothing if the scene
// selects polarised transport by itself (a polariser) and stokes is false.
std::optional<Image> RenderWindow(const std::string& file, const Bounds2f& window, bool stokes,
                                  int spp, int seed) {
    SceneOverrides o;
    o.stokes = stokes;
    auto edit = [&](SceneDescription& d) {
        if (stokes) return;
        // The unpolarised render of a scene that asks for Stokes output
        ParsedParameter off;
        off.type = "bool";
        off.name = "stokes";
        off.bools = {false};
        d.film.parameters.Set(off);
    };
    auto accept = [&](const Scene& scene) {
        EXPECT_TRUE(scene.features.polarized || !stokes);
        return stokes || !scene.features.polarized;
    };
    return testing::RenderSceneWindow(file, window, spp, seed, o, edit, accept);
}

}  // namespace

TEST(PolarizedScenes, IntensityMatchesTheUnpolarisedRender) {
    std::vector<std::string> files = testing::SceneFiles();
    ASSERT_GE(files.size(), 30u);
    for (const std::string& file : files) {
        SCOPED_TRACE(file);
        // The centre of the image, or below it where the centre is black (the ring on black
        // glass)
        Bounds2f window{{0.45f, 0.45f}, {0.55f, 0.55f}};
        std::optional<Image> reference = RenderWindow(file, window, false, kReferenceSpp, 1000);
        if (reference && testing::IsBlack(*reference)) {
            window = Bounds2f{{0.45f, 0.7f}, {0.55f, 0.8f}};
            reference = RenderWindow(file, window, false, kReferenceSpp, 1000);
        }
        if (!reference) {
            std::printf("%s: polarised by itself, skipped\n",
                        std::filesystem::path(file).filename().c_str());
            continue;
        }
        std::vector<Image> renders;
        for (int k = 0; k < kSeeds; ++k)
            renders.push_back(*RenderWindow(file, window, true, kSpp, k + 1));
        testing::NoiseComparison c =
            testing::CompareWithNoise(renders, *reference, kSpp, kReferenceSpp);
        EXPECT_TRUE(c.Pass()) << c;
        // The comparison can see a 10 % error in intensity (most scenes 5 %; lava.pbrt, the
        // noisiest, not at these sample counts)
        EXPECT_FALSE(
            testing::CompareWithNoise(renders, *reference, kSpp, kReferenceSpp, 4, 1.1).Pass());
        std::printf("%s: %s\n", std::filesystem::path(file).filename().c_str(),
                    ::testing::PrintToString(c).c_str());
    }
}

}  // namespace kiln
