// Every scene in scenes/ without participating media renders the same with the volumetric
// integrator (kiln --generic volpath) as with the path integrator kiln chooses for it, within
// the Monte Carlo noise: K volpath renders with independent seeds against one path render of
// K x more samples per pixel, compared per pixel by noise_comparison.h over the centre of the
// image. (VolPathIntegrator weighs emitters by spectral MIS with the balance heuristic where
// PathIntegrator uses the power heuristic: the estimators differ, their expectations must not.)
#include <gtest/gtest.h>

#include "noise_comparison.h"
#include "scene_window.h"

namespace kiln {
namespace {

constexpr int kSeeds = 8, kSpp = 4, kReferenceSpp = 128;

std::optional<Image> RenderWindow(const std::string& file, const Bounds2f& window, bool volpath,
                                  int spp, int seed) {
    SceneOverrides o;
    o.genericVolumes = volpath;
    auto accept = [&](const Scene& scene) {
        EXPECT_EQ(scene.features.volumetric, volpath || scene.features.media > 0);
        return scene.features.media == 0;
    };
    return testing::RenderSceneWindow(file, window, spp, seed, o, {}, accept);
}

}  // namespace

TEST(VolPathScenes, WithoutMediaVolPathRendersWhatPathRenders) {
    std::vector<std::string> files = testing::SceneFiles();
    ASSERT_GE(files.size(), 30u);
    int compared = 0;
    for (const std::string& file : files) {
        SCOPED_TRACE(file);
        Bounds2f window{{0.45f, 0.45f}, {0.55f, 0.55f}};
        std::optional<Image> reference = RenderWindow(file, window, false, kReferenceSpp, 1000);
        if (reference && testing::IsBlack(*reference)) {
            window = Bounds2f{{0.45f, 0.7f}, {0.55f, 0.8f}};
            reference = RenderWindow(file, window, false, kReferenceSpp, 1000);
        }
        if (!reference) continue;  // a scene with media
        std::vector<Image> renders;
        for (int k = 0; k < kSeeds; ++k)
            renders.push_back(*RenderWindow(file, window, true, kSpp, k + 1));
        testing::NoiseComparison c =
            testing::CompareWithNoise(renders, *reference, kSpp, kReferenceSpp);
        EXPECT_TRUE(c.Pass()) << c;
        // The comparison can see a 10 % error
        EXPECT_FALSE(
            testing::CompareWithNoise(renders, *reference, kSpp, kReferenceSpp, 4, 1.1).Pass());
        std::printf("%s: %s\n", std::filesystem::path(file).filename().c_str(),
                    ::testing::PrintToString(c).c_str());
        ++compared;
    }
    EXPECT_GE(compared, 30);
}

}  // namespace kiln
