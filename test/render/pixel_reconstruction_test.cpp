// Pixel reconstruction in renders (PixelReconstruction, Film "string reconstruction"): samples
// spread over the pixels within the filter's radius (default) estimate the same image as pbrt-v4's
// filter importance sampling with less per-pixel noise, reach the image's border pixels from the
// margin beyond it as pbrt-v4's filter offsets do, and give the same pixels whatever the number
// of threads.
#include <gtest/gtest.h>

#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// A floor and a ball lit by a distant light and a sky under pbrt-v4's default Gaussian filter
// (no emitter in view: the noise is the sky's, independent from sample to sample); `film` goes
// on the Film line
std::string LitFloor(const std::string& film, int seed) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24 " << film << "\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 16 \"integer seed\" " << seed << "\n"
      << "Integrator \"path\" \"integer maxdepth\" 3\n"
      << "LookAt 0 2.5 -3.5  0 0 -1  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
      << "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]\n"
      << "LightSource \"distant\" \"point3 from\" [1 3 1] \"point3 to\" [0 0 0] \"rgb L\" [2 2 2]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
         "[-4 0 -4 4 0 -4 4 0 4 -4 0 4]\n"
      << "AttributeBegin\nTranslate 0.2 0.4 -1\nShape \"sphere\" \"float radius\" 0.4\n"
         "AttributeEnd\n";
    return s.str();
}

const char* const kImportance = "\"string reconstruction\" \"importance\"";

TEST(PixelReconstruction, SpreadByDefaultAndSwitchable) {
    testing::ExpectSwitch(LitFloor, kImportance, &SceneFeatures::spreadSamples,
                          &RenderOptions::spreadSamples);
    // A later job of the same scene (Scene::SetJob) may ask for the other
    testing::RenderedScene r = testing::RenderText(LitFloor("", 1));
    Diagnostics diag(nullptr);
    RenderOptions importance;
    importance.spreadSamples = false;
    r.scene->SetJob(importance, diag);
    EXPECT_FALSE(r.scene->features.spreadSamples);
    EXPECT_EQ(r.scene->job->film->Reconstruction(), PixelReconstruction::FilterImportance);
    r.scene->SetJob(RenderOptions{}, diag);
    EXPECT_TRUE(r.scene->features.spreadSamples);
}

// The Gaussian's per-pixel variance for independent sample noise is integral(f^2) /
// integral(f)^2 = 0.34 of filter importance sampling's (measured here 0.3-0.4)
TEST(PixelReconstruction, SameImageAsImportanceSamplingWithLessNoise) {
    testing::ExpectSameImageWithLessNoise("lit floor", LitFloor, kImportance, 0.5);
}

// An orthographic view of 20 x 20 pixels, 0.1 units each, of a black background with an
// emitter ending `gap` pixels beyond the image's left edge: only the filter reaches it, from the
// border column
std::string EmitterBeyondTheEdge(const std::string& film, int seed) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 20 \"integer yresolution\" 20 " << film << "\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 64 \"integer seed\" " << seed << "\n"
      << "Integrator \"path\" \"integer maxdepth\" 1\n"
      << "LookAt 0 0 -5  0 0 0  0 1 0\n"
      << "Camera \"orthographic\" \"float screenwindow\" [-1 1 -1 1]\n"
      << "WorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1] "
         "\"bool twosided\" true\n"
      // x from -3 to -1.02 and from 1.02 to 3: 0.2 pixels beyond the left and right edges
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
         "[-3 -2 0 -1.02 -2 0 -1.02 2 0 -3 2 0]\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" "
         "[1.02 -2 0 3 -2 0 3 2 0 1.02 2 0]\n"
      << "AttributeEnd\n";
    return s.str();
}

TEST(PixelReconstruction, BorderPixelsSeeBeyondTheEdgeAsImportanceSamplingDoes) {
    // The mean of the two border columns over seeds, both ways
    auto borderMean = [](const std::string& film, int seed) {
        testing::RenderedScene r = testing::RenderText(EmitterBeyondTheEdge(film, seed));
        double sum = 0;
        for (int y = 0; y < 20; ++y)
            for (int x : {0, 19}) sum += testing::PixelY(*r.scene, {x, y});
        // The columns beyond the border ones see nothing
        EXPECT_EQ(testing::PixelY(*r.scene, {2, 10}), 0);
        return sum / 40;
    };
    RunningStats spread, importance;
    for (int seed = 1; seed <= 6; ++seed) {
        spread.Add(borderMean("", seed));
        importance.Add(borderMean(kImportance, seed));
    }
    double se = std::hypot(spread.StandardError(), importance.StandardError());
    std::printf("border columns: spread %.5f, importance %.5f (standard error %.5f)\n",
                spread.Mean(), importance.Mean(), se);
    // pbrt-v4's Gaussian reaches 0.2 pixels beyond the edge from the border pixel's centre 0.5
    // inside: a few per cent of the emitter's luminance
    EXPECT_GT(importance.Mean(), 0.005);
    EXPECT_NEAR(spread.Mean(), importance.Mean(), 5 * se + 1e-3 * importance.Mean());
}

TEST(PixelReconstruction, SamePixelsWhateverTheThreads) {
    // Spread samples reach neighbouring tiles' pixels; tiles in four phases keep threads apart,
    // so every pixel adds the same samples in the same order
    testing::RenderedScene one = testing::RenderText(LitFloor("", 3), 1);
    testing::RenderedScene two = testing::RenderText(LitFloor("", 3), 2);
    ASSERT_TRUE(one.scene->features.spreadSamples);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            RGB a = one.scene->job->film->GetPixelRGB({x, y}),
                b = two.scene->job->film->GetPixelRGB({x, y});
            ASSERT_EQ(a.r, b.r) << x << "," << y;
            ASSERT_EQ(a.g, b.g) << x << "," << y;
            ASSERT_EQ(a.b, b.b) << x << "," << y;
        }
}

}  // namespace
}  // namespace kiln
