// Render-level tests: determinism across thread counts, output round trip through
// OpenImageIO, and every scene in scenes/ rendering without warnings or NaNs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/image/image.h"
#include "render/auto_exposure.h"
#include "render_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

const char* kSmallScene = R"(
Film "rgb" "integer xresolution" 40 "integer yresolution" 30
Sampler "zsobol" "integer pixelsamples" 8
Integrator "path" "integer maxdepth" 6
LookAt 0 1 -6  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
LightSource "infinite" "rgb L" [0.2 0.25 0.3]
AttributeBegin
  AreaLightSource "diffuse" "blackbody L" 3000 "float scale" 8
  Translate 0 3 0
  Shape "sphere" "float radius" 0.5
AttributeEnd
Material "conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k" "float roughness" 0.1
Shape "sphere" "float radius" 0.8
Material "dielectric" "float eta" 1.5
Translate 1.5 0 0
Shape "sphere" "float radius" 0.5
Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
  "point3 P" [-10 -0.8 -10  10 -0.8 -10  10 -0.8 10  -10 -0.8 10]
)";

TEST(RenderTest, ImageIsIdenticalForOneAndTwoThreads) {
    testing::RenderedScene one = testing::RenderText(kSmallScene, 1);
    testing::RenderedScene two = testing::RenderText(kSmallScene, 2);
    Bounds2i b = one.scene->job->film->PixelBounds();
    int nonBlack = 0;
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) {
            RGB a = one.scene->job->film->GetPixelRGB({x, y}),
                c = two.scene->job->film->GetPixelRGB({x, y});
            ASSERT_EQ(a.r, c.r) << x << "," << y;
            ASSERT_EQ(a.g, c.g) << x << "," << y;
            ASSERT_EQ(a.b, c.b) << x << "," << y;
            nonBlack += (a.r + a.g + a.b) > 0;
        }
    EXPECT_GT(nonBlack, b.Area() / 2);  // the test would be vacuous on a black image
}

TEST(RenderTest, ExrOutputRoundTripsThroughOpenImageIO) {
    testing::RenderedScene r = testing::RenderText(kSmallScene, 2);
    fs::path dir = fs::path(KILN_BINARY_DIR) / "test-output";
    fs::create_directories(dir);
    fs::path exr = dir / "roundtrip.exr";
    ImageMetadata md;
    r.scene->job->film->WriteImage(exr.string(), md);
    Image img = Image::Read(exr.string());
    Bounds2i b = r.scene->job->film->PixelBounds();
    ASSERT_EQ(img.Resolution().x, b.pMax.x - b.pMin.x);
    ASSERT_EQ(img.Resolution().y, b.pMax.y - b.pMin.y);
    int R = img.ChannelIndex("R"), G = img.ChannelIndex("G"), B = img.ChannelIndex("B");
    ASSERT_GE(R, 0);
    ASSERT_GE(G, 0);
    ASSERT_GE(B, 0);
    for (int y = 0; y < img.Resolution().y; ++y)
        for (int x = 0; x < img.Resolution().x; ++x) {
            RGB want = r.scene->job->film->GetPixelRGB({x + b.pMin.x, y + b.pMin.y});
            // Half floats: 11 significant bits.
            EXPECT_NEAR(img.GetChannel({x, y}, R), want.r, 1e-3f + 1e-3f * std::abs(want.r));
            EXPECT_NEAR(img.GetChannel({x, y}, G), want.g, 1e-3f + 1e-3f * std::abs(want.g));
            EXPECT_NEAR(img.GetChannel({x, y}, B), want.b, 1e-3f + 1e-3f * std::abs(want.b));
        }
    // PNG output goes through the display transform: 8-bit, same size.
    fs::path png = dir / "roundtrip.png";
    r.scene->job->film->WriteImage(png.string(), md);
    Image display = Image::Read(png.string());
    EXPECT_EQ(display.Resolution().x, img.Resolution().x);
    EXPECT_EQ(display.NChannels() >= 3, true);
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

// Every top-level scene in scenes/: a .pbrt file with WorldBegin (or an Include), and every
// gzip-compressed .pbrt.gz (the showcase's largest scene).
std::vector<std::string> TopLevelScenes() {
    std::vector<std::string> scenes;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(KILN_SOURCE_DIR) / "scenes")) {
        std::string name = e.path().filename().string();
        if (name.size() > 8 && name.compare(name.size() - 8, 8, ".pbrt.gz") == 0) {
            scenes.push_back(e.path().string());
            continue;
        }
        if (e.path().extension() != ".pbrt") continue;
        std::ifstream in(e.path());
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.find("WorldBegin") != std::string::npos ||
            text.find("Include") != std::string::npos)
            scenes.push_back(e.path().string());
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

