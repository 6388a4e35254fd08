// Bidirectional path tracing (Integrator "bdpt"): Kirchhoff equilibrium (a closed isothermal
// cavity renders B(T): thermal emitters start light subpaths with their own emission, camera
// paths find it through SurfaceLe, and every strategy's MIS weights must sum to one), agreement
// with the path tracer on a diffuse box lit by an area light and a point light (statistical,
// pixel blocks against their pooled standard errors), and the choices scene creation makes
// (mlt and sppm render with bdpt; media, polarisation and orthographic cameras fall back to
// volpath with a warning).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "base/statistics.h"
#include "render_test_util.h"

namespace kiln {
namespace {

// A closed cavity at temperature T: dark textured diffuse walls (albedo <= 0.3, so that
// maxdepth 10 leaves out less than 1e-4 of the radiance) around an object of `material`;
// spheres, or smooth-shaded meshes (the walls of 168 triangles, the object of 36, normals
// interpolated from the spheres', so their shading normals depart far from the geometric ones)
std::string Cavity(const std::string& material, double T, int spp, bool meshes = false,
                   int maxDepth = 10) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"bdpt\" \"integer maxdepth\" " << maxDepth << "\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
      << "WorldBegin\n"
      << "Attribute \"shape\" \"float temperature\" " << T << "\n"
      << "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8"
         " \"rgb tex1\" [0.3 0.2 0.25] \"rgb tex2\" [0.05 0.1 0.02]\n"
      << "Material \"diffuse\" \"texture reflectance\" \"checks\"\n"
      << (meshes ? testing::MeshSphere(6, 12, 8, 0, 0, 0, true)
                 : "Shape \"sphere\" \"float radius\" 6\n")
      << "Material " << material << "\n"
      << (meshes ? testing::MeshSphere(1.2, 6, 4, 0, 0, 0.3, false)
                 : "AttributeBegin Translate 0 0 0.3 Shape \"sphere\" \"float radius\" 1.2 "
                   "AttributeEnd\n");
    return s.str();
}

TEST(BDPT, CavityRendersTheBlackbody) {
    const char* materials[] = {
        "\"diffuse\" \"rgb reflectance\" [0.4 0.3 0.2]",
        ("\"conductor\" \"spectrum eta\" \"metal-Pt-eta\" \"spectrum k\" \"metal-Pt-k\" "
         "\"float roughness\" 0.3"),
        "\"coateddiffuse\" \"rgb reflectance\" [0.2 0.3 0.2] \"float roughness\" 0.1",
    };
    for (const char* m : materials)
        for (double T : {1500.0}) {
            SCOPED_TRACE(m);
            testing::RenderedScene r = testing::RenderText(Cavity(m, T, 64));
            ASSERT_TRUE(r.scene->features.bidirectional);
            testing::ExpectBlackbodyImage(r, T, std::string("bdpt ") + m);
        }
}

// With shading normals, light subpaths scatter by the adjoint BSDF (BDPTVertex::AdjointF):
// the shading normal's cosine on the side of the light and the geometric one's on the other
// (Veach's correction, which pbrt-v3 has and pbrt-v4 does not), and for folding BSDFs the
// directions swapped. Without the first, these cavities rendered 1.0126 (diffuse), 1.0157
// (gold) and 1.116 (rough glass) of B(T), with 6-60 times the standard error; without the
// swap, the glass 1.005 (which the test cannot see).
TEST(BDPT, SmoothShadedMeshCavityRendersTheBlackbody) {
    const double T = 1500;
    struct {
        const char* material;
        int spp, maxDepth;
    } cases[] = {
        {"\"diffuse\" \"rgb reflectance\" [0.3 0.3 0.3]", 64, 10},
        {"\"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" "
         "\"float roughness\" 0.05",
         64, 10},
        {"\"dielectric\" \"float eta\" 2.4 \"float roughness\" 0.5", 256, 30},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.material);
        testing::ExpectBlackbodyImage(
            testing::RenderText(Cavity(c.material, T, c.spp, true, c.maxDepth)), T,
            std::string("bdpt, meshes, ") + c.material);
    }
}

