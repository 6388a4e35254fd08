// Light samplers: PowerLightSampler's probabilities follow emitted power and its samples follow
// its probabilities (chi-square); UniformLightSampler is uniform; indices out of range have
// PMF 0.
#include <gtest/gtest.h>

#include <vector>

#include "light_test_util.h"
#include "lights/light_sampler.h"

using namespace kiln;
using namespace kiln::testing;

namespace {

template <typename Sampler>
ChiSquareResult SampleFrequencies(const Sampler& sampler, size_t count) {
    std::vector<double> observed(count, 0), expected(count, 0);
    RNG rng(11);
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        auto s = sampler.Sample(rng.UniformFloat());
        EXPECT_TRUE(s.has_value());
        EXPECT_FLOAT_EQ(s->p, sampler.PMF(s->index));
        observed[size_t(s->index)] += 1;
    }
    for (size_t i = 0; i < count; ++i) expected[i] = n * sampler.PMF(int(i));
    return ChiSquareTest(observed, expected, 0.01, 2);
}

}  // namespace

TEST(PowerLightSampler, ProbabilitiesFollowPower) {
    std::vector<PointLight> points;
    for (Float I : {1.f, 2.f, 0.f, 5.f, 0.5f})
        points.emplace_back(Transform(), Spectrum(ConstantSpectrum(I)), 1);
    SpotLight spot(Transform(), Spectrum(ConstantSpectrum(4)), 1, 30, 25);
    DistantLight distant(Transform(), Spectrum(ConstantSpectrum(0.1f)), 1);
    std::vector<Light> lights;
    for (const PointLight& p : points) lights.push_back(Light(&p));
    lights.push_back(Light(&spot));
    lights.push_back(Light(&distant));
    for (const Light& l : lights) l.Preprocess(Bounds3f(Point3f(0, 0, 0), Point3f(2, 2, 2)));

    PowerLightSampler sampler(lights);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    double total = 0, sumPMF = 0;
    for (const Light& l : lights) total += l.Phi(lambda)[0];
    for (size_t i = 0; i < lights.size(); ++i) {
        EXPECT_NEAR(sampler.PMF(int(i)), lights[i].Phi(lambda)[0] / total, 1e-5);
        sumPMF += sampler.PMF(int(i));
    }
    EXPECT_NEAR(sumPMF, 1, 1e-5);
    EXPECT_EQ(sampler.PMF(2), 0);
    EXPECT_EQ(sampler.PMF(-1), 0);
    EXPECT_EQ(sampler.PMF(int(lights.size())), 0);
    ChiSquareResult r = SampleFrequencies(sampler, lights.size());
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(PowerLightSampler, ZeroPowerAndEmpty) {
    PointLight dark(Transform(), Spectrum(ConstantSpectrum(0)), 1);
    std::vector<Light> lights = {Light(&dark), Light(&dark)};
    PowerLightSampler sampler(lights);
    EXPECT_FLOAT_EQ(sampler.PMF(0), 0.5f);
    EXPECT_FALSE(PowerLightSampler(std::span<const Light>()).Sample(0.5f).has_value());
}

TEST(UniformLightSampler, Uniform) {
    PointLight a(Transform(), Spectrum(ConstantSpectrum(1)), 1);
    PointLight b(Transform(), Spectrum(ConstantSpectrum(100)), 1);
    std::vector<Light> lights = {Light(&a), Light(&b), Light(&b)};
    UniformLightSampler sampler(lights.size());
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(sampler.PMF(i), 1.f / 3);
    EXPECT_EQ(sampler.PMF(3), 0);
    ChiSquareResult r = SampleFrequencies(sampler, lights.size());
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_FALSE(UniformLightSampler(0).Sample(0.5f).has_value());
}

// BVHLightSampler: at receiving points near and far from a field of lights of very different
// power, the lights it draws follow the probabilities PMF reports (chi-square), those sum to
// one, zero-power lights are never drawn, and lights at infinity get n_inf / (n_inf + 1).
TEST(BVHLightSampler, SamplesFollowThePMFAtEveryReceiver) {
    std::vector<PointLight> points;
    RNG rng(3);
    for (int i = 0; i < 40; ++i) {
        Point3f p(8 * rng.UniformFloat(), 8 * rng.UniformFloat(), rng.UniformFloat());
        Float I = i == 7 ? 0.f : std::pow(10.f, 3 * rng.UniformFloat());
        points.emplace_back(Translate(Vector3f(p)), Spectrum(ConstantSpectrum(I)), 1);
    }
    SpotLight spot(Translate(Vector3f(4, 4, 3)), Spectrum(ConstantSpectrum(50)), 1, 30, 20);
    DistantLight distant(Transform(), Spectrum(ConstantSpectrum(0.1f)), 1);
    std::vector<Light> lights;
    for (const PointLight& p : points) lights.push_back(Light(&p));
    lights.push_back(Light(&spot));
    lights.push_back(Light(&distant));
    for (const Light& l : lights) l.Preprocess(Bounds3f(Point3f(0, 0, 0), Point3f(8, 8, 3)));
    BVHLightSampler sampler(lights);
    for (Point3f p : {Point3f(1, 1, 0.5f), Point3f(4, 4, -2), Point3f(30, -5, 10)}) {
        SCOPED_TRACE(p.x);
        LightSampleContext ctx(p, Normal3f(0, 0, 1), Normal3f(0, 0, 1));
        double sum = 0;
        for (size_t i = 0; i < lights.size(); ++i) sum += sampler.PMF(ctx, int(i));
        EXPECT_NEAR(sum, 1, 1e-4);
        EXPECT_EQ(sampler.PMF(ctx, 7), 0);                                // zero power
        EXPECT_FLOAT_EQ(sampler.PMF(ctx, int(lights.size()) - 1), 0.5f);  // one infinite light
        std::vector<double> observed(lights.size(), 0), expected(lights.size(), 0);
        const int n = 200000;
        RNG r(11);
        for (int k = 0; k < n; ++k) {
            std::optional<SampledLight> s = sampler.Sample(ctx, r.UniformFloat());
            if (!s) continue;
            EXPECT_NEAR(s->p, sampler.PMF(ctx, s->index), 1e-5f * s->p);
            observed[size_t(s->index)] += 1;
        }
        for (size_t i = 0; i < lights.size(); ++i) expected[i] = n * sampler.PMF(ctx, int(i));
        ChiSquareResult chi = ChiSquareTest(observed, expected, 0.01, 3);
        EXPECT_TRUE(chi.passed) << chi.message;
    }
}

// A spot whose falloff is narrower than float can tell from a hard edge (cos of the falloff
// angle rounds to 1) is still picked inside its cone (LightBounds::Importance), and never
// outside it.
TEST(BVHLightSampler, HardEdgedSpotsArePickedInsideTheirCone) {
    PointLight point(Translate(Vector3f(3, 0, 0)), Spectrum(ConstantSpectrum(1)), 1);
    for (Float falloffStart : {30.f, 29.99f, 29.f}) {
        SCOPED_TRACE(falloffStart);
        SpotLight spot(Transform(), Spectrum(ConstantSpectrum(1)), 1, 30, falloffStart);
        std::vector<Light> lights = {Light(&point), Light(&spot)};
        for (const Light& l : lights) l.Preprocess(Bounds3f(Point3f(-5, -5, 0), Point3f(5, 5, 5)));
        BVHLightSampler sampler(lights);
        LightSampleContext inside(Point3f(0.5f, 0, 5), Normal3f(0, 0, -1), Normal3f(0, 0, -1));
        EXPECT_GT(sampler.PMF(inside, 1), 0.01f);
        LightSampleContext outside(Point3f(5, 0, 1), Normal3f(-1, 0, 0), Normal3f(-1, 0, 0));
        EXPECT_EQ(sampler.PMF(outside, 1), 0);
    }
}

// Path and volpath sample lights with an incomplete PDF, which draws nothing from a uniform
// environment (BSDF sampling covers it): with skipCovered the bvh and power samplers leave it
// out, and the other lights get all the samples; without, it keeps pbrt-v4's share
TEST(LightSamplers, LeaveOutTheUniformEnvironmentWhenAsked) {
    UniformInfiniteLight sky(Transform(), Spectrum(ConstantSpectrum(1)), 1);
    PointLight a(Transform(), Spectrum(ConstantSpectrum(1)), 1);
    PointLight b(Translate(Vector3f(1, 0, 0)), Spectrum(ConstantSpectrum(3)), 1);
    std::vector<Light> lights = {Light(&sky), Light(&a), Light(&b)};
    for (const Light& l : lights) l.Preprocess(Bounds3f(Point3f(-1, -1, -1), Point3f(2, 2, 2)));
    EXPECT_TRUE(lights[0].CoveredByBSDFSampling());
    EXPECT_FALSE(lights[1].CoveredByBSDFSampling());
    LightSampleContext ctx(Point3f(0.5f, 2, 0), Normal3f(0, -1, 0), Normal3f(0, -1, 0));

    BVHLightSampler all(lights), skipping(lights, {}, true);
    EXPECT_FLOAT_EQ(all.PMF(ctx, 0), 0.5f);
    EXPECT_EQ(skipping.PMF(ctx, 0), 0);
    EXPECT_NEAR(skipping.PMF(ctx, 1) + skipping.PMF(ctx, 2), 1, 1e-6);
    EXPECT_NEAR(skipping.PMF(ctx, 1), 2 * all.PMF(ctx, 1), 1e-6);
    RNG rng(5);
    for (int i = 0; i < 1000; ++i) {
        std::optional<SampledLight> s = skipping.Sample(ctx, rng.UniformFloat());
        ASSERT_TRUE(s);
        EXPECT_NE(s->index, 0);
        EXPECT_FLOAT_EQ(s->p, skipping.PMF(ctx, s->index));
    }

    PowerLightSampler byPower(lights), byPowerSkipping(lights, {}, true);
    EXPECT_GT(byPower.PMF(0), 0);
    EXPECT_EQ(byPowerSkipping.PMF(0), 0);
    EXPECT_NEAR(byPowerSkipping.PMF(2) / byPowerSkipping.PMF(1), 3, 1e-4);
    EXPECT_NEAR(byPowerSkipping.PMF(1) + byPowerSkipping.PMF(2), 1, 1e-6);
    ChiSquareResult r = SampleFrequencies(byPowerSkipping, lights.size());
    EXPECT_TRUE(r.passed) << r.message;

    // Only the environment: nothing to sample
    std::vector<Light> skyOnly = {Light(&sky)};
    EXPECT_FALSE(BVHLightSampler(skyOnly, {}, true).Sample(ctx, 0.3f));
    EXPECT_FALSE(PowerLightSampler(skyOnly, {}, true).Sample(0.3f));
}
