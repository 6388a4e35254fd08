// Hostile scene input that used to kill kiln (a NaN direction aborting inside Embree) or that
// pbrt-v4 accepts: out-of-range roughness, constant and textured, and singular transforms on
// every kind of object. Each either renders only finite values or is an error at its location.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "image_stats.h"

namespace kiln {
namespace {

const char* kView = R"(
Film "rgb" "integer xresolution" 20 "integer yresolution" 20
Sampler "zsobol" "integer pixelsamples" 8
Integrator "path" "integer maxdepth" 8
LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
)";

using testing::ImageStats;
using testing::kEnvAndFloor;
using Rendered = ImageStats;

Rendered RenderWorld(const std::string& world) {
    return testing::RenderStats(std::string(kView) + "WorldBegin\n" + kEnvAndFloor + world, 1, 8);
}

void ExpectFinite(const Rendered& r, const std::string& what) {
    EXPECT_EQ(r.nonFinite, 0) << what;
    EXPECT_EQ(r.nonFinitePixels, 0) << what;
    EXPECT_GT(r.meanY, 0) << what;
}

bool HasWarning(const Rendered& r, const std::string& text) {
    for (const std::string& w : r.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

std::string ErrorOf(const std::string& scene) {
    try {
        testing::RenderText(scene);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(HostileInput, ExtremeAndTexturedNegativeRoughnessRenderFinite) {
    // Huge alphas used to overflow alpha^2 and negative textured values to take a square root
    // of a negative number; both made NaN directions that aborted inside Embree
    const char* textures = R"(
Texture "checks" "float" "checkerboard" "float uscale" 4 "float vscale" 4
    "float tex1" 0.3 "float tex2" 1
Texture "negative" "float" "scale" "texture tex" "checks" "float scale" -2
)";
    const char* roughness[] = {"\"float roughness\" 1e30 \"bool remaproughness\" false",
                               "\"float roughness\" 1e8", "\"float roughness\" 1e-30",
                               "\"texture roughness\" \"negative\"",
                               ("\"float uroughness\" 1e30 \"float vroughness\" 0 "
                                "\"bool remaproughness\" false")};
    for (const char* material : {"dielectric", "conductor", "coateddiffuse"})
        for (const char* r : roughness) {
            std::string world = std::string(textures) + "Material \"" + material + "\" " + r +
                                "\nTranslate 0 0.6 0 Shape \"sphere\" \"float radius\" 0.6\n";
            ExpectFinite(RenderWorld(world), std::string(material) + " " + r);
        }
    std::string coated = std::string(textures) +
                         "Material \"coatedconductor\" \"texture interface.roughness\" "
                         "\"negative\" \"float conductor.roughness\" 1e30 "
                         "\"bool remaproughness\" false\n"
                         "Translate 0 0.6 0 Shape \"sphere\" \"float radius\" 0.6\n";
    ExpectFinite(RenderWorld(coated), "coatedconductor");
}

TEST(HostileInput, NegativeRoughnessIsAnErrorAtTheParameter) {
    for (const char* material :
         {"\"dielectric\" \"float roughness\" -0.5", "\"coateddiffuse\" \"float roughness\" -1",
          "\"conductor\" \"float vroughness\" -1e-3 \"float uroughness\" 0.1",
          "\"coatedconductor\" \"float conductor.roughness\" -2"}) {
        std::string error = ErrorOf(std::string(kView) + "WorldBegin\nMaterial " + material +
                                    "\nShape \"sphere\"\n");
        EXPECT_NE(error.find("<test>:8:"), std::string::npos) << error;
        EXPECT_NE(error.find("must be >= 0"), std::string::npos) << error;
    }
}

TEST(HostileInput, ShapesUnderSingularTransforms) {
    // pbrt-v4 accepts singular matrices (its own scenes flatten or hide objects with them)
    Rendered hidden = RenderWorld(R"(
Material "conductor" "float roughness" 0.1
AttributeBegin Scale 0 0 0 Shape "sphere" AttributeEnd
AttributeBegin ConcatTransform [1 0 0 0  0 0 0 0  0 0 1 0  0 1 0 1] Shape "cylinder" AttributeEnd
AttributeBegin Scale 1 1 0 Shape "disk" AttributeEnd
)");
    ExpectFinite(hidden, "hidden quadrics");
    EXPECT_TRUE(HasWarning(hidden, "singular transform has no area")) << "quadrics";

    // A mesh with shading normals flattened onto y = 0.5: still visible, no NaN normals
    Rendered flat = RenderWorld(R"(
Texture "noise" "spectrum" "fbm"
Material "diffuse" "texture reflectance" "noise"
AttributeBegin
  ConcatTransform [1 0 0 0  0 0 0 0  0 0 1 0  0 0.5 0 1]
  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
    "point3 P" [-1 0 -1  1 0 -1  1 3 1  -1 3 1] "normal N" [0 1 0  0 1 0  0 1 1  0 1 1]
    "point2 uv" [0 0 1 0 1 1 0 1]
  Shape "bilinearmesh" "point3 P" [-1 1 -1  1 1 -1  -1 1 1  1 1 1] "normal N" [0 1 0 0 1 0 0 1 0 0 1 0]
AttributeEnd
)");
    ExpectFinite(flat, "flattened meshes");
    Rendered floorOnly = RenderWorld("");
    EXPECT_GT(std::abs(flat.meanY - floorOnly.meanY), 1e-3 * floorOnly.meanY)
        << "the flattened meshes are visible";
}

TEST(HostileInput, LightsTexturesAndInstancesUnderSingularTransforms) {
    Rendered r = RenderWorld(R"(
AttributeBegin
  Scale 0 0 0
  LightSource "spot" "point3 from" [0 3 0] "point3 to" [0 0 0] "rgb I" [5 5 5]
  LightSource "infinite" "rgb L" [1 1 1]
  Texture "wood" "spectrum" "wrinkled"
AttributeEnd
Material "diffuse" "texture reflectance" "wood"
AttributeBegin Translate 0 0.5 0 Shape "sphere" "float radius" 0.5 AttributeEnd
ObjectBegin "ball" Shape "sphere" "float radius" 0.3 ObjectEnd
AttributeBegin Translate 1 0.3 0 ObjectInstance "ball" AttributeEnd
AttributeBegin Scale 0 1 1 ObjectInstance "ball" AttributeEnd
)");
    ExpectFinite(r, "lights, textures and instances");
    EXPECT_TRUE(HasWarning(r, "light \"spot\" under a singular transform"));
    EXPECT_TRUE(HasWarning(r, "texture 'wood' defined under a singular transform"));
    EXPECT_TRUE(HasWarning(r, "ObjectInstance 'ball' under a singular transform"));
}

TEST(HostileInput, SingularCameraTransformIsAnError) {
    std::string error = ErrorOf(R"(Scale 0 0 0
Camera "perspective"
WorldBegin
Shape "sphere"
)");
    EXPECT_NE(error.find("<test>:2:"), std::string::npos) << error;
    EXPECT_NE(error.find("camera transform is singular"), std::string::npos) << error;
}

TEST(HostileInput, ExtremeValuesRenderFinite) {
    // Temperatures from 0 to 1e6 K, radii from 1e-20 to 1e20, optical constants 0 or huge,
    // coordinates far from the origin: every sample finite
    const std::string cases[] = {
        R"(Material "diffuse" "float temperature" 1e6
           Translate 0 0.5 0 Shape "sphere" "float radius" 0.5)",
        R"(Material "conductor" "float roughness" 0.2 "float temperature" 0
           Translate 0 0.5 0 Shape "sphere" "float radius" 0.5)",
        R"(Material "conductor" "float roughness" 0 "float temperature" 1e-3
           Translate 0 0.5 0 Shape "sphere" "float radius" 1e-20)",
        R"(Material "diffuse" Shape "sphere" "float radius" 1e20)",
        R"(Material "conductor" "spectrum eta" [400 0 700 0] "spectrum k" [400 0 700 0]
           "float roughness" 0.1 "float temperature" 2000
           Translate 0 0.5 0 Shape "sphere" "float radius" 0.5)",
        R"(Material "conductor" "spectrum eta" [400 1e30 700 1e30] "spectrum k" [400 1e30 700 1e30]
           "float temperature" 2000 Translate 0 0.5 0 Shape "sphere" "float radius" 0.5)",
        R"(Material "dielectric" "float eta" 1e30 "float roughness" 0.3
           Translate 0 0.5 0 Shape "sphere" "float radius" 0.5)",
        R"(Material "coateddiffuse" "float eta" 1e-30 "float thickness" 1e30
           "float temperature" 1e5 Translate 0 0.5 0 Shape "sphere" "float radius" 0.5)",
        R"(AttributeBegin Translate 1e15 0 0 Scale 1e30 1e30 1e30
             Shape "sphere" "float radius" 1e20 AttributeEnd)",
        R"(Material "diffuse" "float temperature" 1500
           Shape "trianglemesh" "integer indices" [0 1 2] "point3 P" [-1 0 0 1 0 0 0 1e-30 0])",
    };
    for (const std::string& c : cases) {
        Rendered r = RenderWorld(c);
        EXPECT_EQ(r.nonFinite, 0) << c;
        EXPECT_EQ(r.nonFinitePixels, 0) << c;
    }
    // A whole scene, camera included, 1e15 from the origin
    testing::RenderedScene far = testing::RenderText(R"(
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
Sampler "zsobol" "integer pixelsamples" 8
LookAt 1e15 1.5 -4  1e15 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
LightSource "infinite" "rgb L" [0.4 0.45 0.5]
Translate 1e15 0 0
Material "conductor" "float roughness" 0.1 "float temperature" 1800
Shape "sphere" "float radius" 0.5
)");
    EXPECT_EQ(far.scene->job->film->NonFiniteSampleCount(), 0);
}

