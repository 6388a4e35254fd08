// MediumEmissionSampler: its samples follow its PDF (chi-square over a partition of the box),
// the PDF integrates to 1, hot regions get the samples, media are emitters with their power,
// and the density is 0 where it does not sample.
#include <gtest/gtest.h>

#include <cmath>

#include "../textures/param_helpers.h"
#include "base/rng.h"
#include "base/statistics.h"
#include "media/medium.h"
#include "render/medium_emission_sampler.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

using test::Dict;
using test::Float1;
using test::Floats;
using test::Int1;
using test::Rgb;
using test::String1;

struct Media {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    std::vector<std::unique_ptr<ParameterDictionary>> dicts;
    std::vector<Medium> media;

    int Add(const std::string& type, ParameterDictionary d) {
        dicts.push_back(std::make_unique<ParameterDictionary>(std::move(d)));
        TextureParameterDictionary tp(dicts.back().get(), nullptr);
        media.push_back(
            Medium::Create(type, tp, Transform(), std::nullopt, test::TestLoc(), arena, diag));
        return int(media.size()) - 1;
    }
};

// Far from every box: each emitter is always kept.
const Point3f kFar(0, 1000, 0);

// An 8^3 grid over [0, 2] x [0, 1] x [0, 1] at 1500 K, dense (and so bright) only in a blob
// near (1.5, 0.25, 0.75).
int AddBlob(Media& m) {
    const int n = 8;
    std::vector<Float> density;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                Float dx = (x + 0.5f) / n - 0.75f, dy = (y + 0.5f) / n - 0.25f,
                      dz = (z + 0.5f) / n - 0.75f;
                density.push_back(std::exp(-(dx * dx + dy * dy + dz * dz) / 0.02f));
            }
    return m.Add(
        "uniformgrid",
        Dict({Int1("nx", n), Int1("ny", n), Int1("nz", n), Floats("float", "density", density),
              Floats("point3", "p0", {0, 0, 0}), Floats("point3", "p1", {2, 1, 1}),
              Rgb("sigma_a", 2, 2, 2), Rgb("sigma_s", 1, 1, 1), Float1("temperature", 1500)}));
}

TEST(MediumEmissionSampler, SamplesFollowThePDF) {
    Media m;
    int blob = AddBlob(m);
    Bounds3f box(Point3f(0, 0, 0), Point3f(2, 1, 1));
    MediumEmissionSampler::Region region{blob, box};
    MediumEmissionSampler sampler(m.media, std::span(&region, 1));
    ASSERT_EQ(sampler.Emitters(), 1);
    ASSERT_EQ(sampler.MediumOf(0), blob);
    ASSERT_EQ(sampler.EmitterOf(blob), 0);

    // Bins: a 6 x 3 x 3 partition of the box; expected masses from the PDF on a grid fine
    // enough to integrate the sampler's cells exactly (their boundaries fall on its points)
    const int bx = 6, by = 3, bz = 3, fine = 4 * MediumEmissionSampler::kMaxCells;
    std::vector<double> expected(bx * by * bz, 0), observed(bx * by * bz, 0);
    auto bin = [&](Point3f p) {
        int i = std::min(int(p.x / 2 * bx), bx - 1), j = std::min(int(p.y * by), by - 1),
            k = std::min(int(p.z * bz), bz - 1);
        return i + bx * (j + by * k);
    };
    double integral = 0, dV = 2.0 / (fine * fine * fine);
    for (int z = 0; z < fine; ++z)
        for (int y = 0; y < fine; ++y)
            for (int x = 0; x < fine; ++x) {
                Point3f p(2 * (x + 0.5f) / fine, (y + 0.5f) / fine, (z + 0.5f) / fine);
                double mass = sampler.PDF(kFar, 0, p) * dV;
                integral += mass;
                expected[size_t(bin(p))] += mass;
            }
    EXPECT_NEAR(integral, 1, 1e-3);

    const int n = 200000;
    RNG rng(7);
    double inBlob = 0;
    for (int i = 0; i < n; ++i) {
        std::optional<MediumEmissionSampler::PointSample> s =
            sampler.Sample(kFar, rng.UniformFloat(),
                           Point3f(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat()));
        ASSERT_TRUE(s);
        ASSERT_EQ(s->emitter, 0);
        ASSERT_NEAR(s->pdf, sampler.PDF(kFar, 0, s->p), 1e-5 * s->pdf);
        observed[size_t(bin(s->p))] += 1;
        if (Distance(s->p, Point3f(1.5f, 0.25f, 0.75f)) < 0.3f) ++inBlob;
    }
    for (double& e : expected) e *= n;
    ChiSquareResult chi = ChiSquareTest(observed, expected);
    EXPECT_TRUE(chi.passed) << chi.message;
    // The blob (a sphere of 1/20 of the box's volume) is where the emission is
    EXPECT_GT(inBlob / n, 0.6);
}

