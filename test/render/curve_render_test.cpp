// Curves and hair in whole renders: a black curve of width w across an orthographic view of
// height 1 in front of a white sky covers exactly w of it (w cos(tilt) for a tilted ribbon),
// whatever its basis and degree; clear hair (no absorption) in a uniform sky is invisible
// (energy conservation: every pixel is the sky); and a hot metal filament, or hot absorbing
// hair, inside a closed cavity at its temperature renders B(T) (Kirchhoff on the new geometry).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "render_test_util.h"

namespace kiln {
namespace {

// Mean pixel luminance relative to the sky's, and its standard error across 8 renders with
// different seeds (pixels differ by what they cover, so the spread over pixels is no error).
std::pair<double, double> RelativeMean(const std::string& scene, double sky) {
    RunningStats means;
    for (int seed = 1; seed <= 8; ++seed) {
        RenderOptions o;
        o.seed = seed;
        testing::RenderedScene r = testing::RenderText(scene, 0, o);
        for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
        EXPECT_EQ(r.scene->job->film->NonFiniteSampleCount(), 0);
        RunningStats s;
        Bounds2i b = r.scene->job->film->PixelBounds();
        for (int y = b.pMin.y; y < b.pMax.y; ++y)
            for (int x = b.pMin.x; x < b.pMax.x; ++x)
                s.Add(testing::PixelY(*r.scene, {x, y}) / sky);
        means.Add(s.Mean());
    }
    return {means.Mean(), means.StandardError()};
}

std::string Sky(const std::string& world, int spp, const std::string& integrator = "path") {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 32\n"
      << "PixelFilter \"box\"\n"
      << "Sampler \"independent\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"" << integrator << "\" \"integer maxdepth\" 100\n"
      << "LookAt 0 0 5  0 0 0  0 1 0\n"
      << "Camera \"orthographic\" \"float screenwindow\" [-0.5 0.5 -0.5 0.5]\n"
      << "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
      << world;
    return s.str();
}

TEST(CurveRender, CoverageIsTheWidth) {
    const double sky = RelativeMean(Sky("", 1), 1).first;
    ASSERT_GT(sky, 0);
    const std::string black = "Material \"diffuse\" \"rgb reflectance\" [0 0 0]\n";
    struct Case {
        const char* name;
        std::string shape;
        double covered;
    };
    // Straight curves across the view at y = 0.0123 (off the pixel grid), width 0.1
    const Float t = Radians(60.f);
    std::ostringstream ribbon;
    ribbon << "Shape \"curve\" \"point3 P\" [-2 0.0123 0 -0.7 0.0123 0 0.7 0.0123 0 2 0.0123 0] "
           << "\"float width\" 0.1 \"string type\" \"ribbon\" \"normal N\" [0 " << std::sin(t)
           << " " << std::cos(t) << " 0 " << std::sin(t) << " " << std::cos(t) << "]\n";
    const Case cases[] = {
        {"flat bezier",
         "Shape \"curve\" \"point3 P\" [-2 0.0123 0 -0.7 0.0123 0 0.7 0.0123 0 2 0.0123 0] "
         "\"float width\" 0.1\n",
         0.1},
        {"cylinder bspline",
         "Shape \"curve\" \"point3 P\" [-3 0.0123 0 -1.5 0.0123 0 0 0.0123 0 1.5 0.0123 0 3 "
         "0.0123 0] \"string basis\" \"bspline\" \"float width\" 0.1 \"string type\" "
         "\"cylinder\"\n",
         0.1},
        {"quadratic bezier, tapered",
         "Shape \"curve\" \"point3 P\" [-1 0.0123 0 0 0.0123 0 1 0.0123 0] \"integer degree\" 2 "
         "\"float width0\" 0.15 \"float width1\" 0.05\n",
         0.1},  // width 0.1 at x = 0, linear: the mean over [-0.5, 0.5]
        {"ribbon tilted 60 degrees", ribbon.str(), 0.1 * std::cos(t)},
    };
    for (const Case& c : cases) {
        auto [m, se] = RelativeMean(Sky(black + c.shape, 64), sky);
        std::printf("%-28s covers %.4f (se %.4f), expected %.4f\n", c.name, 1 - m, se, c.covered);
        EXPECT_NEAR(1 - m, c.covered, 4 * se + 1e-3) << c.name;
        EXPECT_LT(4 * se, 0.01);
    }
}

TEST(CurveRender, ClearHairInAUniformSkyIsInvisible) {
    // Hair that absorbs nothing scatters all it receives: with the sky the same in every
    // direction, every pixel sees the sky's radiance (up to the path-length cut-off). The
    // cuticle scales' tilt (alpha) makes the model gain a little energy (this scene renders
    // 1.0018 of the sky with pbrt-v4's default 2 degrees): without it
    const Float alpha = 0;
    std::ostringstream hair;
    hair << "Material \"hair\" \"rgb sigma_a\" [0 0 0] \"float beta_m\" 0.25 "
            "\"float beta_n\" 0.4 \"float alpha\" "
         << alpha << "\n";
    for (int i = 0; i < 12; ++i) {
        Float x = -0.45f + 0.08f * i;
        hair << "Shape \"curve\" \"point3 P\" [" << x << " -1 0.1  " << x + 0.05f << " -0.3 -0.1  "
             << x - 0.05f << " 0.3 0.2  " << x << " 1 0] \"float width\" 0.03 \"string type\" "
             << (i % 2 ? "\"cylinder\"" : "\"flat\"") << "\n";
    }
    const double sky = RelativeMean(Sky("", 1), 1).first;
    auto [m, se] = RelativeMean(Sky(hair.str(), 64), sky);
    std::printf("clear hair in a uniform sky: %.5f of the sky (se %.5f)\n", m, se);
    EXPECT_NEAR(m, 1, 4 * se + 5e-4);
    EXPECT_LT(4 * se, 0.01);
    // A coloured fibre does absorb: the test can tell
    auto [dark, seDark] = RelativeMean(Sky("Material \"hair\" \"float eumelanin\" 1\n" +
                                               hair.str().substr(hair.str().find('\n') + 1),
                                           16),
                                       sky);
    EXPECT_LT(dark, 1 - 4 * seDark - 0.02);
}

TEST(CurveRender, HotFilamentInACavityRendersTheBlackbody) {
    // A coiled tungsten filament (a cylinder-type curve, glowing where rays hit it, not sampled
    // as a light) inside a closed diffuse cavity, everything at T
    for (double T : {1500.0, 3000.0}) {
        std::ostringstream s;
        s << testing::CavityPreamble(T, 256)
          << "Material \"diffuse\" \"rgb reflectance\" [0.6 0.5 0.4]\n"
          << "Shape \"sphere\" \"float radius\" 6\n"
          << "Material \"conductor\" \"spectrum eta\" \"metal-W-eta\" \"spectrum k\" "
             "\"metal-W-k\" \"float roughness\" 0.05\n"
          << "Shape \"curve\" \"string type\" \"cylinder\" \"float width\" 0.25 "
             "\"string basis\" \"bspline\" \"point3 P\" [";
        for (int k = 0; k < 24; ++k) {
            Float a = 1.2f * k;
            s << 0.6f * std::cos(a) << " " << -1 + 0.09f * k << " " << 0.6f * std::sin(a) << " ";
        }
        s << "]\n";
        testing::RenderedScene r = testing::RenderText(s.str());
        // The one warning: hot curves are not light-sampled
        ASSERT_EQ(r.warnings.size(), 1u);
        EXPECT_NE(r.warnings[0].message.find("not sampled as lights"), std::string::npos);
        r.warnings.clear();
        testing::ExpectBlackbodyImage(r, T, "tungsten filament curve");
    }
}

TEST(CurveRender, HotHairInACavityRendersTheBlackbody) {
    // Absorbing fibres (flat and cylinder curves, tilted scales, melanin, and an absorption that
    // varies along the spectrum) emit what the hair model does not scatter, 1 - Albedo: in a
    // closed cavity at their temperature they vanish into B(T)
    const double T = 2500;
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" 256\n"
      << "Integrator \"path\" \"integer maxdepth\" 500\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      << "WorldBegin\nAttribute \"shape\" \"float temperature\" " << T << "\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.6 0.5 0.4]\n"
      << "Shape \"sphere\" \"float radius\" 6\n";
    const char* materials[] = {
        "\"float eumelanin\" 1.3 \"float beta_m\" 0.3",
        ("\"rgb sigma_a\" [0.2 1.5 6] \"float beta_m\" 0.15 \"float beta_n\" 0.6 "
         "\"float alpha\" 4"),
        "\"float pheomelanin\" 3 \"float eta\" 1.33 \"float beta_m\" 0.8 \"float beta_n\" 0.9"};
    for (int i = 0; i < 18; ++i) {
        if (i % 6 == 0) s << "Material \"hair\" " << materials[i / 6] << "\n";
        Float x = -0.72f + 0.085f * i;
        s << "Shape \"curve\" \"point3 P\" [" << x << " -1 0.1  " << x + 0.1f << " -0.3 -0.2  "
          << x - 0.1f << " 0.3 0.3  " << x << " 1 0] \"float width\" 0.06 \"string type\" "
          << (i % 2 ? "\"cylinder\"" : "\"flat\"") << "\n";
    }
    testing::RenderedScene r = testing::RenderText(s.str());
    ASSERT_EQ(r.warnings.size(), 18u);  // each hot curve: not light-sampled
    for (const auto& w : r.warnings)
        EXPECT_NE(w.message.find("not sampled as lights"), std::string::npos) << w.message;
    r.warnings.clear();
    testing::ExpectBlackbodyImage(r, T, "hot hair curves");
}

}  // namespace
}  // namespace kiln