TEST(HostileInput, PerVertexTemperaturesMustBeKelvin) {
    std::string error = ErrorOf(std::string(kView) + R"(WorldBegin
Shape "trianglemesh" "integer indices" [0 1 2] "point3 P" [0 0 0 1 0 0 0 1 0]
    "float temperature" [300 -5 300]
)");
    EXPECT_NE(error.find("<test>:9:"), std::string::npos) << error;
    EXPECT_NE(error.find("vertex 1 has temperature -5"), std::string::npos) << error;
}

// Issue 23: a silver sphere at 1e38 K rendered with Stokes layers wrote S0 = 0 and S1, S2
// infinite. Temperatures are refused above 1e27 K (spectral/planck.h); just below, every
// layer is finite and the sphere is bright.
TEST(HostileInput, HotterThanRenderableIsAnErrorAndJustBelowIsFinite) {
    const char* hot = R"(WorldBegin
Material "conductor" "spectrum eta" "metal-Ag-eta" "spectrum k" "metal-Ag-k"
    "float temperature" %s
Shape "sphere" "float radius" 0.5
)";
    char scene[512];
    std::snprintf(scene, sizeof(scene), hot, "1e38");
    std::string error = ErrorOf(std::string(kView) + scene);
    EXPECT_NE(error.find("<test>:9:5: error: temperature must be a number of kelvin from 0 to "
                         "1e27 (at '1e+38')"),
              std::string::npos)
        << error;
    std::string mesh = std::string(kView) + R"(WorldBegin
