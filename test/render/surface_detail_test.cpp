// pbrt-v4's surface detail in whole renders, against what it stands for: a normal map or bump
// map tilting a diffuse plane's shading normal by theta dims it, under a light along the
// geometric normal, by exactly cos(theta) (direct light only, so the images are noise-free);
// a shape with alpha a lets 1 - a of the light through its shadow (each surface of a sphere
// separately), and an area light with alpha a emits a of its light, whichever way paths find it;
// a displaced PLY mesh is where its displacement puts it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/image/image.h"
#include "render_test_util.h"

namespace kiln {
namespace {

// A diffuse square (uv over [0, 1]^2) filling an orthographic view, lit by a distant light
// along its normal; `material` is appended to the diffuse material's parameters.
std::string LitSquare(const std::string& material, const std::string& preamble = "") {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
      << "Sampler \"independent\" \"integer pixelsamples\" 4\n"
      << "Integrator \"path\" \"integer maxdepth\" 1\n"
      << "LookAt 0.5 0.5 5  0.5 0.5 0  0 1 0\n"
      << "Camera \"orthographic\" \"float screenwindow\" [-0.4 0.4 -0.4 0.4]\n"
      << "WorldBegin\n"
      << "LightSource \"distant\" \"point3 from\" [0 0 1] \"point3 to\" [0 0 0] "
         "\"rgb L\" [1 1 1]\n"
      << preamble << "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5] " << material << "\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
         "\"point3 P\" [0 0 0 1 0 0 1 1 0 0 1 0] \"point2 uv\" [0 0 1 0 1 1 0 1]\n";
    return s.str();
}

// Mean pixel luminance and its standard error over pixels.
std::pair<double, double> MeanAndError(const std::string& scene) {
    testing::RenderedScene r = testing::RenderText(scene);
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    EXPECT_EQ(r.scene->job->film->NonFiniteSampleCount(), 0);
    RunningStats s = testing::BlockStats(r.scene->job->film->PixelBounds(),
                                         [&](Point2i p) { return testing::PixelY(*r.scene, p); });
    return {s.Mean(), s.StandardError()};
}

double MeanY(const std::string& scene) { return MeanAndError(scene).first; }

TEST(SurfaceDetailRender, NormalMapDimsByTheCosineOfItsTilt) {
    const double flat = MeanY(LitSquare(""));
    ASSERT_GT(flat, 0);
    for (double degrees : {20.0, 50.0}) {
        // A 2 x 2 map tilting the normal towards +v (green) by `degrees`
        std::string file =
            ::testing::TempDir() + "/kiln_tilt_" + std::to_string(int(degrees)) + ".exr";
        Image image(PixelFormat::Float, {2, 2}, {"R", "G", "B"});
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) {
                image.SetChannel({x, y}, 0, 0.5f);
                image.SetChannel({x, y}, 1, 0.5f + 0.5f * std::sin(Radians(float(degrees))));
                image.SetChannel({x, y}, 2, 0.5f + 0.5f * std::cos(Radians(float(degrees))));
            }
        image.Write(file);
        double tilted = MeanY(LitSquare("\"string normalmap\" \"" + file + "\""));
        EXPECT_NEAR(tilted / flat, std::cos(Radians(degrees)), 2e-3) << degrees;
    }
}

TEST(SurfaceDetailRender, BumpMapDimsByTheCosineOfItsSlope) {
    const double flat = MeanY(LitSquare(""));
    // d = 0.6 u: slope 0.6 along u, cos(theta) = 1 / sqrt(1 + 0.36)
    std::string bump =
        "Texture \"ramp\" \"float\" \"bilerp\" \"float v00\" 0 \"float v10\" 0.6 "
        "\"float v01\" 0 \"float v11\" 0.6\n";
    double bumped = MeanY(LitSquare("\"texture displacement\" \"ramp\"", bump));
    EXPECT_NEAR(bumped / flat, 1 / std::sqrt(1 + 0.36), 2e-3);
    // A constant displacement of a plane changes nothing
    double lifted = MeanY(LitSquare("\"float displacement\" 0.3"));
    EXPECT_NEAR(lifted / flat, 1, 1e-4);
}

// A diffuse floor (z = 0, viewed from above over [0, 1]^2) lit by a distant light from
// (1, 0, 1); `occluder` sits in the light's path (around x + 1 at height 1), out of view.
std::string ShadowedFloor(const std::string& occluder, int spp) {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
      << "Sampler \"independent\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"path\" \"integer maxdepth\" 1\n"
      << "LookAt 0.5 0.5 0.5  0.5 0.5 0  0 1 0\n"
      << "Camera \"orthographic\" \"float screenwindow\" [-0.5 0.5 -0.5 0.5]\n"
      << "WorldBegin\n"
      << "LightSource \"distant\" \"point3 from\" [1 0 1] \"point3 to\" [0 0 0] "
         "\"rgb L\" [1 1 1]\n"
      << "Material \"diffuse\"\n"
      << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
         "\"point3 P\" [-1 -1 0 2 -1 0 2 2 0 -1 2 0]\n"
      << occluder << "\n";
    return s.str();
}

TEST(AlphaRender, ShadowsPassOneMinusAlphaPerSurface) {
    const int spp = 256;
    const double lit = MeanAndError(ShadowedFloor("", spp)).first;
    ASSERT_GT(lit, 0);
    // An opaque square at height 1 over x in [0.8, 2.2] shadows the whole view
    auto square = [](const std::string& alpha) {
        return "Shape \"trianglemesh\" " + alpha +
               " \"integer indices\" [0 1 2 0 2 3] "
               "\"point3 P\" [0.8 -1 1 2.2 -1 1 2.2 2 1 0.8 2 1] \"point2 uv\" [0 0 1 0 1 1 0 1]";
    };
    EXPECT_EQ(MeanAndError(ShadowedFloor(square(""), spp)).first, 0);
    EXPECT_EQ(MeanAndError(ShadowedFloor(square("\"float alpha\" 0"), spp)).first, lit);
    // Alpha 0.3 everywhere, or from a texture: the light passes 70 % of the time
    std::string ramp =
        "Texture \"a\" \"float\" \"bilerp\" \"float v00\" 0.3 \"float v10\" 0.3 "
        "\"float v01\" 0.3 \"float v11\" 0.3\n";
    for (const std::string& occluder :
         {square("\"float alpha\" 0.3"), ramp + square("\"texture alpha\" \"a\"")}) {
        auto [m, se] = MeanAndError(ShadowedFloor(occluder, spp));
        EXPECT_NEAR(m / lit, 0.7, 4 * se / lit) << occluder;
        EXPECT_LT(4 * se / lit, 0.02);
    }
    // A sphere (quadric, Embree user geometry) covering the view's shadow: each of its two
    // surfaces passes 70 %, together 49 %
    std::string sphere =
        "AttributeBegin Translate 2 0.5 1.5 Shape \"sphere\" \"float radius\" 1 "
        "\"float alpha\" 0.3 AttributeEnd";
    auto [m, se] = MeanAndError(ShadowedFloor(sphere, spp));
    EXPECT_NEAR(m / lit, 0.49, 4 * se / lit);
}

TEST(AlphaRender, AreaLightWithAlphaEmitsItsFraction) {
    // A floor lit by a square area light above it, with light sampling and BSDF sampling
    // both finding the light (MIS): alpha 0.4 must give 40 % of the opaque light's image
    auto scene = [](const std::string& alpha) {
        std::ostringstream s;
        s << "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
          << "Sampler \"independent\" \"integer pixelsamples\" 256\n"
          << "Integrator \"path\" \"integer maxdepth\" 1\n"
          << "LookAt 0 0 0.5  0 0 0  0 1 0\n"
          << "Camera \"orthographic\" \"float screenwindow\" [-0.5 0.5 -0.5 0.5]\n"
          << "WorldBegin\nMaterial \"diffuse\"\n"
          << "Texture \"zero\" \"float\" \"checkerboard\" \"float tex1\" 0 \"float tex2\" 0\n"
          << "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
             "\"point3 P\" [-2 -2 0 2 -2 0 2 2 0 -2 2 0]\n"
          << "AttributeBegin AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] "
          << "ReverseOrientation Translate 0 0 1 Shape \"bilinearmesh\" " << alpha
          << " \"point3 P\" [-1 -1 0 1 -1 0 -1 1 0 1 1 0] AttributeEnd\n";
        return s.str();
    };
    auto [opaque, seOpaque] = MeanAndError(scene(""));
    ASSERT_GT(opaque, 0);
    auto [m, se] = MeanAndError(scene("\"float alpha\" 0.4"));
    double tol = 4 * std::hypot(se / opaque, 0.4 * seOpaque / opaque);
    EXPECT_LT(tol, 0.03);
    EXPECT_NEAR(m / opaque, 0.4, tol);
    // pbrt-v4's invisible light: a constant alpha of 0 lights the floor as the opaque light
    // does (light sampling alone finds it); an alpha texture that is 0 but not a constant
    // cuts the light out
    auto [invisible, seInvisible] = MeanAndError(scene("\"float alpha\" 0"));
    EXPECT_NEAR(invisible / opaque, 1, 4 * std::hypot(seInvisible / opaque, seOpaque / opaque));
    EXPECT_EQ(MeanAndError(scene("\"texture alpha\" \"zero\"")).first, 0);
}

TEST(PlyDisplacement, MeshIsWhereTheTextureMovesIt) {
    // An ASCII PLY square (uv) raised 0.3 along its normal, refined to edges under 0.25
    std::string ply = ::testing::TempDir() + "/kiln_displaced_square.ply";
    {
        std::ofstream out(ply);
        out << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
               "property float z\nproperty float u\nproperty float v\nelement face 2\n"
               "property list uchar int vertex_indices\nend_header\n"
               "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2\n3 0 2 3\n";
    }
    auto scene = [&](const std::string& displacement) {
        return "Camera \"perspective\"\nWorldBegin\nLightSource \"distant\"\n"
               "Texture \"lift\" \"float\" \"constant\" \"float value\" 0.3\n"
               "Shape \"plymesh\" \"string filename\" \"" +
               ply + "\" " + displacement + "\n";
    };
    Diagnostics diag(nullptr);
    auto lifted = testing::BuildScene(
        scene("\"texture displacement\" \"lift\" \"float edgelength\" 0.25"), diag);
    EXPECT_EQ(diag.WarningCount(), 0);
    EXPECT_GE(lifted->shapeCount, 32);  // refined: 2 triangles became many
    auto hit = lifted->aggregate->Intersect(Ray(Point3f(0.37f, 0.61f, 5), Vector3f(0, 0, -1)));
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->intr.p.z, 0.3f, 1e-5f);
    // Non-positive edge lengths are located errors
    try {
        testing::BuildScene(scene("\"texture displacement\" \"lift\" \"float edgelength\" 0"),
                            diag);
        ADD_FAILURE() << "edgelength 0 accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.Token(), "edgelength");
    }
}

