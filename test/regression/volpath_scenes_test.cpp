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
    ASSERT_GE(testing::SceneFiles().size(), 30u);
    EXPECT_GE(testing::CompareEveryScene(RenderWindow), 30);  // scenes with media are skipped
}

}  // namespace kiln
