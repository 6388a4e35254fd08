// kiln --frames A-B parses and creates the scene once and moves it from frame to frame
// (Scene::SetAnimation): every frame it writes is bit-identical to a run that renders that frame
// alone. The scene's temperatures follow the animation three ways: a heat-map sequence, a
// cooling curve and keyframes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app_test_util.h"
#include "core/image/image.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;
using testing::Q;

TEST(AnimationCLI, EveryFrameOfOneRunIsWhatARunOfThatFrameRenders) {
    fs::path dir = fs::path(::testing::TempDir()) / ("kiln_animation_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // A 4 x 4 heat map per frame, hotter each frame and hotter to the right
    for (int f = 0; f < 3; ++f) {
        Image heat(PixelFormat::Float, {4, 4}, {"Y"});
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) heat.SetChannel({x, y}, 0, Float(900 + 150 * f + 100 * x));
        heat.Write((dir / ("heat." + std::to_string(f) + ".exr")).string());
    }
    const std::string scene = (dir / "scene.pbrt").string();
    std::ofstream(scene)
        << "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 20\n"
           "Sampler \"independent\" \"integer pixelsamples\" 4\n"
           "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 50\nWorldBegin\n"
           "Texture \"heat\" \"float\" \"heatmap\" \"string filename\" \"heat.#.exr\"\n"
           "Texture \"cool\" \"float\" \"cooling\" \"float T0\" 1800 \"float mass\" 0.2"
           " \"float area\" 0.1\n"
           "Texture \"peak\" \"float\" \"keyframes\" \"float times\" [0 0.1]"
           " \"float values\" [700 1900]\n"
           "Material \"diffuse\" \"texture temperature\" \"heat\"\n"
           "AttributeBegin Translate -1.2 0 0 Shape \"bilinearmesh\" \"point3 P\""
           " [-1 -1 0 1 -1 0 -1 1 0 1 1 0] AttributeEnd\n"
           "Material \"conductor\" \"float roughness\" 0.3 \"texture temperature\" \"cool\"\n"
           "AttributeBegin Translate 1.2 0.5 0 Shape \"sphere\" \"float radius\" 0.5 AttributeEnd\n"
           "Material \"diffuse\" \"texture temperature\" \"peak\"\n"
           "AttributeBegin Translate 1.2 -0.7 0 Shape \"disk\" \"float radius\" 0.4 AttributeEnd\n";
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    std::string all = (dir / "all.#.exr").string();
    ASSERT_EQ(std::system(("cd " + Q(dir.string()) + " && " + Q(kiln) + " " + Q(scene) +
                           " --frames 0-2 --fps 20 --quiet -o " + Q(all))
                              .c_str()),
              0);
    std::vector<float> previous;
    for (int f = 0; f < 3; ++f) {
        std::string single = (dir / ("single" + std::to_string(f) + ".exr")).string();
        ASSERT_EQ(std::system(("cd " + Q(dir.string()) + " && " + Q(kiln) + " " + Q(scene) +
                               " --frames " + std::to_string(f) + "-" + std::to_string(f) +
                               " --fps 20 --quiet -o " + Q(single))
                                  .c_str()),
                  0);
        std::vector<float> pixels =
            testing::Pixels((dir / ("all." + std::to_string(f) + ".exr")).string());
        EXPECT_EQ(pixels, testing::Pixels(single)) << "frame " << f;
        EXPECT_NE(pixels, previous) << "frame " << f << " is the frame before it";
        previous = pixels;
    }
    // A frame whose heat map is missing stops the run with the file named, after the frames
    // before it were written
    fs::remove(dir / "heat.2.exr");
    std::string log = (dir / "log.txt").string();
    EXPECT_NE(std::system(("cd " + Q(dir.string()) + " && " + Q(kiln) + " " + Q(scene) +
                           " --frames 0-2 --fps 20 --quiet -o " + Q((dir / "b.#.exr").string()) +
                           " 2> " + Q(log))
                              .c_str()),
              0);
    EXPECT_TRUE(fs::exists(dir / "b.1.exr"));
    EXPECT_FALSE(fs::exists(dir / "b.2.exr"));
    EXPECT_NE(testing::ReadAll(log).find("heat.2.exr"), std::string::npos) << testing::ReadAll(log);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