Shape "trianglemesh" "integer indices" [0 1 2] "point3 P" [0 0 0 1 0 0 0 1 0]
    "float temperature" [300 2e27 300]
)";
    EXPECT_NE(ErrorOf(mesh).find("vertex 1 has temperature 2e+27"), std::string::npos);
    std::string grid = std::string(kView) + R"(WorldBegin
MakeNamedMedium "hot" "string type" "uniformgrid" "integer nx" 2 "integer ny" 1 "integer nz" 1
    "float density" [1 1] "float temperature" [1000 1e10] "float temperaturescale" 1e18
    "string emission" "kirchhoff"
)";
    EXPECT_NE(ErrorOf(grid).find("<test>:9:27: error: grid temperatures must be kelvin up to 1e27"),
              std::string::npos)
        << ErrorOf(grid);

    std::snprintf(scene, sizeof(scene), hot, "1e26");
    RenderOptions o;
    o.samplesPerPixel = 4;
    o.stokes = true;
    testing::RenderedScene r = testing::RenderText(std::string(kView) + scene, 0, o);
    const RGBFilm& film = *r.scene->job->film;
    EXPECT_EQ(film.NonFiniteSampleCount(), 0);
    Float brightest = 0;
    Bounds2i b = film.PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x)
            for (int k = 0; k < 4; ++k) {
                RGB c = film.GetPixelStokes({x, y}, k);
                ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b))
                    << "S" << k << " at " << x << ", " << y;
                if (k == 0) brightest = std::max(brightest, c.g);
            }
    EXPECT_GT(brightest, 1e20f);
}

TEST(HostileInput, PrimitivesBeyondFloatRangeAreSkipped) {
    Rendered r = RenderWorld(R"(
AttributeBegin
  Scale 1e30 1e30 1e30
  Shape "bilinearmesh" "integer indices" [0 1 2 3 0 4 2 5]
    "point3 P" [0 0 0 1e20 0 0 0 1 0 1 1 0 2 0 0 2 1 0]
  Shape "sphere" "float radius" 1e20
AttributeEnd
Shape "sphere" "float radius" 1e18
Shape "trianglemesh" "integer indices" [0 1 2] "point3 P" [0 0 0 1 0 0 0 2e17 0]
)");
    ExpectFinite(r, "overflowing primitives");
    const char* beyond = " primitives extend beyond float range or +-1e+17";
    EXPECT_TRUE(HasWarning(r, std::string("2 of 2 \"bilinearmesh\"") + beyond));
    EXPECT_TRUE(HasWarning(r, std::string("1 of 1 \"sphere\"") + beyond));
    EXPECT_TRUE(HasWarning(r, std::string("1 of 1 \"trianglemesh\"") + beyond));
}