// pbrt-v4 makes no area light on a shape whose material is an interface (a warning): it only
// marks a boundary between media
TEST(AreaLights, NoneOnInterfaceMaterials) {
    for (const char* material : {"interface", "none", "diffuse"}) {
        Diagnostics diag(nullptr);
        std::unique_ptr<Scene> scene = testing::BuildScene(
            std::string("Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
                        "Camera \"perspective\"\nWorldBegin\nMaterial \"") +
                material +
                "\"\nAttributeBegin AreaLightSource \"diffuse\" Shape \"sphere\" AttributeEnd\n",
            diag);
        bool boundary = std::string(material) != "diffuse";
        EXPECT_EQ(scene->lights.size(), boundary ? 0u : 1u) << material;
        int ignored = 0;
        for (const auto& w : diag.Warnings())
            ignored +=
                w.message.find("area light on a shape with an \"interface\"") != std::string::npos;
        EXPECT_EQ(ignored, boundary ? 1 : 0) << material;
    }
}

// pbrt-v4 decodes an area light's 8-bit "filename" image as sRGB whatever the PNG's gAMA chunk
// says: a file marked linear and one marked sRGB with the same bytes light alike
TEST(AreaLights, EmissionImagesAreSRGBWhateverTheirGamma) {
    std::string dir = ::testing::TempDir();
    double mean[2];
    for (int linear = 0; linear < 2; ++linear) {
        Image im(PixelFormat::U256, {2, 2}, {"R", "G", "B"},
                 linear ? ColorEncoding::Linear() : ColorEncoding::SRGB());
        for (int c = 0; c < 3; ++c)
            for (int p = 0; p < 4; ++p)
                im.SetChannel({p % 2, p / 2}, c,
                              linear ? 128 / 255.f : SRGBToLinear(128 / 255.f));  // byte 128
        std::string file = dir + "/kiln_emission_" + std::to_string(linear) + ".png";
        im.Write(file);
        mean[linear] = MeanY(
            "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\n"
            "Sampler \"independent\" \"integer pixelsamples\" 4\n"
            "LookAt 0 0 1  0 0 0  0 1 0\n"
            "Camera \"orthographic\" \"float screenwindow\" [-0.5 0.5 -0.5 0.5]\n"
            "WorldBegin\nAreaLightSource \"diffuse\" \"string filename\" \"" +
            file + "\"\nShape \"bilinearmesh\" \"point3 P\" [-1 -1 0 1 -1 0 -1 1 0 1 1 0]\n");
        std::remove(file.c_str());
    }
    EXPECT_GT(mean[0], 0);
    EXPECT_NEAR(mean[1] / mean[0], 1, 1e-3);
}

}  // namespace
}  // namespace kiln
