// Light tracing from hot bodies (ThermalAreaLight::SampleLe): a light subpath starts at a point
// of the hot shape (by power where the temperature varies over it, else by area) with the
// surface's own Kirchhoff emission, evaluated with the job's shader. Each sample's pdfPos must
// be PDF_Le's, and the estimate E[L |cos| / (pdfPos pdfDir)] over wavelengths uniform in
// 360-830 nm must give the emitted power the light estimated at load (BandPower, a 32 x 32
// midpoint rule over the shape of the exitance the thermal module integrates), for a sphere and
// a bilinear patch with a temperature gradient and a uniformly hot sphere.
#include <gtest/gtest.h>

#include "base/rng.h"
#include "render_test_util.h"

namespace kiln {
namespace {

TEST(ThermalEmissionSampling, PowerAndDensities) {
    const std::string gradient =
        "Texture \"heat\" \"float\" \"gradient\" \"point3 p0\" [-1 0 0] \"point3 p1\" [1 0 0] "
        "\"float t0\" 700 \"float t1\" 1600 \"string space\" \"world\"\n"
        "Material \"diffuse\" \"rgb reflectance\" [0.3 0.3 0.3] \"texture temperature\" \"heat\"\n";
    const std::string uniform =
        "Material \"conductor\" \"float roughness\" 0.2 \"float temperature\" 1200\n";
    struct Case {
        const char* name;
        std::string text;
        bool byPower;
    };
    const Case cases[] = {
        {"sphere, gradient", gradient + "Shape \"sphere\" \"float radius\" 1", true},
        {"patch, gradient",
         gradient + "Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0 1 -1 0 -1 1 0 1 1 0]", true},
        {"sphere, uniform", uniform + "Shape \"sphere\" \"float radius\" 0.5", false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Diagnostics diag(nullptr);
        std::unique_ptr<Scene> scene = testing::BuildScene(
            "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\nWorldBegin\n" +
                c.text + "\n",
            diag);
        ASSERT_EQ(scene->lights.size(), 1u);
        const Light& light = scene->lights[0];
        const ThermalAreaLight* t = light.GetIf<ThermalAreaLight>();
        ASSERT_TRUE(t);
        EXPECT_EQ(t->SamplesByPower(), c.byPower);
        RNG rng(23);
        const int n = 40000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
            Point2f u1(rng.UniformFloat(), rng.UniformFloat());
            Point2f u2(rng.UniformFloat(), rng.UniformFloat());
            SampledWavelengths lambda = SampledWavelengths::SampleUniform(rng.UniformFloat());
            std::optional<LightLeSample> les = light.SampleLe(u1, u2, lambda, *scene->job->shader);
            double v = 0;
            if (les) {
                ASSERT_TRUE(les->intr);
                LightLePDF pdf = light.PDF_Le(*les->intr, les->ray.d);
                EXPECT_NEAR(pdf.pos, les->pdfPos, 2e-3 * les->pdfPos);
                EXPECT_NEAR(pdf.dir, les->pdfDir, 1e-4 * les->pdfDir);
                v = (les->L / lambda.PDF()).Average() * les->AbsCosTheta(les->ray.d) /
                    (les->pdfPos * les->pdfDir);
            }
            sum += v;
            sum2 += v * v;
        }
        double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
        double power = t->BandPower();
        std::printf("%-18s power %.5g W from SampleLe, %.5g W at load (standard error %.2g)\n",
                    c.name, mean, power, se);
        EXPECT_NEAR(mean, power, 5 * se + 0.01 * power);
        EXPECT_LT(se, 0.01 * power);
    }
}

}  // namespace
}  // namespace kiln