TEST(MediumEmissionSampler, ZeroWhereItDoesNotSample) {
    Media m;
    int blob = AddBlob(m);
    int cold = m.Add("homogeneous", Dict({Rgb("sigma_a", 1, 1, 1)}));
    MediumEmissionSampler::Region region{blob, Bounds3f(Point3f(0, 0, 0), Point3f(2, 1, 1))};
    MediumEmissionSampler sampler(m.media, std::span(&region, 1));
    EXPECT_GT(sampler.PDF(kFar, 0, Point3f(0.1f, 0.1f, 0.1f)), 0);  // the uniform share
    EXPECT_EQ(sampler.PDF(kFar, 0, Point3f(2.1f, 0.5f, 0.5f)), 0);
    EXPECT_EQ(sampler.EmitterOf(cold), -1);
    EXPECT_EQ(sampler.EmitterOf(-1), -1);
    EXPECT_EQ(sampler.PDF(kFar, 1, Point3f(1, 0.5f, 0.5f)), 0);
    EXPECT_EQ(sampler.PDF(kFar, -1, Point3f(1, 0.5f, 0.5f)), 0);
}

TEST(MediumEmissionSampler, PowerOfEachMediumAndFlatRegionsSkipped) {
    // Two hot homogeneous media at 1200 K: emission per volume 1 : 3, volumes 2 : 1, so power
    // 2 : 3, each 4 pi sigma_a integral(B) volume. A third region is flat (no volume): not an
    // emitter.
    Media m;
    auto hot = [&](Float sigma_a) {
        return m.Add("homogeneous", Dict({Rgb("sigma_a", sigma_a, sigma_a, sigma_a),
                                          Float1("temperature", 1200)}));
    };
    int a = hot(1), b = hot(3), flat = hot(5);
    MediumEmissionSampler::Region regions[] = {
        {a, Bounds3f(Point3f(0, 0, 0), Point3f(2, 1, 1))},
        {b, Bounds3f(Point3f(5, 0, 0), Point3f(6, 1, 1))},
        {flat, Bounds3f(Point3f(0, 3, 0), Point3f(1, 3, 1))}};
    MediumEmissionSampler sampler(m.media, regions);
    ASSERT_EQ(sampler.Emitters(), 2);
    EXPECT_EQ(sampler.EmitterOf(flat), -1);
    int ea = sampler.EmitterOf(a), eb = sampler.EmitterOf(b);
    ASSERT_GE(ea, 0);
    ASSERT_GE(eb, 0);
    double integralB = planck_band_radiance(360, 830, 1200);  // W m^-2 sr^-1
    // Estimated from 8 points and 4 wavelengths per cell, 32 stratified wavelengths per cell
    EXPECT_NEAR(sampler.Power(ea) / (4 * Pi * 1 * integralB * 2), 1, 0.01);
    EXPECT_NEAR(sampler.Power(eb) / (4 * Pi * 3 * integralB * 1), 1, 0.01);
    // Chosen by power, uniform within each (constant emission): the density is the emitter's
    // probability over its volume
    EXPECT_NEAR(sampler.PDF(kFar, ea, Point3f(1, 0.5f, 0.5f)) * 2, 0.4, 0.01);
    EXPECT_NEAR(sampler.PDF(kFar, eb, Point3f(5.5f, 0.5f, 0.5f)) * 1, 0.6, 0.01);
}

TEST(MediumEmissionSampler, NearLargeEmittersAreKeptByTheirSolidAngle) {
    // From inside the box (the whole sphere) and from afar: Sample keeps the emitter with
    // KeepProbability, and PDF integrates to it
    Media m;
    int blob = AddBlob(m);
    MediumEmissionSampler::Region region{blob, Bounds3f(Point3f(0, 0, 0), Point3f(2, 1, 1))};
    MediumEmissionSampler sampler(m.media, std::span(&region, 1));
    Point3f inside(1, 0.5f, 0.5f);
    Float keep = sampler.KeepProbability(0, inside);
    EXPECT_FLOAT_EQ(keep, MediumEmissionSampler::kSolidAngleBudget / (4 * Pi));
    EXPECT_EQ(sampler.KeepProbability(0, kFar), 1);
    const int n = 100000;
    RNG rng(3);
    int kept = 0;
    for (int i = 0; i < n; ++i) {
        std::optional<MediumEmissionSampler::PointSample> s =
            sampler.Sample(inside, rng.UniformFloat(),
                           Point3f(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat()));
        if (!s) continue;
        ++kept;
        ASSERT_NEAR(s->pdf, sampler.PDF(inside, 0, s->p), 1e-5 * s->pdf);
        ASSERT_NEAR(s->pdf, keep * sampler.PDF(kFar, 0, s->p), 1e-5 * s->pdf);
    }
    double se = std::sqrt(keep * (1 - keep) / n);
    EXPECT_NEAR(double(kept) / n, keep, 5 * se);
}

}  // namespace
}  // namespace kiln
