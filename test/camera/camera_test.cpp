// Cameras: camera transform, perspective and orthographic rays, thin-lens focus,
// Approximate_dp_dxy, creation; GetCameraSample.
#include "core/camera/camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../textures/param_helpers.h"
#include "core/camera/sampler.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {
namespace {

Float AngleDegrees(Vector3f a, Vector3f b) {
    return Degrees(AngleBetween(Normalize(a), Normalize(b)));
}

struct Fixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);

    Camera Make(const std::string& name, ParsedParameterVector params, Point2i res,
                const Transform& worldFromCamera = Transform()) {
        ParameterDictionary dict(std::move(params), nullptr);
        return Camera::Create(name, dict, CameraTransform(worldFromCamera), res, 0.035f, FileLoc(),
                              arena, diag);
    }
    Ray RayAt(const Camera& c, Point2f pFilm, Point2f pLens = Point2f(0.5f, 0.5f)) {
        CameraSample s;
        s.pFilm = pFilm;
        s.pLens = pLens;
        s.time = 0.5f;
        std::optional<CameraRay> r = c.GenerateRay(s, lambda);
        EXPECT_TRUE(r.has_value());
        return r ? r->ray : Ray();
    }
};

TEST(CameraTransform, CameraAtTenMapsToRenderOrigin) {
    CameraTransform ct(Translate(Vector3f(10, 0, 0)));
    Point3f p = ct.RenderFromWorld()(Point3f(10, 0, 0));
    EXPECT_NEAR(p.x, 0, 1e-6);
    EXPECT_NEAR(p.y, 0, 1e-6);
    EXPECT_NEAR(p.z, 0, 1e-6);
    Point3f c = ct.RenderFromCamera()(Point3f(0, 0, 0));
    EXPECT_NEAR(Length(Vector3f(c)), 0, 1e-6);
    Point3f w = ct.WorldFromRender()(Point3f(1, 2, 3));
    EXPECT_NEAR(w.x, 11, 1e-5);
    EXPECT_NEAR(w.y, 2, 1e-5);
    // Orientation is that of world space (render space only translates).
    Vector3f d = ct.RenderFromWorld()(Vector3f(0, 0, 1));
    EXPECT_NEAR(d.z, 1, 1e-6);
    Point3f back = ct.CameraFromRender()(ct.RenderFromCamera()(Point3f(1, -2, 5)));
    EXPECT_NEAR(back.y, -2, 1e-5);
}

TEST(CameraTransform, LookAtCameraRaysInRenderSpace) {
    Fixture fx;
    // Camera at world (10, 0, 0) looking towards +x.
    std::optional<Transform> cameraFromWorld =
        LookAt(Point3f(10, 0, 0), Point3f(20, 0, 0), Vector3f(0, 1, 0));
    ASSERT_TRUE(cameraFromWorld);
    Camera cam = fx.Make("perspective", {}, Point2i(64, 64), Inverse(*cameraFromWorld));
    Ray r = fx.RayAt(cam, Point2f(32, 32));
    EXPECT_NEAR(Length(Vector3f(r.o)), 0, 1e-5);
    EXPECT_NEAR(r.d.x, 1, 1e-5);
    EXPECT_NEAR(Length(r.d), 1, 1e-6);
    // Top of the image is +y (world up).
    EXPECT_GT(fx.RayAt(cam, Point2f(32, 0)).d.y, 0);
}

TEST(PerspectiveCamera, CentreRayPointsDownZ) {
    Fixture fx;
    Camera cam = fx.Make("perspective", {}, Point2i(100, 60));
    Ray r = fx.RayAt(cam, Point2f(50, 30));
    EXPECT_NEAR(r.d.x, 0, 1e-6);
    EXPECT_NEAR(r.d.y, 0, 1e-6);
    EXPECT_NEAR(r.d.z, 1, 1e-6);
    EXPECT_EQ(r.o, Point3f(0, 0, 0));
    EXPECT_FLOAT_EQ(r.time, 0.5f);
    // Raster x to the right is camera +x; raster y down is camera -y.
    EXPECT_GT(fx.RayAt(cam, Point2f(90, 30)).d.x, 0);
    EXPECT_LT(fx.RayAt(cam, Point2f(50, 55)).d.y, 0);
}

TEST(PerspectiveCamera, FovSpansShorterAxis) {
    Fixture fx;
    Vector3f z(0, 0, 1);
    // Landscape: fov is vertical.
    Camera land = fx.Make("perspective", {test::Floats("float", "fov", {60})}, Point2i(200, 100));
    EXPECT_NEAR(AngleDegrees(fx.RayAt(land, Point2f(100, 0)).d, z), 30, 1e-3);
    EXPECT_NEAR(AngleDegrees(fx.RayAt(land, Point2f(100, 100)).d, z), 30, 1e-3);
    Float horiz = Degrees(std::atan(2 * std::tan(Radians(30))));
    EXPECT_NEAR(AngleDegrees(fx.RayAt(land, Point2f(0, 50)).d, z), horiz, 1e-3);
    // Portrait: fov is horizontal.
    Camera port = fx.Make("perspective", {test::Floats("float", "fov", {60})}, Point2i(100, 200));
    EXPECT_NEAR(AngleDegrees(fx.RayAt(port, Point2f(0, 100)).d, z), 30, 1e-3);
    EXPECT_NEAR(AngleDegrees(fx.RayAt(port, Point2f(50, 0)).d, z), horiz, 1e-3);
    // Default fov 90 on a square image.
    Camera sq = fx.Make("perspective", {}, Point2i(64, 64));
    EXPECT_NEAR(AngleDegrees(fx.RayAt(sq, Point2f(64, 32)).d, z), 45, 1e-3);
}

