// Participating media: grids and their majorants, delta and ratio tracking against the exact
// transmittance, emission per model, presets, and parameter errors.
#include <gtest/gtest.h>

#include <cmath>

#include "../textures/param_helpers.h"
#include "base/rng.h"
#include "base/statistics.h"
#include "media/medium.h"
#include "spectral/cie.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

using test::Dict;
using test::Float1;
using test::Floats;
using test::Int1;
using test::Rgb;
using test::String1;

struct MediumFixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};

    Medium Make(const std::string& type, ParameterDictionary d,
                const Transform& renderFromMedium = Transform()) {
        dicts.push_back(std::make_unique<ParameterDictionary>(std::move(d)));
        TextureParameterDictionary tp(dicts.back().get(), nullptr);
        return Medium::Create(type, tp, renderFromMedium, std::nullopt, test::TestLoc(), arena,
                              diag);
    }
    std::vector<std::unique_ptr<ParameterDictionary>> dicts;
};

// A 5x4x3 grid of densities in [0, 2) with some empty voxels.
std::vector<Float> RandomDensities(RNG& rng, int n) {
    std::vector<Float> d(static_cast<size_t>(n));
    for (Float& v : d) v = rng.UniformFloat() < 0.3f ? 0 : 2 * rng.UniformFloat();
    return d;
}

SampledWavelengths Lambda(Float u = 0.3f) { return SampledWavelengths::SampleVisible(u); }

TEST(SampledGridTest, InterpolatesBetweenSamplesAndIsZeroBeyond) {
    SampledGrid<Float> g({1, 3, 5, 7, 11, 13, 17, 19}, 2, 2, 2);
    EXPECT_FLOAT_EQ(g.Lookup(Point3f(0.25f, 0.25f, 0.25f)), 1);
    EXPECT_FLOAT_EQ(g.Lookup(Point3f(0.75f, 0.75f, 0.75f)), 19);
    EXPECT_FLOAT_EQ(g.Lookup(Point3f(0.5f, 0.25f, 0.25f)), 2);
    EXPECT_FLOAT_EQ(g.Lookup(Point3f(0.5f, 0.5f, 0.5f)), 9.5f);
    // Half a voxel beyond the last sample, half of it remains; far away, nothing
    EXPECT_FLOAT_EQ(g.Lookup(Point3f(1.f, 0.75f, 0.75f)), 9.5f);
    EXPECT_EQ(g.Lookup(Point3f(-3, 0.5f, 0.5f)), 0);
    EXPECT_EQ(g.Lookup(Point3f(1e30f, 0.5f, 0.5f)), 0);
    EXPECT_EQ(g.Lookup(Point3f(NAN, 0.5f, 0.5f)), 0);
}

TEST(SampledGridTest, MaxValueBoundsEveryLookupInTheBox) {
    RNG rng(7);
    SampledGrid<Float> g(RandomDensities(rng, 60), 5, 4, 3);
    for (int box = 0; box < 200; ++box) {
        Point3f a(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat());
        Point3f b(rng.UniformFloat(), rng.UniformFloat(), rng.UniformFloat());
        Bounds3f bounds(a, b);
        Float m = g.MaxValue(bounds, [](Float v) { return v; });
        for (int i = 0; i < 50; ++i) {
            Point3f p(Lerp(rng.UniformFloat(), bounds.pMin.x, bounds.pMax.x),
                      Lerp(rng.UniformFloat(), bounds.pMin.y, bounds.pMax.y),
                      Lerp(rng.UniformFloat(), bounds.pMin.z, bounds.pMax.z));
            ASSERT_LE(g.Lookup(p), m + 1e-5f);
        }
    }
}

// A grid medium in a rotated, scaled frame.
Medium RandomGridMedium(MediumFixture& f, RNG& rng) {
    std::vector<Float> d = RandomDensities(rng, 60);
    return f.Make("uniformgrid",
                  Dict({Floats("float", "density", d), Int1("nx", 5), Int1("ny", 4), Int1("nz", 3),
                        Rgb("sigma_a", 0.5f, 1.0f, 2.0f), Rgb("sigma_s", 1.0f, 0.5f, 0.2f),
                        Float1("scale", 1.5f), Floats("point3", "p0", {-1, -1, -1}),
                        Floats("point3", "p1", {1, 2, 1})}),
                  Translate(Vector3f(0.3f, -0.2f, 0.1f)) * Rotate(30, Vector3f(1, 1, 0)) *
                      Scale(1.2f, 0.8f, 1));
}

