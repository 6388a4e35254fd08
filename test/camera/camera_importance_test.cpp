// Camera importance for light tracing (pbrt-v4's PerspectiveCamera::We, PDF_We, SampleWi):
// consistency with GenerateRay (film positions, directions), the normalisation of We (its
// integral times cos theta over the directions that reach the film is 1) and of PDF_We (a
// density over those directions), and SampleWi's lens density for a pinhole and a thin lens.
#include <gtest/gtest.h>

#include <cmath>

#include "../textures/param_helpers.h"
#include "base/rng.h"
#include "base/sampling.h"
#include "core/camera/camera.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {
namespace {

struct ImportanceFixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    Point2i res{40, 30};
    Bounds2f bounds{Point2f(0, 0), Point2f(40, 30)};  // the whole image

    const PerspectiveCamera* Make(ParsedParameterVector params) {
        ParameterDictionary dict(std::move(params), nullptr);
        // Looking along a tilted axis from (1, 2, 3), so render space is no camera space
        Transform worldFromCamera = Translate(Vector3f(1, 2, 3)) * Rotate(25, Vector3f(1, 2, 0));
        Camera c = Camera::Create("perspective", dict, CameraTransform(worldFromCamera), res,
                                  0.035f, FileLoc(), arena, diag);
        return c.GetIf<PerspectiveCamera>();
    }
};

TEST(CameraImportance, WeAndPDFMatchGenerateRay) {
    ImportanceFixture f;
    const PerspectiveCamera* cam = f.Make({test::Floats("float", "fov", {50})});
    ASSERT_TRUE(cam);
    RNG rng(7);
    Vector3f axis = Normalize(cam->GetCameraTransform().RenderFromCamera()(Vector3f(0, 0, 1)));
    for (int i = 0; i < 200; ++i) {
        CameraSample s;
        s.pFilm = Point2f(rng.UniformFloat() * 40, rng.UniformFloat() * 30);
        Ray ray = cam->GenerateRay(s, f.lambda)->ray;
        Point2f pRaster;
        SampledSpectrum We = cam->We(ray, f.bounds, &pRaster);
        EXPECT_NEAR(pRaster.x, s.pFilm.x, 1e-3f);
        EXPECT_NEAR(pRaster.y, s.pFilm.y, 1e-3f);
        Float cosTheta = Dot(ray.d, axis), A = cam->ImagePlaneArea();
        EXPECT_NEAR(We[0], 1 / (A * std::pow(cosTheta, 4.f)), 1e-4f * We[0]);
        CameraPDF pdf = cam->PDF_We(ray, f.bounds);
        EXPECT_EQ(pdf.pos, 1);
        EXPECT_NEAR(pdf.dir, 1 / (A * std::pow(cosTheta, 3.f)), 1e-4f * pdf.dir);
    }
    // Away from the film, and behind the camera: nothing
    EXPECT_FALSE(cam->We(Ray(Point3f(0, 0, 0), -axis), f.bounds));
    EXPECT_EQ(cam->PDF_We(Ray(Point3f(0, 0, 0), -axis), f.bounds).dir, 0);
}

TEST(CameraImportance, Normalisation) {
    // Over uniformly sampled directions: integral of We cos theta = 1 and integral of PDF_We
    // = 1 (both over the directions that reach the film), and the solid angle the film sees
    ImportanceFixture f;
    const PerspectiveCamera* cam = f.Make({test::Floats("float", "fov", {60})});
    Vector3f axis = Normalize(cam->GetCameraTransform().RenderFromCamera()(Vector3f(0, 0, 1)));
    RNG rng(3);
    const int n = 400000;
    double sumWe = 0, sumWe2 = 0, sumPdf = 0;
    for (int i = 0; i < n; ++i) {
        Vector3f w = SampleUniformSphere(Point2f(rng.UniformFloat(), rng.UniformFloat()));
        Ray ray(Point3f(0, 0, 0), w);
        double v = cam->We(ray, f.bounds)[0] * std::max<Float>(0, Dot(w, axis)) / Inv4Pi;
        sumWe += v;
        sumWe2 += v * v;
        sumPdf += cam->PDF_We(ray, f.bounds).dir / Inv4Pi;
    }
    double mean = sumWe / n, sd = std::sqrt((sumWe2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, 1, 5 * sd);
    EXPECT_NEAR(sumPdf / n, 1, 5 * sd);
    // A = (2 tan 30 deg)^2 (4 / 3) for the 4:3 image (fov spans the shorter side)
    EXPECT_NEAR(cam->ImagePlaneArea(), Sqr(2 * std::tan(Radians(30.f))) * 4 / 3, 1e-4);
}

TEST(CameraImportance, SampleWiConnectsToTheFilm) {
    ImportanceFixture f;
    for (Float lensRadius : {0.f, 0.05f}) {
        const PerspectiveCamera* cam = f.Make({test::Floats("float", "fov", {50}),
                                               test::Floats("float", "lensradius", {lensRadius}),
                                               test::Floats("float", "focaldistance", {4})});
        RNG rng(9);
        int seen = 0;
        for (int i = 0; i < 500; ++i) {
            // A point in focus on a film ray
            CameraSample s;
            s.pFilm = Point2f(rng.UniformFloat() * 40, rng.UniformFloat() * 30);
            s.pLens = Point2f(0.5f, 0.5f);
            Ray center = cam->GenerateRay(s, f.lambda)->ray;
            Vector3f axis =
                Normalize(cam->GetCameraTransform().RenderFromCamera()(Vector3f(0, 0, 1)));
            Point3f pRef = center(4 / Dot(center.d, axis));
            Point2f u(rng.UniformFloat(), rng.UniformFloat());
            std::optional<CameraWiSample> cs = cam->SampleWi(pRef, 0, u, f.bounds);
            ASSERT_TRUE(cs);
            ++seen;
            // In focus: every lens point sees pRef at the same film position
            EXPECT_NEAR(cs->pRaster.x, s.pFilm.x, 2e-3f);
            EXPECT_NEAR(cs->pRaster.y, s.pFilm.y, 2e-3f);
            Float lensArea = lensRadius > 0 ? Pi * Sqr(lensRadius) : 1;
            Float dist2 = DistanceSquared(cs->pLens, pRef);
            EXPECT_NEAR(cs->pdf, dist2 / (AbsDot(cs->nLens, cs->wi) * lensArea), 1e-3f * cs->pdf);
            EXPECT_NEAR(cs->Wi[0], cam->We(Ray(cs->pLens, -cs->wi), f.bounds)[0], 1e-6f);
            EXPECT_NEAR(Length(cs->wi), 1, 1e-5f);
        }
        EXPECT_EQ(seen, 500);
    }
}

}  // namespace
}  // namespace kiln
