// Numerical stress tests at render level: degenerate geometry and emitters, far-from-origin
// scenes, camera inside geometry, grazing views, extreme roughness, empty and unlit scenes.
// Every render must produce only finite radiance samples (the film's NonFiniteSampleCount).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "../render/render_test_util.h"
#include "image_stats.h"
#include "noise_comparison.h"

namespace kiln {
namespace {

const char* kHeader = R"(
Film "rgb" "integer xresolution" 24 "integer yresolution" 24
Sampler "zsobol" "integer pixelsamples" 16
Integrator "path" "integer maxdepth" 8
)";

using testing::ImageStats;
using testing::kEnvAndFloor;
using testing::RenderStats;

void ExpectFinite(const std::string& world, const char* what, bool expectLight = true) {
    std::string text = std::string(kHeader) + world;
    ImageStats s = RenderStats(text);
    EXPECT_EQ(s.nonFinite, 0) << what;
    EXPECT_EQ(s.nonFinitePixels, 0) << what;
    if (expectLight) {
        EXPECT_GT(s.meanY, 0) << what;  // not vacuous
    }
}

TEST(StressTest, DegenerateAndSliverTriangles) {
    ExpectFinite(std::string(R"(LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
)") + kEnvAndFloor + R"(
Material "conductor" "float roughness" 0.2
# collinear, repeated-vertex, 1e-7-wide sliver, 1e-30-area, and a normal mesh
Shape "trianglemesh" "integer indices" [0 1 2  3 3 4  5 6 7  8 9 10  11 12 13]
  "point3 P" [-1 0.5 0  0 0.5 0  1 0.5 0   0 1 0  1 1 0
              -1 0 0.5  1 0 0.5  0 1e-7 0.5   0 0.3 0  1e-15 0.3 0  0 0.3 1e-15
              -1 0 1  1 0 1  0 1.5 1]
  "normal N" [0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0
              0 0 -1  0 0 -1  0 0 -1]
Material "dielectric" "float eta" 1.5
Shape "trianglemesh" "integer indices" [0 1 2]
  "point3 P" [-0.5 0.2 -0.5  0.5 0.2 -0.5  0 0.2000001 -0.5]
)",
                 "degenerate triangles");
}

// Each zero-size emitter alone: it must either be rejected with a SceneError (file:line) or
// render with finite values (the floor is lit by the environment either way).
TEST(StressTest, ZeroAreaAndZeroRadiusEmitters) {
    const char* emitters[] = {
        R"(Shape "sphere" "float radius" 0)",
        R"(Shape "sphere" "float radius" 1e-20)",
        R"(Shape "disk" "float radius" 0)",
        R"(Shape "disk" "float radius" 1e-20)",
        R"(Shape "cylinder" "float radius" 0 "float zmin" 0 "float zmax" 1)",
        R"(Shape "cylinder" "float radius" 1 "float zmin" 0 "float zmax" 0)",
        R"(Shape "trianglemesh" "integer indices" [0 1 2] "point3 P" [0 0 0  1 0 0  2 0 0])",
        R"(Shape "trianglemesh" "integer indices" [0 1 2] "point3 P" [0 0 0  0 0 0  0 0 0])",
        R"(Shape "bilinearmesh" "integer indices" [0 1 2 3] "point3 P" [0 0 0 0 0 0 0 0 0 0 0 0])",
    };
    int rendered = 0;
    for (const char* shape : emitters) {
        std::string world = std::string(R"(LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
)") + kEnvAndFloor + R"(
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [10 10 10]
  Translate 0 1 0
  )" + shape + R"(
AttributeEnd
)";
        try {
            ExpectFinite(world, shape);
            ++rendered;
        } catch (const SceneError& e) {
            RecordProperty(shape, e.what());
            std::printf("rejected: %s\n", e.what());
        }
    }
    EXPECT_GE(rendered, 4);
}

TEST(StressTest, DegenerateLights) {
    ExpectFinite(std::string(R"(LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
)") + kEnvAndFloor + R"(
LightSource "point" "point3 from" [0 0 0] "rgb I" [0 0 0]
LightSource "point" "point3 from" [0 1e-30 0] "rgb I" [1 1 1]
LightSource "spot" "point3 from" [0 2 0] "point3 to" [0 1 0] "rgb I" [1 1 1]
  "float coneangle" 0 "float conedeltaangle" 0
LightSource "spot" "point3 from" [0 2 0] "point3 to" [0 1 0] "rgb I" [1 1 1]
  "float coneangle" 10 "float conedeltaangle" 30
)",
                 "degenerate lights");
}

// Found by this suite: "distant" and "spot" lights with from == to normalise a zero vector
// (src/lights/light_create.cpp:99 and :117), so the light direction is NaN and the first shadow
// ray aborts the process in Embree (assertion `ray.valid()`). Enable once they are rejected
// with a SceneError or given a default direction.
TEST(StressTest, LightsWithFromEqualToToAreRejected) {
    // A zero-length direction used to become NaN and abort inside Embree; now it is an error
    // at the light's parameters.
    for (const char* light :
         {R"(LightSource "distant" "point3 from" [0 1 0] "point3 to" [0 1 0] "rgb L" [1 1 1])",
          R"(LightSource "spot" "point3 from" [0 2 0] "point3 to" [0 2 0] "rgb I" [1 1 1])"}) {
        std::string what;
        try {
            ExpectFinite(std::string(R"(LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
)") + kEnvAndFloor + light,
                         light);
        } catch (const SceneError& e) {
            what = e.what();
        }
        EXPECT_NE(what.find("must differ"), std::string::npos) << light;
    }
}

TEST(StressTest, CameraInsideClosedSphere) {
    // Inside a diffuse sphere lit by a small emitter inside it; and inside an emitting sphere.
    ExpectFinite(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "perspective" "float fov" 90
WorldBegin
Material "diffuse" "rgb reflectance" [0.8 0.8 0.8]
Shape "sphere" "float radius" 3
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [5 5 5]
  Translate 0 1 0.5
  Shape "sphere" "float radius" 0.2
AttributeEnd
)",
                 "inside diffuse sphere");
    ExpectFinite(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "perspective" "float fov" 90
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 1 1] "bool twosided" true
  Material "dielectric" "float eta" 1.33 "float roughness" 0.5
  Shape "sphere" "float radius" 1
AttributeEnd
)",
                 "inside emitting rough-glass sphere");
}

