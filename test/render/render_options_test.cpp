// RenderOptions reach the objects they choose, typed: the scene description stays as parsed
// (nothing is written back into it as scene-file parameters), and each option wins over the
// scene file.
#include <gtest/gtest.h>

#include "core/parser/parser.h"
#include "render/scene.h"
#include "render/scene_builder.h"
#include "textures/basic_textures.h"
#include "textures/texture_eval_context.h"

namespace kiln {
namespace {

bool Same(const Bounds2i& a, const Bounds2i& b) { return a.pMin == b.pMin && a.pMax == b.pMax; }

const char* kOptionsScene =
    "Film \"rgb\" \"integer xresolution\" 40 \"integer yresolution\" 20\n"
    "  \"float cropwindow\" [0 0.5 0 0.5]\n"
    "Integrator \"volpath\" \"string lightsampler\" \"uniform\" \"string strategy\" \"light\"\n"
    "Sampler \"independent\" \"integer pixelsamples\" 3\n"
    "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
    "WorldBegin\n"
    "Texture \"cool\" \"float\" \"cooling\" \"float T0\" 1500 \"float mass\" 1\n"
    "Material \"diffuse\" \"texture temperature\" \"cool\"\n"
    "Shape \"sphere\" \"float radius\" 1\n";

TEST(RenderOptions, WinOverTheSceneFileAndLeaveTheDescriptionAsParsed) {
    Diagnostics diag(nullptr);
    SceneBuilder builder(diag);
    ParseString(builder, kOptionsScene, diag, "<test>");
    SceneDescription& desc = builder.Description();

    RenderOptions o;
    o.pixelBounds = Bounds2i{{4, 2}, {12, 10}};
    o.stokes = true;
    o.samplesPerPixel = 5;
    o.seed = 9;
    o.lightSelection = LightSelection::Power;
    o.strategy = LightStrategy::BSDFOnly;
    o.emitterPowerSampling = false;
    o.singleWavelength = true;
    o.timeSeconds = 30;
    std::unique_ptr<Scene> scene = Scene::Create(desc, o, diag);

    EXPECT_TRUE(Same(scene->job->film->PixelBounds(), Bounds2i{{4, 2}, {12, 10}}));
    EXPECT_TRUE(scene->job->film->WritesStokes());
    EXPECT_EQ(scene->job->sampler->SamplesPerPixel(), 5);
    EXPECT_EQ(scene->job->sampler->Seed(), 9);
    EXPECT_EQ(scene->integrator.lightSelection, LightSelection::Power);
    EXPECT_EQ(scene->integrator.strategy, LightStrategy::BSDFOnly);
    EXPECT_FALSE(scene->integrator.emitterPowerSampling);
    EXPECT_TRUE(scene->integrator.singleWavelength);
    // The description holds only what the file said
    EXPECT_FALSE(desc.film.parameters.Has("pixelbounds"));
    EXPECT_FALSE(desc.film.parameters.Has("stokes"));
    EXPECT_EQ(desc.film.parameters.GetFloatArray("cropwindow").size(), 4u);
    EXPECT_EQ(desc.integrator.parameters.GetOneString("lightsampler", ""), "uniform");
    EXPECT_FALSE(desc.integrator.parameters.Has("wavelengths"));
    EXPECT_FALSE(desc.integrator.parameters.Has("emittersampling"));
    ASSERT_EQ(desc.floatTextures.size(), 1u);
    EXPECT_FALSE(desc.floatTextures[0].second.parameters.Has("time"));
}

// The key that identifies a render's pixel-changing options (merges and checkpoints compare it)
TEST(RenderOptions, EveryPixelChangingOptionChangesTheKey) {
    std::vector<RenderOptions> variants(9);
    variants[1].emission = EmissionModel::Additive;
    variants[2].emission = EmissionModel::Kirchhoff;  // explicit, not the scene file's
    variants[3].layeredMIS = LayeredMIS::PbrtV4;
    variants[4].genericVolumes = true;
    variants[5].stokes = false;
    variants[6].lightSelection = LightSelection::Uniform;
    variants[7].strategy = LightStrategy::BSDFOnly;
    variants[8].singleWavelength = true;
    for (size_t i = 0; i < variants.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            EXPECT_NE(RenderOptionsKey(variants[i]), RenderOptionsKey(variants[j]))
                << i << " " << j;
    // What does not change pixels does not change the key
    RenderOptions job;
    job.seed = 4;
    job.samplesPerPixel = 9;
    job.cropWindow = Bounds2f{{0, 0}, {0.5f, 0.5f}};
    job.genericFootprints = job.genericAOVs = true;
    EXPECT_EQ(RenderOptionsKey(job), RenderOptionsKey(RenderOptions()));
}

TEST(RenderOptions, TheFrameTimeReachesTimeDependentTextures) {
    // The cooling texture at the options' time equals the one whose file gives that time
    auto temperature = [](const std::string& extra, std::optional<Float> time) {
        Diagnostics diag(nullptr);
        SceneBuilder builder(diag);
        std::string text = kOptionsScene;
        text.insert(text.find("\"float mass\" 1") + 14, extra);
        ParseString(builder, text, diag, "<test>");
        RenderOptions o;
        o.timeSeconds = time;
        std::unique_ptr<Scene> scene = Scene::Create(builder.Description(), o, diag);
        if (scene->lights.empty() || !scene->lights[0].Is<ThermalAreaLight>()) {
            ADD_FAILURE() << "no thermal light";
            return Float(-1);
        }
        const FloatTexture& t =
            scene->lights[0].GetIf<ThermalAreaLight>()->Emission().TemperatureTexture();
        return t.Evaluate(TextureEvalContext());
    };
    Float atZero = temperature("", std::nullopt);
    Float fromOptions = temperature("", 120);
    Float fromFile = temperature(" \"float time\" 120", std::nullopt);
    Float fileWins = temperature(" \"float time\" 120", 5);
    EXPECT_FLOAT_EQ(atZero, 1500);
    EXPECT_LT(fromOptions, 1400);
    EXPECT_EQ(fromOptions, fromFile);
    EXPECT_EQ(fileWins, fromFile);
}

TEST(RenderOptions, ACropWindowReplacesTheScenesAndPixelBoundsReplaceBoth) {
    Diagnostics diag(nullptr);
    auto bounds = [&](RenderOptions o) {
        SceneBuilder builder(diag);
        ParseString(builder, kOptionsScene, diag, "<test>");
        return Scene::Create(builder.Description(), o, diag)->job->film->PixelBounds();
    };
    EXPECT_TRUE(Same(bounds({}), Bounds2i{{0, 0}, {20, 10}}));
    RenderOptions crop;
    crop.cropWindow = Bounds2f{{0.5f, 0.5f}, {1, 1}};
    EXPECT_TRUE(Same(bounds(crop), Bounds2i{{20, 10}, {40, 20}}));
    RenderOptions both = crop;
    both.pixelBounds = Bounds2i{{1, 1}, {3, 4}};
    EXPECT_TRUE(Same(bounds(both), Bounds2i{{1, 1}, {3, 4}}));
}

}  // namespace
}  // namespace kiln