// A ray through the medium's box from a random point outside it.
Ray RandomRay(RNG& rng) {
    Point3f target(rng.UniformFloat() - 0.5f, rng.UniformFloat(), rng.UniformFloat() - 0.5f);
    Vector3f d = Normalize(
        Vector3f(rng.UniformFloat() - 0.5f, rng.UniformFloat() - 0.5f, rng.UniformFloat() - 0.5f));
    return Ray(target - d * 4.f, d);
}

TEST(GridMediumTest, MajorantSegmentsCoverTheRayAndBoundTheExtinction) {
    MediumFixture f;
    RNG rng(11);
    Medium m = RandomGridMedium(f, rng);
    SampledWavelengths lambda = Lambda();
    int segments = 0;
    for (int r = 0; r < 100; ++r) {
        Ray ray = RandomRay(rng);
        MajorantIterator it = m.SampleRay(ray, 8, lambda);
        std::optional<Float> last;
        while (std::optional<RayMajorantSegment> seg = it.Next()) {
            ++segments;
            if (last) {
                ASSERT_NEAR(seg->tMin, *last, 1e-4f);  // contiguous
            }
            ASSERT_LE(seg->tMin, seg->tMax);
            last = seg->tMax;
            for (int i = 0; i < 20; ++i) {
                Float t = Lerp(rng.UniformFloat(), seg->tMin, seg->tMax);
                MediumProperties mp = m.SamplePoint(ray(t), lambda);
                for (int k = 0; k < NSpectrumSamples; ++k)
                    ASSERT_LE(mp.sigma_a[k] + mp.sigma_s[k], seg->sigma_maj[k] * (1 + 1e-4f));
            }
        }
        // Outside the segments there is nothing
        for (int i = 0; i < 20; ++i) {
            Float t = 8 * rng.UniformFloat();
            bool inside = false;
            MajorantIterator again = m.SampleRay(ray, 8, lambda);
            while (std::optional<RayMajorantSegment> seg = again.Next())
                inside |= t >= seg->tMin - 1e-3f && t <= seg->tMax + 1e-3f;
            if (!inside) {
                ASSERT_EQ(m.SamplePoint(ray(t), lambda).sigma_a[0], 0);
            }
        }
    }
    EXPECT_GT(segments, 300);  // the DDA walks voxels, not one box
}

// exp(-integral of sigma_t) along ray over [0, tMax], by the midpoint rule.
SampledSpectrum ExactTransmittance(const Medium& m, const Ray& ray, Float tMax,
                                   const SampledWavelengths& lambda) {
    constexpr int n = 20000;
    SampledSpectrum tau(0.f);
    for (int i = 0; i < n; ++i) {
        MediumProperties mp = m.SamplePoint(ray((i + 0.5f) * tMax / n), lambda);
        tau += (mp.sigma_a + mp.sigma_s) * (tMax / n);
    }
    SampledSpectrum T;
    for (int k = 0; k < NSpectrumSamples; ++k) T[k] = std::exp(-tau[k]);
    return T;
}

TEST(GridMediumTest, RatioTrackingEstimatesTheTransmittanceAtEveryWavelength) {
    MediumFixture f;
    RNG rng(5);
    Medium m = RandomGridMedium(f, rng);
    SampledWavelengths lambda = Lambda(0.7f);
    for (int r = 0; r < 6; ++r) {
        Ray ray = RandomRay(rng);
        Float tMax = 3 + 2 * rng.UniformFloat();
        SampledSpectrum exact = ExactTransmittance(m, ray, tMax, lambda);
        RunningStats est[NSpectrumSamples];
        for (int i = 0; i < 20000; ++i) {
            SampledSpectrum T(1.f);
            SampledSpectrum T_maj = m.SampleT_maj(
                ray, tMax, rng.UniformFloat(), rng, lambda,
                [&](Point3f, const MediumProperties& mp, const SampledSpectrum& sigma_maj,
                    const SampledSpectrum& T_maj) {
                    SampledSpectrum sigma_n = ClampZero(sigma_maj - mp.sigma_a - mp.sigma_s);
                    T *= T_maj * sigma_n / (T_maj[0] * sigma_maj[0]);
                    return true;
                });
            T *= T_maj / T_maj[0];
            for (int k = 0; k < NSpectrumSamples; ++k) est[k].Add(T[k]);
        }
        for (int k = 0; k < NSpectrumSamples; ++k)
            EXPECT_NEAR(est[k].Mean(), exact[k], 4 * est[k].StandardError() + 1e-4)
                << "ray " << r << " wavelength " << k;
    }
}