TEST(StressTest, GrazingViewsOfSmoothConductor) {
    for (const char* eye : {"0 1e-3 -10", "0 1e-6 -10", "0 0 -10"})
        ExpectFinite(std::string("LookAt ") + eye + R"(  0 0 10  0 1 0
Camera "perspective" "float fov" 10
WorldBegin
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
LightSource "distant" "point3 from" [0 1e-4 1] "point3 to" [0 0 0] "rgb L" [3 3 3]
Material "conductor" "float roughness" 0
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
  "point3 P" [-100 0 -100  100 0 -100  100 0 100  -100 0 100]
Material "conductor" "float roughness" 1e-4
Shape "sphere" "float radius" 1
)",
                     eye);
}

TEST(StressTest, RoughDielectricAtRoughnessZeroAndOne) {
    for (const char* rough : {"0", "1e-5", "0.001", "1"})
        for (const char* eta : {"1.5", "1", "0.67"})
            ExpectFinite(std::string(R"(LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
)") + kEnvAndFloor + R"(
LightSource "point" "point3 from" [1 3 -1] "rgb I" [5 5 5]
Material "dielectric" "float eta" )" +
                             eta + " \"float roughness\" " + rough + R"(
Translate 0 0.6 0
Shape "sphere" "float radius" 0.6
Material "dielectric" "float eta" )" +
                             eta + " \"float uroughness\" " + rough + R"( "float vroughness" 0.5
Translate 1.3 0 0
Shape "sphere" "float radius" 0.5
)",
                         (std::string("rough dielectric ") + rough + " eta " + eta).c_str());
}

TEST(StressTest, EmptySceneAndSceneWithoutLightsAreBlack) {
    ImageStats empty = RenderStats(std::string(kHeader) + R"(LookAt 0 0 -1  0 0 0  0 1 0
Camera "perspective"
WorldBegin
)");
    EXPECT_EQ(empty.nonFinite, 0);
    EXPECT_EQ(empty.meanY, 0);
    ImageStats dark = RenderStats(std::string(kHeader) + R"(LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
WorldBegin
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "sphere" "float radius" 1
Material "dielectric" "float eta" 1.5 "float roughness" 0.2
Shape "trianglemesh" "integer indices" [0 1 2]  "point3 P" [-5 0 -5  5 0 -5  0 0 5]
)");
    EXPECT_EQ(dark.nonFinite, 0);
    EXPECT_EQ(dark.meanY, 0);
}

