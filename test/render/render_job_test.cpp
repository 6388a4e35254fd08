// A loaded scene re-rendered as new jobs (Scene::SetJob: samples per pixel, seed, crop window,
// pixel bounds) renders exactly what a fresh load of the same file with those options renders,
// gives back its film's memory, and keeps its job when a new one is invalid.
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "render_test_util.h"

namespace kiln {
namespace {

// Hot textured metal and a filtered texture on a hot diffuse disk (footprints), an area light
const char* kScene =
    "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 16\n"
    "Sampler \"independent\" \"integer pixelsamples\" 4\n"
    "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 45\n"
    "WorldBegin\n"
    "Texture \"heat\" \"float\" \"checkerboard\" \"float uscale\" 6 \"float vscale\" 6"
    " \"float tex1\" 900 \"float tex2\" 1600\n"
    "Material \"conductor\" \"float roughness\" 0.2 \"texture temperature\" \"heat\"\n"
    "Shape \"sphere\" \"float radius\" 1\n"
    "Material \"diffuse\" \"texture temperature\" \"heat\"\n"
    "AttributeBegin Translate 1.5 0.5 0 Shape \"disk\" \"float radius\" 0.5 AttributeEnd\n"
    "AttributeBegin AreaLightSource \"diffuse\" \"rgb L\" [2 2 2]\n"
    "  Translate -1.5 1 -1 Shape \"sphere\" \"float radius\" 0.3 AttributeEnd\n";

Image RenderJob(Scene& scene) {
    RenderSettings settings;
    settings.threads = 2;
    Render(scene, settings);
    return scene.job->film->GetImage(nullptr);
}

Image Fresh(const RenderOptions& o) {
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(kScene, diag, o);
    return RenderJob(*scene);
}

void ExpectIdentical(const Image& a, const Image& b) {
    ASSERT_EQ(a.Resolution(), b.Resolution());
    ASSERT_EQ(a.NChannels(), b.NChannels());
    int differ = 0;
    for (int y = 0; y < a.Resolution().y; ++y)
        for (int x = 0; x < a.Resolution().x; ++x)
            for (int c = 0; c < a.NChannels(); ++c)
                differ += a.GetChannel({x, y}, c) != b.GetChannel({x, y}, c);
    EXPECT_EQ(differ, 0);
}

TEST(RenderJob, NewJobsRenderWhatFreshLoadsRender) {
    RenderOptions a;
    a.samplesPerPixel = 4;
    a.seed = 1;
    RenderOptions b;
    b.samplesPerPixel = 9;
    b.seed = 7;
    b.cropWindow = Bounds2f{{0.25f, 0.1f}, {0.8f, 0.9f}};
    RenderOptions c;
    c.samplesPerPixel = 2;
    c.seed = 3;
    c.pixelBounds = Bounds2i{{3, 2}, {17, 11}};

    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(kScene, diag, a);
    ASSERT_GE(scene->thermalEmitterCount, 2);
    ExpectIdentical(RenderJob(*scene), Fresh(a));
    scene->SetJob(b, diag);
    ExpectIdentical(RenderJob(*scene), Fresh(b));
    scene->SetJob(c, diag);
    ExpectIdentical(RenderJob(*scene), Fresh(c));
    // Back to the first job: the same image again (nothing carried over between jobs)
    scene->SetJob(a, diag);
    ExpectIdentical(RenderJob(*scene), Fresh(a));
}

TEST(RenderJob, ANewJobGivesBackTheOldFilmsMemory) {
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(kScene, diag);
    MemoryBudget& budget = scene->arena.Budget();
    double loaded = budget.Committed();
    double film = scene->job->chargedBytes;
    EXPECT_GT(film, 0);
    for (int k = 0; k < 20; ++k) {
        RenderOptions o;
        o.seed = k;
        scene->SetJob(o, diag);
    }
    EXPECT_DOUBLE_EQ(budget.Committed(), loaded);
    RenderOptions quarter;
    quarter.cropWindow = Bounds2f{{0, 0}, {0.5f, 0.5f}};
    scene->SetJob(quarter, diag);
    EXPECT_DOUBLE_EQ(budget.Committed(), loaded - film + scene->job->chargedBytes);
    EXPECT_LT(scene->job->chargedBytes, film);
}

TEST(RenderJob, AnInvalidJobIsAnErrorAndTheCurrentJobStays) {
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(kScene, diag);
    RenderOptions bad;
    bad.cropWindow = Bounds2f{{0.5f, 0.5f}, {0.5f, 0.9f}};  // no pixel
    const RGBFilm* before = scene->job->film;
    EXPECT_THROW(scene->SetJob(bad, diag), SceneError);
    EXPECT_EQ(scene->job->film, before);
    Image image = RenderJob(*scene);
    EXPECT_EQ(image.Resolution(), Point2i(24, 16));
}

}  // namespace
}  // namespace kiln
