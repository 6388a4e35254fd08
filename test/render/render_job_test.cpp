// A loaded scene re-rendered as new jobs (Scene::SetJob: samples per pixel, seed, crop window,
// pixel bounds) or moved to another frame (Scene::SetAnimation) renders exactly what a fresh
// load of the same file with those options renders, gives back its film's memory, and keeps its
// job when a new one is invalid.
#include <gtest/gtest.h>

#include "lights/thermal_area_light.h"
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

// Temperatures that follow the animation: a keyframed ramp across a sphere (its power is
// sampled by position and changes with the frame) and a cooling disk
const char* kAnimatedScene =
    "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 16\n"
    "Sampler \"independent\" \"integer pixelsamples\" 4\n"
    "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 45\n"
    "WorldBegin\n"
    "Texture \"ramp\" \"float\" \"gradient\" \"point3 p0\" [-1 0 0] \"point3 p1\" [1 0 0]"
    " \"float t0\" 0.5 \"float t1\" 1\n"
    "Texture \"peak\" \"float\" \"keyframes\" \"float times\" [0 1] \"float values\" [900 2000]\n"
    "Texture \"heat\" \"float\" \"scale\" \"texture tex\" \"ramp\" \"texture scale\" \"peak\"\n"
    "Texture \"cool\" \"float\" \"cooling\" \"float T0\" 1800 \"float mass\" 0.2"
    " \"float area\" 0.1\n"
    "Material \"conductor\" \"float roughness\" 0.2 \"texture temperature\" \"heat\"\n"
    "Shape \"sphere\" \"float radius\" 1\n"
    "Material \"diffuse\" \"texture temperature\" \"cool\"\n"
    "AttributeBegin Translate 1.5 0.5 0 Shape \"disk\" \"float radius\" 0.5 AttributeEnd\n";

RenderOptions AtFrame(int frame) {
    RenderOptions o;
    o.frame = frame;
    o.timeSeconds = frame / Float(4);
    return o;
}

TEST(RenderJob, NewFramesRenderWhatFreshLoadsOfThoseFramesRender) {
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> scene = testing::BuildScene(kAnimatedScene, diag, AtFrame(0));
    ASSERT_EQ(scene->animatedFields.size(), 2u);
    ASSERT_FALSE(scene->varyingThermalLights.empty());
    auto power = [&] {
        Float p = 0;
        for (const ThermalAreaLight* l : scene->varyingThermalLights) p += l->BandPower();
        return p;
    };
    Float power0 = power();
    Image frame0 = RenderJob(*scene);
    for (int f : {3, 1}) {
        Diagnostics fresh(nullptr);
        std::unique_ptr<Scene> loaded = testing::BuildScene(kAnimatedScene, fresh, AtFrame(f));
        scene->SetAnimation({AtFrame(f).frame, AtFrame(f).timeSeconds});
        scene->SetJob(AtFrame(f), diag);
        ExpectIdentical(RenderJob(*scene), RenderJob(*loaded));
    }
    EXPECT_NE(power(), power0);  // the lights estimated their power again
    // And back to frame 0
    scene->SetAnimation({0, Float(0)});
    scene->SetJob(AtFrame(0), diag);
    ExpectIdentical(RenderJob(*scene), frame0);
    EXPECT_EQ(power(), power0);
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

// RenderSettings::afterWave sees the film after every wave: each time it holds exactly what a
// render with that many samples per pixel holds (in a scene without filtered textures, whose
// footprints depend on the samples per pixel, as in pbrt-v4); maxWaveSize 1 gives a call per
// sample count
TEST(RenderWaves, AfterEveryWaveTheFilmIsARenderOfThatManySamples) {
    Diagnostics diag(nullptr);
    RenderOptions o = AtFrame(0);
    o.samplesPerPixel = 12;
    std::unique_ptr<Scene> scene = testing::BuildScene(kAnimatedScene, diag, o);
    std::vector<int> completed;
    std::vector<Image> images;
    RenderSettings settings;
    settings.threads = 2;
    settings.afterWave = [&](int n) {
        completed.push_back(n);
        images.push_back(scene->job->film->GetImage(nullptr));
    };
    Render(*scene, settings);
    EXPECT_EQ(completed, (std::vector<int>{1, 3, 7, 12}));  // waves of 1, 2, 4, 5
    for (size_t i = 0; i < completed.size(); ++i) {
        RenderOptions fewer = AtFrame(0);
        fewer.samplesPerPixel = completed[i];
        Diagnostics d(nullptr);
        std::unique_ptr<Scene> fresh = testing::BuildScene(kAnimatedScene, d, fewer);
        ExpectIdentical(images[i], RenderJob(*fresh));
    }
    // One sample per wave
    scene->SetJob(o, diag);
    completed.clear();
    settings.maxWaveSize = 1;
    Render(*scene, settings);
    EXPECT_EQ(completed.size(), 12u);
    EXPECT_EQ(completed.back(), 12);
    // A wave time limit no wave can meet (--display-server's, made tiny) also gives one sample
    // per wave after the first, and the image of the same samples
    scene->SetJob(o, diag);
    completed.clear();
    settings.maxWaveSize = 64;
    settings.waveSeconds = 1e-12;
    Render(*scene, settings);
    EXPECT_EQ(completed.size(), 12u);
    EXPECT_EQ(completed.back(), 12);
    ExpectIdentical(scene->job->film->GetImage(nullptr), images.back());
}

}  // namespace
}  // namespace kiln