// The diffuse box of the regression suite, optionally wrapped in a world transform.
std::string BoxScene(const std::string& lookAt, const std::string& worldTransform) {
    return std::string(R"(
Film "rgb" "integer xresolution" 24 "integer yresolution" 24
Sampler "zsobol" "integer pixelsamples" 16
Integrator "path" "integer maxdepth" 5
)") + lookAt +
           R"(
Camera "perspective" "float fov" 40
WorldBegin
)" + worldTransform +
           R"(
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [6 5.5 5]
  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
    "point3 P" [-0.3 1.99 -0.3  0.3 1.99 -0.3  0.3 1.99 0.3  -0.3 1.99 0.3]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.7 0.7 0.7]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3  4 5 6 4 6 7  8 9 10 8 10 11
                                        12 13 14 12 14 15  16 17 18 16 18 19]
  "point3 P" [-1 0 -1  -1 0 1  1 0 1  1 0 -1
              -1 2 -1  1 2 -1  1 2 1  -1 2 1
              -1 0 -1  1 0 -1  1 2 -1  -1 2 -1
              -1 0 -1  -1 2 -1  -1 2 1  -1 0 1
              1 0 -1  1 0 1  1 2 1  1 2 -1]
Material "coateddiffuse" "rgb reflectance" [0.5 0.3 0.2] "float roughness" 0.05
AttributeBegin
  Translate -0.35 0.35 -0.2
  Shape "sphere" "float radius" 0.35
AttributeEnd
)";
}

// Mean luminance per seed of the two scenes; Welch's t statistic of the difference.
double MeanLuminanceT(const std::string& a, const std::string& b, double* meanA, double* meanB) {
    const int K = 8;
    double s[2] = {0, 0}, s2[2] = {0, 0};
    for (int k = 0; k < K; ++k) {
        ImageStats ia = RenderStats(a, 1 + k), ib = RenderStats(b, 101 + k);
        EXPECT_EQ(ia.nonFinite, 0);
        EXPECT_EQ(ib.nonFinite, 0);
        double v[2] = {ia.meanY, ib.meanY};
        for (int i = 0; i < 2; ++i) s[i] += v[i], s2[i] += v[i] * v[i];
    }
    double m[2], var[2];
    for (int i = 0; i < 2; ++i) {
        m[i] = s[i] / K;
        var[i] = std::max(0.0, (s2[i] - K * m[i] * m[i]) / (K - 1));
    }
    *meanA = m[0];
    *meanB = m[1];
    return (m[0] - m[1]) / std::sqrt((var[0] + var[1]) / K + 1e-30);
}

TEST(StressTest, SceneFarFromOriginMatchesSceneAtOrigin) {
    std::string atOrigin = BoxScene("LookAt 0 1 3.4  0 1 0  0 1 0", "");
    // Camera and scene translated by 1e6 in x, y and z (float spacing there: 1/16).
    std::string far =
        BoxScene("LookAt 1e6 1000001 1000003.4  1e6 1000001 1e6  0 1 0", "Translate 1e6 1e6 1e6");
    // Camera at the origin, the scene 3.4e5 units away and scaled by 1e5 (render space is
    // camera-world, so here the ray offsets must cope with large coordinates).
    std::string huge = BoxScene("LookAt 0 1 3.4  0 1 0  0 1 0",
                                "Translate 0 1 3.4  Scale 1e5 1e5 1e5  Translate 0 -1 -3.4");
    double mOrigin, mFar, mHuge, unused;
    double tFar = MeanLuminanceT(atOrigin, far, &mOrigin, &mFar);
    double tHuge = MeanLuminanceT(atOrigin, huge, &unused, &mHuge);
    std::printf("mean Y: origin %.5f, 1e6 away %.5f (t %.2f), scaled 1e5 %.5f (t %.2f)\n", mOrigin,
                mFar, tFar, mHuge, tHuge);
    EXPECT_GT(mOrigin, 0.01);
    // 8 + 8 renders: |t| > 5 has probability < 1e-3 for equal means (t, ~14 dof).
    EXPECT_LT(std::abs(tFar), 5) << "origin " << mOrigin << " vs 1e6 away " << mFar;
    EXPECT_LT(std::abs(tHuge), 5) << "origin " << mOrigin << " vs scaled 1e5 " << mHuge;
}

}  // namespace
}  // namespace kiln