TEST(PerspectiveCamera, ScreenWindowAndAspect) {
    Fixture fx;
    Vector3f z(0, 0, 1);
    // A screen window of [0,1]x[0,1] puts the image centre's ray at the window centre.
    Camera cam = fx.Make(
        "perspective",
        {test::Floats("float", "fov", {90}), test::Floats("float", "screenwindow", {0, 1, 0, 1})},
        Point2i(10, 10));
    Vector3f d = fx.RayAt(cam, Point2f(5, 5)).d;
    EXPECT_NEAR(d.x / d.z, 0.5f, 1e-5);
    EXPECT_NEAR(d.y / d.z, 0.5f, 1e-5);
    EXPECT_THROW(
        fx.Make("perspective", {test::Floats("float", "screenwindow", {0, 1, 0})}, Point2i(10, 10)),
        SceneError);
    (void)z;
}

TEST(PerspectiveCamera, ThinLensFocusesAtFocalDistance) {
    Fixture fx;
    const Float focal = 5;
    Camera cam = fx.Make("perspective",
                         {test::Floats("float", "lensradius", {0.5f}),
                          test::Floats("float", "focaldistance", {focal})},
                         Point2i(80, 60));
    for (Point2f pFilm : {Point2f(40, 30), Point2f(3, 57), Point2f(71.5f, 10)}) {
        Ray ref = fx.RayAt(cam, pFilm, Point2f(0.5f, 0.5f));  // lens centre
        Point3f focus = ref(focal / ref.d.z);
        for (Point2f uLens : {Point2f(0.1f, 0.2f), Point2f(0.9f, 0.5f), Point2f(0.3f, 0.95f)}) {
            Ray r = fx.RayAt(cam, pFilm, uLens);
            EXPECT_NEAR(r.o.z, 0, 1e-6);
            EXPECT_GT(Length(Vector3f(r.o)), 1e-3);  // off-centre lens points
            EXPECT_LE(Length(Vector3f(r.o)), 0.5f + 1e-5);
            EXPECT_NEAR(Length(r.d), 1, 1e-5);
            Point3f q = r(focal / r.d.z);
            EXPECT_NEAR(Distance(q, focus), 0, 1e-4 * focal);
        }
    }
}

TEST(OrthographicCamera, RaysAreParallel) {
    Fixture fx;
    Camera cam = fx.Make("orthographic", {}, Point2i(200, 100));
    Ray a = fx.RayAt(cam, Point2f(0, 0)), b = fx.RayAt(cam, Point2f(200, 100));
    Ray c = fx.RayAt(cam, Point2f(100, 50));
    for (const Ray& r : {a, b, c}) {
        EXPECT_NEAR(r.d.x, 0, 1e-6);
        EXPECT_NEAR(r.d.y, 0, 1e-6);
        EXPECT_NEAR(r.d.z, 1, 1e-6);
    }
    // Default screen window: [-2,2] x [-1,1] in scene units (aspect 2).
    EXPECT_NEAR(a.o.x, -2, 1e-5);
    EXPECT_NEAR(a.o.y, 1, 1e-5);
    EXPECT_NEAR(b.o.x, 2, 1e-5);
    EXPECT_NEAR(b.o.y, -1, 1e-5);
    EXPECT_NEAR(Length(Vector3f(c.o)), 0, 1e-5);
}

TEST(OrthographicCamera, ThinLensFocus) {
    Fixture fx;
    // As pbrt-v4: with a lens, rays leave lens points around the camera axis and meet at the
    // film point's position on the plane of focus.
    Camera cam = fx.Make(
        "orthographic",
        {test::Floats("float", "lensradius", {0.2f}), test::Floats("float", "focaldistance", {3})},
        Point2i(50, 50));
    Camera pinhole = fx.Make("orthographic", {}, Point2i(50, 50));
    Point3f focus = fx.RayAt(pinhole, Point2f(10, 40))(3);
    for (Point2f uLens : {Point2f(0.5f, 0.5f), Point2f(0.8f, 0.3f), Point2f(0.1f, 0.9f)}) {
        Ray r = fx.RayAt(cam, Point2f(10, 40), uLens);
        EXPECT_NEAR(Distance(r(3 / r.d.z), focus), 0, 1e-4);
    }
}