// Bright smooth-shaded walls (albedo 0.8, the 168-triangle mesh) and nothing inside: light
// bounces many times between folding BSDFs (bsdf.h), which scatter between some pairs of
// directions they sample in one order only. A strategy that cannot make a path has a reverse
// density of 0; counted as 1 (pbrt-v4's remap0, meant for specular vertices) it took a share
// of the MIS weights, and this cavity rendered 0.9915 of B(T) (albedo 0.5: 0.9989).
TEST(BDPT, BrightSmoothShadedWallsRenderTheBlackbody) {
    const double T = 1500;
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 128\n"
      << "Integrator \"bdpt\" \"integer maxdepth\" 45\n"  // 0.8^45 < 1e-4
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
      << "WorldBegin\nAttribute \"shape\" \"float temperature\" " << T << "\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.8 0.8 0.8]\n"
      << testing::MeshSphere(6, 12, 8, 0, 0, 0, true);
    testing::ExpectBlackbodyImage(testing::RenderText(s.str()), T,
                                  "bdpt, bright smooth-shaded walls");
}

// A box of diffuse walls lit by an area light on the ceiling and a point light, or (thermal)
// by a glowing sphere whose temperature rises from 900 K to 1400 K across it (its light
// subpaths start by power over its surface); deadLight adds a bright area light cut out
// everywhere by an alpha texture (its light subpaths never start; light selection still picks
// it)
std::string Box(const char* integrator, int spp, bool thermal = false, bool deadLight = false) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"" << integrator << "\" \"integer maxdepth\" 4\n"
      << "LookAt 0 1 3.5  0 1 0  0 1 0\nCamera \"perspective\" \"float fov\" 45\n"
      << "WorldBegin\n"
      << "LightSource \"point\" \"point3 from\" [0.5 1.5 0.5] \"rgb I\" [0.5 0.5 0.5]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.6 0.6 0.6]\n"
      << "Shape \"bilinearmesh\" \"point3 P\" [-1 0 -1 1 0 -1 -1 0 1 1 0 1]\n"
      << "Shape \"bilinearmesh\" \"point3 P\" [-1 2 -1 -1 2 1 1 2 -1 1 2 1]\n"
      << "Shape \"bilinearmesh\" \"point3 P\" [-1 0 -1 -1 2 -1 1 0 -1 1 2 -1]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.6 0.2 0.2]\n"
      << "Shape \"bilinearmesh\" \"point3 P\" [-1 0 -1 -1 0 1 -1 2 -1 -1 2 1]\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.2 0.6 0.2]\n"
      << "Shape \"bilinearmesh\" \"point3 P\" [1 0 -1 1 2 -1 1 0 1 1 2 1]\n"
      << "AttributeBegin\n";
    if (thermal)
        s << "  Texture \"heat\" \"float\" \"gradient\" \"point3 p0\" [-0.3 0 0] \"point3 p1\" "
             "[0.3 0 0] \"float t0\" 900 \"float t1\" 1400 \"string space\" \"world\"\n"
          << "  Material \"diffuse\" \"rgb reflectance\" [0.3 0.3 0.3] \"texture temperature\" "
             "\"heat\"\n"
          << "  Translate 0 1.5 0 Shape \"sphere\" \"float radius\" 0.3\n";
    else
        s << "  AreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
          << "  Shape \"bilinearmesh\" \"point3 P\" [-0.3 1.99 -0.3 -0.3 1.99 0.3 0.3 1.99 -0.3 "
             "0.3 1.99 0.3]\n";
    s << "AttributeEnd\n";
    if (deadLight)
        s << "AttributeBegin\n"
          << "  Texture \"zero\" \"float\" \"checkerboard\" \"float tex1\" 0 \"float tex2\" 0\n"
          << "  AreaLightSource \"diffuse\" \"rgb L\" [40 40 40]\n"
          << "  Shape \"bilinearmesh\" \"point3 P\" [-0.5 1.9 -0.9 0.5 1.9 -0.9 -0.5 1.2 -0.9 0.5 "
             "1.2 -0.9] \"texture alpha\" \"zero\"\n"
          << "AttributeEnd\n";
    return s.str();
}