TEST(HomogeneousMediumTest, DeltaTrackingPassesWithBeerLambertProbability) {
    MediumFixture f;
    Medium m = f.Make("homogeneous",
                      Dict({Rgb("sigma_a", 0.2f, 0.2f, 0.2f), Rgb("sigma_s", 0.3f, 0.3f, 0.3f)}));
    SampledWavelengths lambda = Lambda();
    RNG rng(3);
    Ray ray(Point3f(0, 0, 0), Vector3f(0, 0, 2));  // not unit: t is in the ray's units
    const Float tMax = 1.5f;                       // a distance of 3
    MediumProperties mp = m.SamplePoint(Point3f(), lambda);
    double tau = 3.0 * (mp.sigma_a[0] + mp.sigma_s[0]);
    int passed = 0, n = 40000;
    for (int i = 0; i < n; ++i) {
        bool collided = false;
        m.SampleT_maj(
            ray, tMax, rng.UniformFloat(), rng, lambda,
            [&](Point3f, const MediumProperties&, const SampledSpectrum&, const SampledSpectrum&) {
                collided = true;
                return false;
            });
        passed += !collided;
    }
    double p = std::exp(-tau), se = std::sqrt(p * (1 - p) / n);
    EXPECT_NEAR(double(passed) / n, p, 4 * se);
}

TEST(MediumEmissionTest, ThermalEmissionFollowsTheModelInAbsoluteUnits) {
    SampledWavelengths lambda = Lambda(0.45f);
    const Float T = 1300;
    SampledSpectrum B = planck_radiance(lambda, T);
    for (const char* model : {"kirchhoff", "additive", "diffuse", "none"}) {
        SCOPED_TRACE(model);
        MediumFixture f;
        Medium m = f.Make("homogeneous",
                          Dict({Rgb("sigma_a", 0.4f, 0.4f, 0.4f), Rgb("sigma_s", 0.6f, 0.6f, 0.6f),
                                Float1("temperature", T), String1("emission", model)}));
        m.SetRefractiveIndex(ConstantSpectrum(1.5f));
        MediumProperties mp = m.SamplePoint(Point3f(), lambda);
        std::string s = model;
        Float sigma_a = s == "diffuse" ? 1.0f : 0.4f, sigma_s = s == "diffuse" ? 0 : 0.6f;
        Float perLength = s == "kirchhoff" ? 0.4f : s == "none" ? 0 : 1.0f;
        EXPECT_EQ(m.IsEmissive(), s != "none");
        for (int k = 0; k < NSpectrumSamples; ++k) {
            EXPECT_NEAR(mp.sigma_a[k], sigma_a, 1e-4f);
            EXPECT_NEAR(mp.sigma_s[k], sigma_s, 1e-4f);
            EXPECT_NEAR(mp.emission[k], perLength * 1.5f * 1.5f * B[k], 1e-3f * B[k]);
        }
    }
}

TEST(MediumEmissionTest, PbrtTemperatureGridsGlowWithTheNormalisedBlackbody) {
    MediumFixture f;
    // One voxel at 2000 K (pbrt-v4: Lescale times the peak-normalised blackbody); with kiln's
    // "emission" the same grid is in kelvin and absolute
    auto grid = [&](bool kiln) {
        ParsedParameterVector p = {Floats("float", "density", {1}),
                                   Floats("float", "temperature", {2000}), Float1("Lescale", 3),
                                   Rgb("sigma_a", 1, 1, 1)};
        if (kiln) p.push_back(String1("emission", "kirchhoff"));
        return f.Make("uniformgrid", ParameterDictionary(p, nullptr));
    };
    SampledWavelengths lambda = Lambda(0.2f);
    Point3f centre(0.5f, 0.5f, 0.5f);
    MediumProperties pbrt = grid(false).SamplePoint(centre, lambda);
    MediumProperties kiln = grid(true).SamplePoint(centre, lambda);
    for (int k = 0; k < NSpectrumSamples; ++k) {
        // times CIE_Y_integral: pbrt-v4's film does not divide by it (medium_emission.h)
        EXPECT_NEAR(pbrt.emission[k],
                    3 * planck_radiance_normalized(lambda[k], 2000) * CIE_Y_integral, 1e-2);
        EXPECT_NEAR(kiln.emission[k], planck_radiance(lambda[k], 2000),
                    1e-4 * planck_radiance(lambda[k], 2000));
    }
}

