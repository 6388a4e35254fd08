// The spherical camera: directions of both mappings (pbrt-v4's axes), equal solid angle per
// pixel for "equalarea", the film edge's wrap, footprints and creation.
#include <gtest/gtest.h>

#include <cmath>

#include "base/rng.h"
#include "base/sphere_mappings.h"
#include "core/camera/camera.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {
namespace {

Camera MakeSpherical(ObjectArena& arena, Diagnostics& diag, const std::string& mapping, Point2i res,
                     const Transform& worldFromCamera = Transform()) {
    ParsedParameterVector params;
    if (!mapping.empty()) {
        ParsedParameter p;
        p.type = "string";
        p.name = "mapping";
        p.strings = {mapping};
        params.push_back(p);
    }
    ParameterDictionary dict(std::move(params), nullptr);
    return Camera::Create("spherical", dict, CameraTransform(worldFromCamera), res, 0.035f,
                          FileLoc(), arena, diag);
}

Vector3f Direction(const Camera& c, Point2f pFilm) {
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    CameraSample s;
    s.pFilm = pFilm;
    std::optional<CameraRay> r = c.GenerateRay(s, lambda);
    EXPECT_TRUE(r.has_value());
    EXPECT_EQ(r->weight[0], 1);
    EXPECT_EQ(r->ray.o, Point3f(0, 0, 0));
    return r->ray.d;
}

TEST(SphericalCamera, EquirectangularAxes) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    Camera c = MakeSpherical(arena, diag, "equirectangular", Point2i(64, 32));
    EXPECT_EQ(diag.WarningCount(), 0);
    // Top row: camera +y; middle row at u = 1/4: camera +z (forward); u = 0: camera +x
    EXPECT_NEAR(Direction(c, Point2f(10, 0)).y, 1, 1e-6);
    EXPECT_NEAR(Direction(c, Point2f(16, 16)).z, 1, 1e-6);
    EXPECT_NEAR(Direction(c, Point2f(0, 16)).x, 1, 1e-6);
    EXPECT_NEAR(Direction(c, Point2f(32, 16)).x, -1, 1e-6);
    // The camera transform applies (rotated a quarter turn about y: forward becomes +x)
    Camera r = MakeSpherical(arena, diag, "equirectangular", Point2i(64, 32),
                             Rotate(90, Vector3f(0, 1, 0)));
    EXPECT_NEAR(Direction(r, Point2f(16, 16)).x, 1, 1e-5);
}

TEST(SphericalCamera, EqualAreaIsTheOctahedralMapWithYUp) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    Camera c = MakeSpherical(arena, diag, "", Point2i(32, 32));  // equalarea by default
    EXPECT_EQ(c.GetIf<SphericalCamera>()->GetMapping(), SphericalCamera::Mapping::EqualArea);
    RNG rng(2);
    for (int i = 0; i < 1000; ++i) {
        Point2f uv(rng.UniformFloat(), rng.UniformFloat());
        Vector3f d = Direction(c, Point2f(32 * uv.x, 32 * uv.y));
        Vector3f m = EqualAreaSquareToSphere(uv);
        EXPECT_NEAR(d.x, m.x, 1e-5);
        EXPECT_NEAR(d.y, m.z, 1e-5);  // the mapping's pole is camera +y
        EXPECT_NEAR(d.z, m.y, 1e-5);
    }
    // The film centre looks up; film positions beyond the edge wrap (filters reach there)
    EXPECT_NEAR(Direction(c, Point2f(16, 16)).y, 1, 1e-6);
    Vector3f a = Direction(c, Point2f(-0.2f, 10)), b = Direction(c, Point2f(0.2f, 10));
    EXPECT_LT(Length(a - b), 0.05f);
    // Every pixel spans 4 pi / 1024 sr: the fraction of pixels seeing the upper half (camera
    // y > 0) is one half, and of the cap y > 0.9, 0.05
    // (Sample points on the equator itself, the square's inner diamond, count half)
    double upper = 0, cap = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int k = 0; k < 16; ++k) {
                Vector3f d = Direction(c, Point2f(x + (k % 4 + 0.5f) / 4, y + (k / 4 + 0.5f) / 4));
                upper += d.y > 0 ? 1 : d.y == 0 ? 0.5 : 0;
                cap += d.y > 0.9f;
            }
    EXPECT_NEAR(upper / 16384.0, 0.5, 0.005);
    EXPECT_NEAR(cap / 16384.0, 0.05, 0.005);
}

TEST(SphericalCamera, FootprintAndCreation) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    Camera c = MakeSpherical(arena, diag, "equalarea", Point2i(64, 64));
    // A pixel spans about sqrt(4 pi / 64^2) rad: the footprint at distance 10 is of that order
    Vector3f dpdx, dpdy;
    c.Approximate_dp_dxy(Point3f(0, 0, 10), Normal3f(0, 0, -1), 0, 1, &dpdx, &dpdy);
    Float pixel = 10 * std::sqrt(4 * Pi / (64 * 64));
    EXPECT_GT(Length(dpdx), 0.2f * pixel);
    EXPECT_LT(Length(dpdx), 2 * pixel);
    EXPECT_GT(Length(dpdy), 0.2f * pixel);
    // A non-square film with "equalarea": a warning (pbrt-v4 stretches the map silently)
    EXPECT_EQ(diag.WarningCount(), 0);
    MakeSpherical(arena, diag, "equalarea", Point2i(64, 32));
    EXPECT_EQ(diag.WarningCount(), 1);
    EXPECT_THROW(MakeSpherical(arena, diag, "cubemap", Point2i(8, 8)), SceneError);
}

}  // namespace
}  // namespace kiln
