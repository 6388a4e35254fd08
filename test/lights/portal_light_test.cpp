// PortalInfiniteLight: the portal parameterisation and its Jacobian, light samples only through
// the portal (chi-square of SampleLi against PDF_Li over the directions seen from a point in the
// room), and radiance only for rays that leave through the portal.
#include <gtest/gtest.h>

#include "core/parser/diagnostics.h"
#include "light_test_util.h"
#include "lights/light.h"
#include "spectral/color.h"

using namespace kiln;
using namespace kiln::testing;

namespace {

// A window in the plane y = 2, x in [-0.8, 0.8], z in [1, 2], facing +y (out of the room)
const std::array<Point3f, 4> kPortal = {Point3f(-0.8f, 2, 1), Point3f(0.8f, 2, 1),
                                        Point3f(0.8f, 2, 2), Point3f(-0.8f, 2, 2)};

Image Environment(int n) {
    Image image(PixelFormat::Float, {n, n}, {"R", "G", "B"});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c)
                image.SetChannel({x, y}, c, 0.2f + Float((x * 5 + y * 3 + c) % 7) + 10 * (x == 2));
    return image;
}

}  // namespace

TEST(PortalInfiniteLight, ParameterisationRoundTripsWithItsJacobian) {
    PortalInfiniteLight light(Transform(), Environment(8), &RGBColorSpace::sRGB(), 1, kPortal);
    for (Point2f uv : {Point2f(0.5f, 0.5f), Point2f(0.1f, 0.8f), Point2f(0.93f, 0.27f)}) {
        Float dw_duv;
        Vector3f w = light.RenderFromImage(uv, &dw_duv);
        EXPECT_GT(w.y, 0);  // out through the window's side
        std::optional<Point2f> back = light.ImageFromRender(w);
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->x, uv.x, 1e-5f);
        EXPECT_NEAR(back->y, uv.y, 1e-5f);
        // Jacobian: the solid angle of a small uv square over its area
        Float e = 1e-3f;
        Vector3f a = light.RenderFromImage(Point2f(uv.x + e, uv.y)) - w;
        Vector3f b = light.RenderFromImage(Point2f(uv.x, uv.y + e)) - w;
        EXPECT_NEAR(Length(Cross(a, b)) / (e * e), dw_duv, 2e-2f * dw_duv);
    }
    EXPECT_FALSE(light.ImageFromRender(Vector3f(0, -1, 0)));
}

TEST(PortalInfiniteLight, SamplesThroughThePortalOnly) {
    PortalInfiniteLight light(Rotate(40, Vector3f(1, 0, 0)), Environment(8), &RGBColorSpace::sRGB(),
                              1, kPortal);
    light.Preprocess(Bounds3f(Point3f(-2, -2, 0), Point3f(2, 2, 3)));
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
    for (Point3f p : {Point3f(0.3f, -1, 0.5f), Point3f(-1.5f, 1.2f, 2.5f)}) {
        LightSampleContext ctx(p, Normal3f(), Normal3f());
        std::optional<Bounds2f> window = light.ImageBounds(p);
        ASSERT_TRUE(window);
        auto sample = [&](Point2f u) -> std::optional<DirectionSample> {
            auto ls = light.SampleLi(ctx, u, lambda);
            if (!ls) return std::nullopt;
            // Every sampled direction passes through the window
            Float t = (2 - p.y) / ls->wi.y;
            Point3f hit = p + t * ls->wi;
            EXPECT_GT(t, 0);
            EXPECT_NEAR(Clamp(hit.x, -0.8f, 0.8f), hit.x, 1e-3f);
            EXPECT_NEAR(Clamp(hit.z, 1.f, 2.f), hit.z, 1e-3f);
            EXPECT_TRUE(light.Le(Ray(p, ls->wi), lambda));
            return DirectionSample{ls->wi, ls->pdf};
        };
        auto pdf = [&](Vector3f w) { return light.PDF_Li(ctx, w); };
        Vector3f axis = Point3f(0, 2, 1.5f) - p;
        ChiSquareResult r = DirectionChiSquare(sample, pdf, axis, 0.7f, 100000, 2, 12, 24, 32);
        EXPECT_TRUE(r.passed) << r.message;
    }
    // Rays leaving elsewhere see nothing
    EXPECT_FALSE(light.Le(Ray(Point3f(0, 0, 1.5f), Vector3f(0, 1, 0.9f)), lambda));
    EXPECT_FALSE(light.Le(Ray(Point3f(0, 0, 1.5f), Vector3f(0, -1, 0)), lambda));
    EXPECT_TRUE(light.Le(Ray(Point3f(0, 0, 1.5f), Vector3f(0, 1, 0)), lambda));
}

TEST(PortalInfiniteLight, CreateNeedsFourCornersAndASquareMap) {
    ObjectArena arena;
    Diagnostics diag(nullptr);
    // Three corners: an error at the parameter
    ParsedParameterVector params = {FloatParam("point3", "portal", {-1, 0, 0, 1, 0, 0, 1, 0, 1})};
    ParameterDictionary dict(std::move(params), nullptr);
    EXPECT_THROW(Light::Create("infinite", dict, Transform(), FileLoc(), arena, diag), SceneError);
    EXPECT_THROW(
        PortalInfiniteLight(Transform(), Image(PixelFormat::Float, {8, 4}, {"R", "G", "B"}),
                            &RGBColorSpace::sRGB(), 1, kPortal),
        std::invalid_argument);
}
