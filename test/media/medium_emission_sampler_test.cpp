// MediumEmissionSampler: its samples follow its PDF (chi-square over a partition of the box),
// the PDF integrates to 1, hot regions and hot media get the samples, and the density is 0
// where it does not sample.
#include <gtest/gtest.h>

#include <cmath>

#include "../textures/param_helpers.h"
#include "base/rng.h"
#include "base/statistics.h"
#include "media/medium.h"
#include "media/medium_emission_sampler.h"

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
    ASSERT_EQ(sampler.Media(), 1);

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
                double mass = sampler.PDF(blob, p) * dV;
                integral += mass;
                expected[size_t(bin(p))] += mass;
            }
    EXPECT_NEAR(integral, 1, 1e-3);

    const int n = 200000;
    RNG rng(7);
    double inBlob = 0;
    for (int i = 0; i < n; ++i) {
        std::optional<MediumEmissionSampler::PointSample> s =
            sampler.Sample(rng.UniformFloat(),
                           Point3f(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat()));
        ASSERT_TRUE(s);
        ASSERT_EQ(s->medium, blob);
        ASSERT_NEAR(s->pdf, sampler.PDF(blob, s->p), 1e-5 * s->pdf);
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
    EXPECT_GT(sampler.PDF(blob, Point3f(0.1f, 0.1f, 0.1f)), 0);  // the uniform share
    EXPECT_EQ(sampler.PDF(blob, Point3f(2.1f, 0.5f, 0.5f)), 0);
    EXPECT_EQ(sampler.PDF(cold, Point3f(1, 0.5f, 0.5f)), 0);
    EXPECT_EQ(sampler.PDF(-1, Point3f(1, 0.5f, 0.5f)), 0);
    EXPECT_EQ(sampler.PDF(99, Point3f(1, 0.5f, 0.5f)), 0);
}

TEST(MediumEmissionSampler, ChoosesMediaByPowerAndSkipsFlatRegions) {
    // Two hot homogeneous media of equal temperature: emission per volume 1 : 3, volumes 2 : 1,
    // so power 2 : 3. A third region is flat (no volume) and is not sampled.
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
    EXPECT_EQ(sampler.Media(), 2);
    EXPECT_EQ(sampler.PDF(flat, Point3f(0.5f, 3, 0.5f)), 0);
    // Each medium's probability: its density integrated over its box (on a grid whose points
    // fall inside the sampler's cells, an exact integral)
    auto probability = [&](int medium, Bounds3f box) {
        const int n = 2 * MediumEmissionSampler::kMaxCells;
        Vector3f d = box.Diagonal();
        double sum = 0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    sum += sampler.PDF(
                        medium, box.pMin + Vector3f(d.x * (x + 0.5f) / n, d.y * (y + 0.5f) / n,
                                                    d.z * (z + 0.5f) / n));
        return sum * d.x * d.y * d.z / (double(n) * n * n);
    };
    double pA = probability(a, regions[0].bounds), pB = probability(b, regions[1].bounds);
    EXPECT_NEAR(pA + pB, 1, 1e-4);
    // Estimated from 8 points and 4 wavelengths per cell
    EXPECT_NEAR(pA, 0.4, 0.01);
}

}  // namespace
}  // namespace kiln