// Issue 23: these aborted inside Embree ("Assertion 'ray.valid()' failed"). A sphere of radius
// 1e10 overflowed its normal (the squared length of dp/du x dp/dv, near 1e40, in float); a
// hit within 1e-22 of a sphere's pole (every ray of a camera with fov 1e-20 or an orthographic
// window of 1e-30 hits the pole) underflowed it. Each renders finite and lit.
TEST(HostileInput, ExtremeSpheresAndCamerasRenderFinite) {
    const char* film = R"(
Film "rgb" "integer xresolution" 12 "integer yresolution" 12
Sampler "zsobol" "integer pixelsamples" 4
LookAt 0 0 5  0 0 0  0 1 0
)";
    const char* world = R"(WorldBegin
LightSource "distant" "point3 from" [0 0 10] "point3 to" [0 0 0] "rgb L" [1 1 1]
Material "diffuse"
)";
    std::string cameraInside =
        std::string(film) + "Camera \"perspective\"\n" + world +
        "Material \"conductor\" \"float roughness\" 0.3 "
        "\"float temperature\" 1500\nShape \"sphere\" \"float radius\" 1e10\n";
    ExpectFinite(testing::RenderStats(cameraInside, 1, 4), "inside a hot sphere of radius 1e10");
    const char* cameras[] = {
        "Camera \"perspective\" \"float fov\" 1e-20",
        "Camera \"orthographic\" \"float screenwindow\" [-1e-30 1e-30 -1e-30 1e-30]",
        ("Camera \"perspective\" \"float fov\" 1e-20 \"float lensradius\" 1e-25 "
         "\"float focaldistance\" 4")};
    for (const char* camera : cameras) {
        std::string scene =
            std::string(film) + camera + "\n" + world +
            "Shape \"sphere\" \"float radius\" 1\nShape \"disk\" \"float height\" -1\n";
        ExpectFinite(testing::RenderStats(scene, 1, 4), camera);
    }
}

TEST(HostileInput, CamerasThatWouldStartRaysOutOfRangeAreErrorsAtTheParameter) {
    const char* world = "WorldBegin\nShape \"sphere\"\n";
    struct Case {
        const char* camera;
        const char* error;
    } cases[] = {
        {"Camera \"orthographic\" \"float screenwindow\" [-1e20 1e20 -1 1]",
         "<test>:3:23: error: camera rays would start beyond +-1e17"},
        {"Camera \"perspective\" \"float lensradius\" 1e30 \"float focaldistance\" 5",
         "<test>:3:22: error: camera rays would start beyond +-1e17"},
        {"Camera \"perspective\" \"float screenwindow\" [0 1e-45 0 1]",
         "<test>:3:22: error: \"screenwindow\" is degenerate or not finite"},
        {"Camera \"perspective\" \"float lensradius\" -1", "\"lensradius\" must be finite"},
    };
    for (const Case& c : cases) {
        std::string error = ErrorOf(std::string("Film \"rgb\"\n\n") + c.camera + "\n" + world);
        EXPECT_NE(error.find(c.error), std::string::npos) << c.camera << "\n" << error;
    }
}

TEST(HostileInput, InstancesAndCurvesOutOfRangeAreSkippedOrErrors) {
    // An instance scaled by 1e-30 is traced in its own space, where the scene's rays are 1e30
    // times longer than Embree accepts; one translated by 1e18 lies beyond the range
    Rendered r = RenderWorld(R"(
ObjectBegin "ball"
  Shape "sphere" "float radius" 0.5
ObjectEnd
AttributeBegin
  Scale 1e-30 1e-30 1e-30
  ObjectInstance "ball"
AttributeEnd
AttributeBegin
  Translate 1e18 0 0
  ObjectInstance "ball"
AttributeEnd
AttributeBegin
  Translate 0 0.5 0
  ObjectInstance "ball"
AttributeEnd
)");
    ExpectFinite(r, "instances out of range");
    int skipped = 0;
    for (const std::string& w : r.warnings)
        skipped += w.find(
                       "instance of \"ball\" under a singular transform, or one that takes it "
                       "or the scene's rays beyond") != std::string::npos;
    EXPECT_EQ(skipped, 2);
    std::string error = ErrorOf(std::string(kView) + R"(WorldBegin
Shape "curve" "point3 P" [0 0 0 1 1 0 2 0 0 3 1e18 0] "float width" 0.1
)");
    EXPECT_NE(error.find("<test>:8:15: error: curve reaches beyond +-1e17"), std::string::npos)
        << error;
}

}  // namespace
}  // namespace kiln