TEST(MediumTest, PresetsAndParametersAsPbrt) {
    MediumFixture f;
    Medium milk = f.Make("homogeneous", Dict({String1("preset", "Wholemilk")}));
    SampledWavelengths lambda = Lambda();
    MediumProperties mp = milk.SamplePoint(Point3f(), lambda);
    EXPECT_GT(mp.sigma_s.Average(), 100 * mp.sigma_a.Average());  // milk scatters
    EXPECT_EQ(f.diag.WarningCount(), 0);
    f.Make("homogeneous", Dict({String1("preset", "Vapour")}));
    EXPECT_EQ(f.diag.WarningCount(), 1);
    // Defaults: sigma_a = sigma_s = 1, times scale
    MediumProperties d =
        f.Make("homogeneous", Dict({Float1("scale", 2)})).SamplePoint(Point3f(), lambda);
    EXPECT_FLOAT_EQ(d.sigma_a[0], 2);
    EXPECT_FLOAT_EQ(d.sigma_s[0], 2);
}

TEST(MediumTest, BadParametersAreLocatedErrors) {
    MediumFixture f;
    auto error = [&](const std::string& type, ParsedParameterVector p) -> std::string {
        try {
            f.Make(type, ParameterDictionary(std::move(p), nullptr));
        } catch (const SceneError& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(error("homogeneous", {Float1("g", 1)}), "");
    EXPECT_NE(error("homogeneous", {Float1("scale", -1)}), "");
    EXPECT_NE(error("uniformgrid", {}), "");
    EXPECT_NE(error("uniformgrid", {Floats("float", "density", {1, 2, 3}), Int1("nx", 2)}), "");
    EXPECT_NE(
        error("uniformgrid", {Floats("float", "density", {1}), Floats("point3", "p0", {0, 0, 0}),
                              Floats("point3", "p1", {1, 0, 1})}),
        "");
    EXPECT_NE(error("rgbgrid", {}), "");
    EXPECT_NE(error("fog", {}), "");
    EXPECT_NE(error("homogeneous", {Float1("temperature", -5)}), "");
    // A missing .nvdb file: kiln's NanoVDB reader names it and says why
    std::string nvdb = error("nanovdb", {String1("filename", "explosion.nvdb")});
    EXPECT_NE(nvdb.find("explosion.nvdb: cannot read it"), std::string::npos) << nvdb;
    EXPECT_NE(error("nanovdb", {String1("filename", "/nonexistent/smoke.vdb")}), "");
    try {
        f.Make("homogeneous", Dict({}), Scale(0, 1, 1));
        ADD_FAILURE() << "a singular medium transform was accepted";
    } catch (const SceneError&) {
    }
}

TEST(CloudMediumTest, DensityStaysWithinItsMajorant) {
    MediumFixture f;
    Medium cloud = f.Make("cloud", Dict({Rgb("sigma_a", 1, 1, 1), Rgb("sigma_s", 2, 2, 2)}));
    SampledWavelengths lambda = Lambda();
    RNG rng(9);
    for (int r = 0; r < 50; ++r) {
        Ray ray = RandomRay(rng);
        MajorantIterator it = cloud.SampleRay(ray, 8, lambda);
        while (std::optional<RayMajorantSegment> seg = it.Next())
            for (int i = 0; i < 50; ++i) {
                MediumProperties mp =
                    cloud.SamplePoint(ray(Lerp(rng.UniformFloat(), seg->tMin, seg->tMax)), lambda);
                ASSERT_LE(mp.sigma_a[0] + mp.sigma_s[0], seg->sigma_maj[0] + 1e-5f);
                ASSERT_GE(mp.sigma_a[0], 0);
            }
    }
}

}  // namespace
}  // namespace kiln