TEST(RenderTest, EveryBundledSceneRendersWithoutWarningsOrNaNs) {
    std::vector<std::string> scenes = TopLevelScenes();
    ASSERT_GE(scenes.size(), 3u);
    for (const std::string& file : scenes) {
        SCOPED_TRACE(file);
        Diagnostics diag(nullptr);
        SceneBuilder builder(diag);
        ParseFile(builder, file, diag);
        std::unique_ptr<Scene> scene = Scene::Create(builder.Description(), RenderOptions(), diag);
        // One sample per pixel in a window from (0.3, 0.3) of the image, 30 % of it on a side
        // and at most 64 x 64 pixels: fast whatever the scene's resolution (the sanitizer
        // stage runs this too)
        Point2i res = scene->job->film->FullResolution();
        Vector2f size(std::min(0.3f, 64.f / float(res.x)), std::min(0.3f, 64.f / float(res.y)));
        RenderOptions job;
        job.samplesPerPixel = 1;
        job.cropWindow = Bounds2f{Point2f(0.3f, 0.3f), Point2f(0.3f, 0.3f) + size};
        scene->SetJob(job, diag);
        RenderStats stats = Render(*scene, RenderSettings());
        for (const Diagnostics::Warning& w : diag.Warnings())
            ADD_FAILURE() << w.loc.ToString() << ": " << w.message;
        EXPECT_EQ(scene->job->film->NonFiniteSampleCount(), 0);
        EXPECT_GT(stats.cameraPaths, 0);
    }
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

TEST(RenderTest, AutoExposureBringsTheBrightPercentileToTheTarget) {
    testing::RenderedScene r = testing::RenderText(kSmallScene, 2);
    RGBFilm& film = *r.scene->job->film;
    Float ev = AutoExposureEV(film, 0.99f, 0.9f);
    EXPECT_TRUE(std::isfinite(ev));
    film.SetExposureEV(ev);
    std::vector<Float> Y;
    Bounds2i b = film.PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x)
            if (Float v = testing::PixelY(*r.scene, {x, y}); v > 0) Y.push_back(v);
    std::sort(Y.begin(), Y.end());
    EXPECT_NEAR(Y[size_t(0.99f * (Y.size() - 1))], 0.9f, 1e-3f);
    // Applying it again changes nothing: the estimate ignores the current exposure.
    EXPECT_NEAR(AutoExposureEV(film, 0.99f, 0.9f), ev, 1e-4f);
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

// Ctrl-C sets the render's cancel flag; the loop must stop, report it, and leave a film that
// can still be written (kiln then writes the image rendered so far).
TEST(RenderTest, CancelStopsTheRenderAndKeepsAWritableFilm) {
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(kSmallScene, diag);
    std::atomic<bool> cancel{true};
    RenderSettings settings;
    settings.cancel = &cancel;
    RenderStats stats = Render(*scene, settings);
    EXPECT_TRUE(stats.cancelled);
    EXPECT_EQ(stats.completedSamples, 0);
    EXPECT_EQ(stats.cameraPaths, 0);
    fs::path out = fs::path(KILN_BINARY_DIR) / "test-output" / "cancelled.exr";
    fs::create_directories(out.parent_path());
    scene->job->film->WriteImage(out.string(), ImageMetadata());
    EXPECT_TRUE(fs::exists(out));
}

}  // namespace
}  // namespace kiln