// Mean luminance of 4 x 4 pixel blocks, with the standard error over independent seeds
struct Blocks {
    std::vector<RunningStats> stats = std::vector<RunningStats>(16);
    void Add(const Scene& scene) {
        std::vector<double> sums(16, 0);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                sums[(y / 4) * 4 + x / 4] += testing::PixelY(scene, {x, y});
        for (int b = 0; b < 16; ++b) stats[b].Add(sums[b] / 16);
    }
};

TEST(BDPT, AgreesWithPathTracing) {
    for (bool thermal : {false, true}) {
        SCOPED_TRACE(thermal ? "hot sphere" : "area and point lights");
        Blocks bdpt, path;
        const int seeds = 6;
        for (int k = 0; k < seeds; ++k) {
            RenderOptions o;
            o.seed = k + 1;
            bdpt.Add(*testing::RenderText(Box("bdpt", 64, thermal), 0, o).scene);
            path.Add(*testing::RenderText(Box("path", 64, thermal), 0, o).scene);
        }
        double chi2 = 0;
        for (int b = 0; b < 16; ++b) {
            double d = bdpt.stats[b].Mean() - path.stats[b].Mean();
            double se2 = Sqr(bdpt.stats[b].StandardError()) + Sqr(path.stats[b].StandardError());
            ASSERT_GT(path.stats[b].Mean(), 0);
            chi2 += d * d / se2;
            EXPECT_LT(std::abs(d), 5 * std::sqrt(se2) + 1e-3 * path.stats[b].Mean())
                << "block " << b << ": bdpt " << bdpt.stats[b].Mean() << " path "
                << path.stats[b].Mean();
        }
        // 16 blocks: the sum of squared z-scores is chi-square with ~16 degrees of freedom
        // (from 6 seeds each, heavier tailed); 60 is far beyond its 0.999 quantile
        EXPECT_LT(chi2, 60);
        std::printf("bdpt vs path (%s), 16 blocks: chi2 %.1f\n", thermal ? "hot sphere" : "lights",
                    chi2);
    }
}

TEST(BDPT, LightSamplingRunsWhenTheLightSubpathCannotStart) {
    // Most light subpaths start at the cut-out light and fail at once; light sampling from the
    // camera paths must run anyway (pbrt-v4 skips it: 0.84 of the mean in a scene with a
    // weaker cut-out light, where fewer light subpaths fail than here)
    RunningStats bdpt, path;
    for (int k = 0; k < 6; ++k) {
        RenderOptions o;
        o.seed = k + 1;
        auto mean = [](const Scene& scene) {
            double sum = 0;
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) sum += testing::PixelY(scene, {x, y});
            return sum / 256;
        };
        bdpt.Add(mean(*testing::RenderText(Box("bdpt", 32, false, true), 0, o).scene));
        path.Add(mean(*testing::RenderText(Box("path", 32, false, true), 0, o).scene));
    }
    double se = std::sqrt(Sqr(bdpt.StandardError()) + Sqr(path.StandardError()));
    EXPECT_NEAR(bdpt.Mean(), path.Mean(), 5 * se);
    EXPECT_LT(5 * se, 0.1 * path.Mean());
    std::printf("cut-out light: bdpt %.5f, path %.5f (standard error %.5f)\n", bdpt.Mean(),
                path.Mean(), se);
}

