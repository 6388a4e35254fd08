// Bump and normal mapping (materials/shading_perturbation.h) against the geometry they stand
// for: a displacement linear in uv tilts a plane's normal by its slope, a constant one on a
// sphere scales the tangents by (r + h) / r, and a normal map's texel is the normal in the
// tangent frame, with v flipped as pbrt-v4 reads images.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/image/image.h"
#include "material_test_util.h"
#include "materials/shading_perturbation.h"
#include "textures/basic_textures.h"

namespace kiln {
namespace {

using test::MaterialFixture;

// The plane z = 0 at (u, v), dp/du = +x, dp/dv = +y, normal +z.
SurfaceInteraction PlanePoint(Point2f uv) {
    return SurfaceInteraction(Point3f(uv.x, uv.y, 0), uv, Vector3f(0, 0, 1), Vector3f(1, 0, 0),
                              Vector3f(0, 1, 0), Normal3f(0, 0, 0), Normal3f(0, 0, 0), 0, false);
}

void ExpectDirection(Vector3f got, Vector3f want, Float tol = 1e-4f) {
    want = Normalize(want);
    EXPECT_NEAR(got.x, want.x, tol) << got.x << " " << got.y << " " << got.z;
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

TEST(BumpMapTest, LinearDisplacementTiltsThePlaneByItsSlope) {
    MaterialFixture f;
    // d(u, v) = 0.3 u - 0.2 v
    f.AddBilerpFloat("d", 0, 0.3f, -0.2f, 0.1f);
    const Material* m = f.Make("diffuse", {test::Texture("displacement", "d")});
    ASSERT_TRUE(m->Perturbation().displacement);
    EXPECT_TRUE(m->UsesFootprint());  // the finite differences span the footprint
    for (Float footprint : {0.f, 0.01f}) {
        SurfaceInteraction si = PlanePoint({0.4f, 0.6f});
        si.dudx = si.dvdy = footprint;
        ApplyShadingPerturbation(m->Perturbation(), si);
        // The surface z = d(x, y) has normal (-dd/dx, -dd/dy, 1)
        ExpectDirection(Vector3f(si.shading.n), Vector3f(-0.3f, 0.2f, 1), 2e-3f);
        EXPECT_EQ(si.n, Normal3f(0, 0, 1));  // the geometric normal stays
    }
}

TEST(BumpMapTest, ConstantDisplacementOnASphereScalesItsTangents) {
    // Sphere of radius 2 at (theta, phi): dn/du = dp/du / r, so a displacement h moves the
    // point along n and lengthens both tangents by (r + h) / r, the normal unchanged.
    const Float r = 2, h = 0.5f, theta = 1.1f, phi = 0.7f;
    Vector3f n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    Vector3f dpdu(-r * std::sin(theta) * std::sin(phi), r * std::sin(theta) * std::cos(phi), 0);
    Vector3f dpdv(r * std::cos(theta) * std::cos(phi), r * std::cos(theta) * std::sin(phi),
                  -r * std::sin(theta));
    SurfaceInteraction si(Point3f(r * n), Point2f(0.1f, 0.3f), n, dpdu, dpdv, Normal3f(dpdu / r),
                          Normal3f(dpdv / r), 0, false);
    si.shading.n = si.n = FaceForward(si.n, n);
    MaterialFixture f;
    ShadingPerturbation p;
    p.displacement = f.arena.New<FloatConstantTexture>(h);
    Vector3f bu, bv;
    BumpMap(*p.displacement, si, &bu, &bv);
    EXPECT_NEAR(Length(bu) / Length(dpdu), (r + h) / r, 1e-5f);
    EXPECT_NEAR(Length(bv) / Length(dpdv), (r + h) / r, 1e-5f);
    ApplyShadingPerturbation(p, si);
    ExpectDirection(Vector3f(si.shading.n), n);
}

// A normal-map file of 1 x 2 texels: the top row tilts the normal by +30 degrees towards +u,
// the bottom row by -30 degrees.
std::string WriteNormalMap() {
    std::string file = ::testing::TempDir() + "/kiln_normal_map.exr";
    Image image(PixelFormat::Float, {1, 2}, {"R", "G", "B"});
    const Float s = std::sin(Radians(30.f)), c = std::cos(Radians(30.f));
    for (int y = 0; y < 2; ++y) {
        Float x = y == 0 ? s : -s;
        image.SetChannel({0, y}, 0, 0.5f * x + 0.5f);
        image.SetChannel({0, y}, 1, 0.5f);
        image.SetChannel({0, y}, 2, 0.5f * c + 0.5f);
    }
    image.Write(file);
    return file;
}

TEST(NormalMapTest, TexelIsTheNormalInTheTangentFrameWithVFlipped) {
    MaterialFixture f;
    std::string file = WriteNormalMap();
    const Material* m = f.Make("conductor", {test::String1("normalmap", file)});
    ASSERT_NE(m->Perturbation().normalMap, nullptr);
    EXPECT_FALSE(m->UsesFootprint());
    const Float s = std::sin(Radians(30.f)), c = std::cos(Radians(30.f));
    // v = 0.75 reads row 0.25 of the image from the top: the centre of the top texel
    for (auto [v, sign] : {std::pair{0.75f, 1.f}, std::pair{0.25f, -1.f}}) {
        SurfaceInteraction si = PlanePoint({0.5f, v});
        // A tangent frame rotated about the normal: the map follows dp/du
        si.shading.dpdu = Vector3f(0, 2, 0);
        si.shading.dpdv = Vector3f(-3, 0, 0);
        ApplyShadingPerturbation(m->Perturbation(), si);
        ExpectDirection(Vector3f(si.shading.n), Vector3f(0, sign * s, c));
        EXPECT_NEAR(Length(si.shading.dpdu), 2, 1e-5f);  // lengths kept
        EXPECT_NEAR(Length(si.shading.dpdv), 3, 1e-5f);
        EXPECT_NEAR(Dot(si.shading.dpdu, Vector3f(si.shading.n)), 0, 1e-5f);
    }
    // Shared between materials naming the same file
    const Material* m2 = f.Make("diffuse", {test::String1("normalmap", file)});
    EXPECT_EQ(m2->Perturbation().normalMap, m->Perturbation().normalMap);
}

TEST(NormalMapTest, UnreadableOrDegenerateMapsAreHandled) {
    MaterialFixture f;
    // A missing file is a located error naming the file
    try {
        f.Make("diffuse", {test::String1("normalmap", "/nonexistent/n.png")});
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("normal map"), std::string::npos) << e.what();
        EXPECT_EQ(e.Token(), "/nonexistent/n.png");
    }
    // A grey texel (the zero vector) leaves the frame as it was; huge uv stay finite
    std::string file = ::testing::TempDir() + "/kiln_grey_normal_map.exr";
    Image grey(PixelFormat::Float, {2, 2}, {"R", "G", "B"});
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            for (int c = 0; c < 3; ++c) grey.SetChannel({x, y}, c, 0.5f);
    grey.Write(file);
    const Material* m = f.Make("diffuse", {test::String1("normalmap", file)});
    for (Float u : {0.3f, 1e30f}) {
        SurfaceInteraction si = PlanePoint({u, 0.3f});
        ApplyShadingPerturbation(m->Perturbation(), si);
        EXPECT_EQ(si.shading.n, Normal3f(0, 0, 1));
        EXPECT_EQ(si.shading.dpdu, Vector3f(1, 0, 0));
    }
}

}  // namespace
}  // namespace kiln