TEST(Camera, Approximate_dp_dxy) {
    Fixture fx;
    const int res = 100;
    Camera cam = fx.Make("perspective", {test::Floats("float", "fov", {60})}, Point2i(res, res));
    // A plane facing the camera at distance 10: a central pixel spans 2 * 10 tan(30 deg) / res.
    // pbrt-v4 uses the smallest angular differential over the film (at the corners: smaller
    // by about cos^2 of the corner angle, 0.6 here), so the estimate lies in [0.6, 1] pixel.
    Vector3f dpdx, dpdy;
    cam.Approximate_dp_dxy(Point3f(0, 0, 10), Normal3f(0, 0, -1), 0, 1, &dpdx, &dpdy);
    Float pixel = 2 * 10 * std::tan(Radians(30)) / res;
    EXPECT_GT(Length(dpdx), 0.58f * pixel);
    EXPECT_LT(Length(dpdx), 1.001f * pixel);
    EXPECT_NEAR(Length(dpdy), Length(dpdx), 1e-3f * pixel);
    EXPECT_GT(std::abs(dpdx.x), 0.95f * Length(dpdx));  // along the image x axis
    EXPECT_GT(std::abs(dpdy.y), 0.95f * Length(dpdy));
    // Twice as far: twice the footprint.
    Vector3f dpdxFar, dpdyFar;
    cam.Approximate_dp_dxy(Point3f(0, 0, 20), Normal3f(0, 0, -1), 0, 1, &dpdxFar, &dpdyFar);
    EXPECT_NEAR(Length(dpdxFar), 2 * Length(dpdx), 1e-3f * pixel);
    // More samples per pixel shrink the footprint (1/sqrt(spp), at most by 8).
    Vector3f dpdx16, dpdy16;
    cam.Approximate_dp_dxy(Point3f(0, 0, 10), Normal3f(0, 0, -1), 0, 16, &dpdx16, &dpdy16);
    EXPECT_NEAR(Length(dpdx16), Length(dpdx) / 4, 1e-3f * pixel);
    // Orthographic: a pixel's width in scene units regardless of distance.
    Camera ortho = fx.Make("orthographic", {}, Point2i(res, res));
    ortho.Approximate_dp_dxy(Point3f(0.3f, 0, 50), Normal3f(0, 0, -1), 0, 1, &dpdx, &dpdy);
    EXPECT_NEAR(Length(dpdx), 2.f / res, 1e-4);
}

TEST(Camera, Create) {
    Fixture fx;
    Camera p = fx.Make("perspective", {}, Point2i(8, 8));
    EXPECT_TRUE(p.Is<PerspectiveCamera>());
    EXPECT_EQ(p.ShutterOpen(), 0);
    EXPECT_EQ(p.ShutterClose(), 1);
    Camera s = fx.Make("spherical", {}, Point2i(8, 8));
    EXPECT_TRUE(s.Is<SphericalCamera>());
    EXPECT_EQ(fx.diag.WarningCount(), 0);
    Camera sw = fx.Make("perspective",
                        {test::Floats("float", "shutteropen", {0.8f}),
                         test::Floats("float", "shutterclose", {0.2f})},
                        Point2i(8, 8));
    EXPECT_FLOAT_EQ(sw.ShutterOpen(), 0.2f);
    EXPECT_FLOAT_EQ(sw.ShutterClose(), 0.8f);
    EXPECT_EQ(fx.diag.WarningCount(), 1);
    EXPECT_FLOAT_EQ(fx.RayAt(sw, Point2f(4, 4)).time, 0.5f);
    EXPECT_THROW(fx.Make("fisheye", {}, Point2i(8, 8)), SceneError);
    EXPECT_THROW(fx.Make("perspective", {test::Floats("float", "fov", {180})}, Point2i(8, 8)),
                 SceneError);
}

TEST(Camera, GetCameraSample) {
    ObjectArena arena;
    Filter box = arena.New<BoxFilter>();
    Filter gauss = arena.New<GaussianFilter>(Vector2f(1.5f, 1.5f));
    Sampler s = ZSobolSampler(16, Point2i(16, 16), RandomizeStrategy::FastOwen, 0);
    for (int i = 0; i < 16; ++i) {
        s.StartPixelSample(Point2i(3, 4), i);
        CameraSample cs = GetCameraSample(s, Point2i(3, 4), box);
        EXPECT_GE(cs.pFilm.x, 3);
        EXPECT_LE(cs.pFilm.x, 4);
        EXPECT_GE(cs.pFilm.y, 4);
        EXPECT_LE(cs.pFilm.y, 5);
        EXPECT_EQ(cs.filterWeight, 1);
        EXPECT_GE(cs.time, 0);
        EXPECT_LT(cs.time, 1);
        // Replaying the sample gives the same camera sample.
        s.StartPixelSample(Point2i(3, 4), i);
        CameraSample again = GetCameraSample(s, Point2i(3, 4), box);
        EXPECT_EQ(cs.pFilm, again.pFilm);
        EXPECT_EQ(cs.pLens, again.pLens);
        s.StartPixelSample(Point2i(3, 4), i);
        CameraSample g = GetCameraSample(s, Point2i(3, 4), gauss);
        EXPECT_LE(std::abs(g.pFilm.x - 3.5f), 1.5f);
        EXPECT_GT(g.filterWeight, 0);
    }
}

}  // namespace
}  // namespace kiln