TEST(BDPT, CropWindowMatchesTheFullImage) {
    // Light tracing from a crop window splats only inside it, with pbrt-v4's scale for the
    // share of the image it covers: the crop's pixels must agree with the full image's
    RunningStats full, crop;
    for (int k = 0; k < 6; ++k) {
        RenderOptions o;
        o.seed = k + 1;
        testing::RenderedScene f = testing::RenderText(Box("bdpt", 32), 0, o);
        o.cropWindow = Bounds2f{{0.25f, 0.25f}, {0.75f, 0.75f}};
        testing::RenderedScene c = testing::RenderText(Box("bdpt", 32), 0, o);
        ASSERT_EQ(c.scene->job->film->PixelBounds().Area(), 64);
        double sf = 0, sc = 0;
        for (int y = 4; y < 12; ++y)
            for (int x = 4; x < 12; ++x) {
                sf += testing::PixelY(*f.scene, {x, y});
                sc += testing::PixelY(*c.scene, {x, y});
            }
        full.Add(sf / 64);
        crop.Add(sc / 64);
    }
    double se = std::sqrt(Sqr(full.StandardError()) + Sqr(crop.StandardError()));
    EXPECT_NEAR(crop.Mean(), full.Mean(), 5 * se) << "standard error " << se;
    std::printf("crop %.5f, full image %.5f (standard error %.5f)\n", crop.Mean(), full.Mean(), se);
    // Without the scale the crop would be 4 times too dark in its light-traced part
    EXPECT_LT(5 * se, 0.05 * full.Mean());
}

TEST(BDPT, ResumedRenderEqualsTheUninterruptedOne) {
    // A render resumed from the film state after 8 of 16 samples per pixel (as kiln's
    // checkpoints do) traces the same paths: the splats kept in the state and the splat scale
    // of the finished render give the uninterrupted image, up to the order of atomic sums
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> a = testing::BuildScene(Box("bdpt", 16), diag);
    std::string state;
    RenderSettings settings;
    settings.maxWaveSize = 1;
    settings.afterWave = [&](int completed) {
        if (completed == 8) state = a->job->film->SaveState();
    };
    Render(*a, settings);
    ASSERT_FALSE(state.empty());
    std::unique_ptr<Scene> b = testing::BuildScene(Box("bdpt", 16), diag);
    ASSERT_TRUE(b->job->film->LoadState(state));
    RenderSettings resume;
    resume.startSample = 8;
    Render(*b, resume);
    double maxRel = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            double ya = testing::PixelY(*a, {x, y}), yb = testing::PixelY(*b, {x, y});
            ASSERT_GT(ya, 0);
            maxRel = std::max(maxRel, std::abs(ya - yb) / ya);
        }
    EXPECT_LT(maxRel, 1e-4);
}

TEST(BDPT, IntegratorChoices) {
    auto load = [](const std::string& integrator, const std::string& extra,
                   const std::string& camera = "perspective") {
        Diagnostics diag(nullptr);
        std::string text =
            "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
            "Integrator \"" +
            integrator + "\"\nCamera \"" + camera + "\"\n" + extra +
            "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\n";
        std::unique_ptr<Scene> scene = testing::BuildScene(text, diag);
        return std::make_pair(scene->features.bidirectional, diag.WarningCount());
    };
    EXPECT_EQ(load("bdpt", ""), std::make_pair(true, 0));
    EXPECT_EQ(load("mlt", ""), std::make_pair(true, 1));
    EXPECT_EQ(load("sppm", ""), std::make_pair(true, 1));
    EXPECT_EQ(load("volpath", ""), std::make_pair(false, 0));
    EXPECT_EQ(load("bdpt", "", "orthographic"), std::make_pair(false, 1));
    EXPECT_EQ(load("bdpt", "Film \"rgb\" \"bool stokes\" true\n").first, false);
    // Media: volpath, which renders them
    Diagnostics diag(nullptr);
    std::unique_ptr<Scene> fog = testing::BuildScene(
        "Integrator \"bdpt\"\nWorldBegin\nLightSource \"point\"\n"
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "MediumInterface \"fog\" \"\"\nMaterial \"interface\"\nShape \"sphere\"\n",
        diag);
    EXPECT_FALSE(fog->features.bidirectional);
    EXPECT_TRUE(fog->features.volumetric);
    EXPECT_EQ(diag.WarningCount(), 1);
}

}  // namespace
}  // namespace kiln
