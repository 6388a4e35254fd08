// Samplers: determinism, range, stratification, Sobol' net properties, convergence, creation.
#include "core/camera/sampler.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <set>
#include <vector>

#include "base/statistics.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {
namespace {

ParsedParameter IntParam(const std::string& name, int v) {
    ParsedParameter p;
    p.type = "integer";
    p.name = name;
    p.ints = {v};
    return p;
}
ParsedParameter StringParam(const std::string& name, const std::string& v) {
    ParsedParameter p;
    p.type = "string";
    p.name = name;
    p.strings = {v};
    return p;
}

std::vector<Sampler> AllSamplers(int spp = 16) {
    int sq = int(std::sqrt(double(spp)));
    return {IndependentSampler(spp, 3),
            StratifiedSampler(sq, spp / sq, true, 3),
            ZSobolSampler(spp, Point2i(64, 48), RandomizeStrategy::FastOwen, 3),
            ZSobolSampler(spp, Point2i(64, 48), RandomizeStrategy::Owen, 3),
            ZSobolSampler(spp, Point2i(64, 48), RandomizeStrategy::PermuteDigits, 3),
            ZSobolSampler(spp, Point2i(64, 48), RandomizeStrategy::None, 3),
            PaddedSobolSampler(spp, RandomizeStrategy::FastOwen, 3),
            HaltonSampler(spp, Point2i(64, 48), RandomizeStrategy::PermuteDigits, 3),
            HaltonSampler(spp, Point2i(64, 48), RandomizeStrategy::Owen, 3),
            HaltonSampler(spp, Point2i(64, 48), RandomizeStrategy::None, 3),
            SobolSampler(spp, Point2i(64, 48), RandomizeStrategy::FastOwen, 3),
            SobolSampler(spp, Point2i(64, 48), RandomizeStrategy::None, 3),
            PMJ02BNSampler(spp, 3)};
}

// The values of one pixel sample: pixel 2D, then 1D, 2D, 1D, ... over 20 dimensions.
std::vector<Float> Stream(Sampler& s, Point2i p, int index, int dim = 0) {
    s.StartPixelSample(p, index, dim);
    std::vector<Float> v;
    Point2f u = s.GetPixel2D();
    v.push_back(u.x), v.push_back(u.y);
    for (int i = 0; i < 6; ++i) {
        v.push_back(s.Get1D());
        u = s.Get2D();
        v.push_back(u.x), v.push_back(u.y);
    }
    return v;
}

TEST(Sampler, DeterministicRegardlessOfOrder) {
    for (Sampler s : AllSamplers()) {
        std::vector<Float> a = Stream(s, Point2i(5, 7), 9);
        // Interleave other pixels, samples and a clone.
        Sampler other = s.Clone();
        for (int i = 0; i < 16; ++i) Stream(other, Point2i(i, 3 * i), i);
        for (int i = 0; i < 16; ++i) Stream(s, Point2i(i + 1, 2), 15 - i);
        EXPECT_EQ(a, Stream(s, Point2i(5, 7), 9)) << s.Index();
        EXPECT_EQ(a, Stream(other, Point2i(5, 7), 9)) << s.Index();
        // Different pixels and samples give different values.
        EXPECT_NE(a, Stream(s, Point2i(6, 7), 9));
        EXPECT_NE(a, Stream(s, Point2i(5, 7), 10));
    }
}

TEST(Sampler, StartAtDimensionMatchesSkipping) {
    for (Sampler s : AllSamplers()) {
        // Starting at dimension 2 equals the values after GetPixel2D.
        s.StartPixelSample(Point2i(1, 2), 3, 0);
        s.GetPixel2D();
        Float a = s.Get1D();
        s.StartPixelSample(Point2i(1, 2), 3, 2);
        if (s.Is<IndependentSampler>() || s.Is<StratifiedSampler>())
            continue;  // RNG-based samplers advance by values drawn, as in pbrt-v4
        EXPECT_EQ(a, s.Get1D()) << s.Index();
    }
}

TEST(Sampler, ValuesInUnitInterval) {
    for (Sampler s : AllSamplers()) {
        for (int py = 0; py < 4; ++py)
            for (int px = 0; px < 4; ++px)
                for (int i = 0; i < s.SamplesPerPixel(); ++i)
                    for (Float v : Stream(s, Point2i(px, py), i)) {
                        ASSERT_GE(v, 0);
                        ASSERT_LT(v, 1);
                    }
    }
}

// Independent values are uniform: chi-square over many pixels, and pairs uncorrelated.
TEST(Sampler, IndependentIsUniform) {
    Sampler s = IndependentSampler(16, 0);
    const int nb = 16;
    std::vector<double> observed(nb * nb, 0), expected(nb * nb, 0);
    int n = 0;
    for (int py = 0; py < 32; ++py)
        for (int px = 0; px < 32; ++px)
            for (int i = 0; i < 16; ++i) {
                s.StartPixelSample(Point2i(px, py), i);
                s.GetPixel2D();
                Point2f u = s.Get2D();
                observed[int(u.y * nb) * nb + int(u.x * nb)] += 1;
                ++n;
            }
    for (double& e : expected) e = double(n) / (nb * nb);
    ChiSquareResult r = ChiSquareTest(observed, expected);
    EXPECT_TRUE(r.passed) << r.message;
}

// Every k x (spp/k) grid (a power-of-two spp: all elementary intervals of area 1/spp) holds
// exactly one of a pixel's spp points.
void ExpectElementaryIntervals(const std::vector<Point2f>& pts, const std::string& what) {
    int n = int(pts.size());
    int m = Log2Int(uint64_t(n));
    ASSERT_EQ(1 << m, n);
    for (int k = 0; k <= m; ++k) {
        int nx = 1 << k, ny = 1 << (m - k);
        std::vector<int> count(n, 0);
        for (Point2f p : pts) ++count[int(p.y * ny) * nx + int(p.x * nx)];
        for (int c : count) ASSERT_EQ(c, 1) << what << " intervals " << nx << "x" << ny;
    }
}

TEST(Sampler, ZSobolIsANetPerPixel) {
    for (int spp : {4, 8, 16, 32, 64, 256}) {
        for (RandomizeStrategy r : {RandomizeStrategy::None, RandomizeStrategy::PermuteDigits,
                                    RandomizeStrategy::FastOwen, RandomizeStrategy::Owen}) {
            ZSobolSampler z(spp, Point2i(100, 60), r, 1);
            ASSERT_EQ(z.SamplesPerPixel(), spp);
            for (Point2i p : {Point2i(0, 0), Point2i(13, 7), Point2i(99, 59)}) {
                std::vector<Point2f> pixel, later;
                for (int i = 0; i < spp; ++i) {
                    z.StartPixelSample(p, i, 0);
                    pixel.push_back(z.GetPixel2D());
                    z.Get1D();
                    later.push_back(z.Get2D());
                }
                std::string what = "spp " + std::to_string(spp) + " r " + std::to_string(int(r)) +
                                   " pixel " + std::to_string(p.x);
                ExpectElementaryIntervals(pixel, what + " dims 0-1");
                ExpectElementaryIntervals(later, what + " dims 3-4");
            }
        }
    }
}

TEST(Sampler, StratifiedOnePointPerStratum) {
    StratifiedSampler st(4, 2, true, 5);
    Sampler s = st;
    for (Point2i p : {Point2i(0, 0), Point2i(3, 9)}) {
        for (int dim : {0, 3}) {
            std::set<int> strata;
            for (int i = 0; i < 8; ++i) {
                s.StartPixelSample(p, i, dim);
                Point2f u = s.Get2D();
                strata.insert(int(u.y * 2) * 4 + int(u.x * 4));
            }
            EXPECT_EQ(strata.size(), 8u);
        }
        // 1D values: one per 1/8 interval.
        std::set<int> bins;
        for (int i = 0; i < 8; ++i) {
            s.StartPixelSample(p, i, 0);
            s.Get2D();
            bins.insert(int(s.Get1D() * 8));
        }
        EXPECT_EQ(bins.size(), 8u);
    }
}

TEST(Sampler, PaddedSobolStratifiesEachDimensionPair) {
    Sampler s = PaddedSobolSampler(16, RandomizeStrategy::FastOwen, 2);
    std::vector<Point2f> a, b;
    for (int i = 0; i < 16; ++i) {
        s.StartPixelSample(Point2i(4, 4), i);
        a.push_back(s.GetPixel2D());
        s.Get1D();
        b.push_back(s.Get2D());
    }
    ExpectElementaryIntervals(a, "padded 0-1");
    ExpectElementaryIntervals(b, "padded 3-4");
}

// Unscrambled Sobol': each dimension is a (0,1)-sequence (the first 2^m values fall one per
// interval of length 2^-m), and dimensions 0 and 1 form a (0,2)-sequence.
TEST(Sobol, MatricesGiveLowDiscrepancy) {
    for (int d = 0; d < NSobolDimensions; ++d) {
        for (int m : {1, 4, 10}) {
            std::vector<int> count(1 << m, 0);
            for (uint64_t a = 0; a < (1u << m); ++a)
                ++count[int(SobolSample(a, d, NoRandomizer()) * (1 << m))];
            for (int c : count) ASSERT_EQ(c, 1) << "dim " << d << " m " << m;
        }
        // A later aligned block of 2^m indices too.
        std::vector<int> count(256, 0);
        for (uint64_t a = 256 * 77; a < 256 * 78; ++a)
            ++count[int(SobolSample(a, d, NoRandomizer()) * 256)];
        for (int c : count) ASSERT_EQ(c, 1) << "dim " << d << " block";
    }
    // Known first values of dimension 2 (Joe-Kuo d=2: m = 1): 0, 1/2, 3/4, 1/4.
    EXPECT_EQ(SobolSample(1, 1, NoRandomizer()), 0.5f);
    EXPECT_EQ(SobolSample(2, 1, NoRandomizer()), 0.75f);
    EXPECT_EQ(SobolSample(3, 1, NoRandomizer()), 0.25f);
    std::vector<Point2f> pts;
    for (uint64_t a = 1024; a < 2048; ++a)
        pts.push_back(
            Point2f(SobolSample(a, 0, NoRandomizer()), SobolSample(a, 1, NoRandomizer())));
    ExpectElementaryIntervals(pts, "sobol 0-1");
}

TEST(Sobol, ScramblersAreBijectiveOnPrefixes) {
    // Owen scrambling maps each dyadic interval onto one of the same size: the scrambled first
    // 2^m points still fill every interval of length 2^-m.
    for (uint32_t seed : {1u, 0x12345678u, 0xdeadbeefu}) {
        std::vector<int> cf(64, 0), co(64, 0);
        for (uint64_t a = 0; a < 64; ++a) {
            ++cf[int(SobolSample(a, 3, FastOwenScrambler(seed)) * 64)];
            ++co[int(SobolSample(a, 3, OwenScrambler(seed)) * 64)];
        }
        for (int i = 0; i < 64; ++i) {
            EXPECT_EQ(cf[i], 1);
            EXPECT_EQ(co[i], 1);
        }
    }
}

TEST(Sampler, PermutationElementIsAPermutation) {
    for (uint32_t n : {1u, 5u, 16u, 100u}) {
        std::set<int> seen;
        for (uint32_t i = 0; i < n; ++i) seen.insert(PermutationElement(i, n, 0xabcdef));
        EXPECT_EQ(seen.size(), n);
        EXPECT_EQ(*seen.rbegin(), int(n) - 1);
    }
}

// Mean absolute error of per-pixel estimates of a smooth integral over [0,1]^2.
double MeanError(Sampler s, int npixels) {
    auto f = [](Point2f u) { return std::exp(-Sqr(u.x - 0.3f) - 2 * Sqr(u.y - 0.6f)) * u.x; };
    // Reference by fine midpoint quadrature.
    double ref = 0;
    const int n = 1024;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) ref += f(Point2f((x + 0.5f) / n, (y + 0.5f) / n));
    ref /= double(n) * n;
    double err = 0;
    for (int p = 0; p < npixels; ++p) {
        double sum = 0;
        for (int i = 0; i < s.SamplesPerPixel(); ++i) {
            s.StartPixelSample(Point2i(p % 8, p / 8), i);
            s.GetPixel2D();
            s.Get1D();
            sum += f(s.Get2D());
        }
        err += std::abs(sum / s.SamplesPerPixel() - ref);
    }
    return err / npixels;
}

TEST(Sampler, ZSobolConvergesFasterThanIndependent) {
    double indep = MeanError(IndependentSampler(256, 1), 64);
    double zsobol =
        MeanError(ZSobolSampler(256, Point2i(8, 8), RandomizeStrategy::FastOwen, 1), 64);
    double strat = MeanError(StratifiedSampler(16, 16, true, 1), 64);
    // At 256 spp independent error ~ sigma/16; a scrambled (0,2)-net is ~ N^-1.5 for smooth
    // integrands. Require a factor of 8, far below the expected ~50.
    EXPECT_LT(zsobol * 8, indep) << zsobol << " vs " << indep;
    EXPECT_LT(strat * 4, indep) << strat << " vs " << indep;
}

TEST(Sampler, Create) {
    Diagnostics diag(nullptr);
    ParameterDictionary empty;
    Point2i res(32, 32);
    Sampler z = Sampler::Create("zsobol", empty, res, FileLoc(), diag);
    EXPECT_TRUE(z.Is<ZSobolSampler>());
    EXPECT_EQ(z.SamplesPerPixel(), 16);

    Sampler h = Sampler::Create("halton", empty, res, FileLoc(), diag);
    EXPECT_TRUE(h.Is<HaltonSampler>());
    EXPECT_EQ(h.SamplesPerPixel(), 16);
    EXPECT_TRUE(Sampler::Create("sobol", empty, res, FileLoc(), diag).Is<SobolSampler>());
    EXPECT_TRUE(Sampler::Create("pmj02bn", empty, res, FileLoc(), diag).Is<PMJ02BNSampler>());
    EXPECT_EQ(diag.WarningCount(), 0);
    // halton rejects "fastowen" (pbrt-v4); sobol warns about 12 spp and keeps it; pmj02bn warns
    // about 8 (not a power of 4) and keeps it, and refuses more than 65536.
    ParameterDictionary fastOwen({StringParam("randomization", "fastowen")}, nullptr);
    EXPECT_THROW(Sampler::Create("halton", fastOwen, res, FileLoc(), diag), SceneError);
    EXPECT_TRUE(Sampler::Create("sobol", fastOwen, res, FileLoc(), diag).Is<SobolSampler>());
    EXPECT_EQ(Sampler::Create("sobol", empty, res, FileLoc(), diag, 12).SamplesPerPixel(), 12);
    EXPECT_EQ(diag.WarningCount(), 1);
    EXPECT_EQ(Sampler::Create("pmj02bn", empty, res, FileLoc(), diag, 8).SamplesPerPixel(), 8);
    EXPECT_EQ(diag.WarningCount(), 2);
    EXPECT_EQ(Sampler::Create("pmj02bn", empty, res, FileLoc(), diag, 64).SamplesPerPixel(), 64);
    EXPECT_EQ(diag.WarningCount(), 2);
    EXPECT_THROW(Sampler::Create("pmj02bn", empty, res, FileLoc(), diag, 65537), SceneError);

    ParameterDictionary params({IntParam("pixelsamples", 64), IntParam("seed", 4)}, nullptr);
    Sampler i = Sampler::Create("independent", params, res, FileLoc(), diag);
    EXPECT_EQ(i.SamplesPerPixel(), 64);
    EXPECT_EQ(Sampler::Create("independent", params, res, FileLoc(), diag, 8).SamplesPerPixel(), 8);
    // The seed changes the values; an override wins over the parameter.
    Sampler a = Sampler::Create("independent", params, res, FileLoc(), diag, {}, 9);
    Sampler b = Sampler::Create("independent", empty, res, FileLoc(), diag, {}, 9);
    Sampler c = Sampler::Create("independent", empty, res, FileLoc(), diag);
    EXPECT_EQ(Stream(a, Point2i(1, 1), 0), Stream(b, Point2i(1, 1), 0));
    EXPECT_NE(Stream(a, Point2i(1, 1), 0), Stream(c, Point2i(1, 1), 0));

    ParameterDictionary strat({IntParam("xsamples", 3), IntParam("ysamples", 5)}, nullptr);
    EXPECT_EQ(Sampler::Create("stratified", strat, res, FileLoc(), diag).SamplesPerPixel(), 15);
    EXPECT_EQ(Sampler::Create("stratified", strat, res, FileLoc(), diag, 12).SamplesPerPixel(), 12);

    // pbrt-v4's counts: zsobol renders the largest power of two not above the count (12 -> 8),
    // paddedsobol the count itself; independent defaults to 4 samples, the others to 16
    int warnings = diag.WarningCount();
    EXPECT_EQ(Sampler::Create("zsobol", empty, res, FileLoc(), diag, 12).SamplesPerPixel(), 8);
    EXPECT_EQ(diag.WarningCount(), warnings + 1);
    EXPECT_EQ(Sampler::Create("paddedsobol", empty, res, FileLoc(), diag, 12).SamplesPerPixel(),
              12);
    EXPECT_EQ(diag.WarningCount(), warnings + 2);
    EXPECT_EQ(Sampler::Create("independent", empty, res, FileLoc(), diag).SamplesPerPixel(), 4);

    ParameterDictionary badRand({StringParam("randomization", "bogus")}, nullptr);
    EXPECT_THROW(Sampler::Create("zsobol", badRand, res, FileLoc(), diag), SceneError);
    EXPECT_THROW(Sampler::Create("random", empty, res, FileLoc(), diag), SceneError);
}

TEST(Sampler, ZSobolPixelCacheIsTransparent) {
    // ZSobolSampler memoises the pixel's digits per dimension: a sampler reused across samples
    // and pixels (and beyond the cached dimensions) must return what a fresh one returns.
    for (int spp : {1, 2, 8, 32, 64}) {
        ZSobolSampler reused(spp, Point2i(100, 60), RandomizeStrategy::FastOwen, 5);
        for (Point2i p : {Point2i(3, 4), Point2i(3, 4), Point2i(99, 59), Point2i(3, 4)})
            for (int i = 0; i < spp; ++i) {
                ZSobolSampler fresh(spp, Point2i(100, 60), RandomizeStrategy::FastOwen, 5);
                reused.StartPixelSample(p, i, 0);
                fresh.StartPixelSample(p, i, 0);
                for (int d = 0; d < 90; ++d) {
                    ASSERT_EQ(reused.GetSampleIndex(), fresh.GetSampleIndex()) << spp << " " << d;
                    ASSERT_EQ(reused.Get1D(), fresh.Get1D());
                }
            }
    }
    // As the renderer visits them: waves of 1, 2, 4, ... samples over the rows of a tile, so
    // pixels of one 2x2 block (whose upper digits are cached) come and go between others
    for (int spp : {1, 2, 4, 8, 16, 32}) {
        ZSobolSampler reused(spp, Point2i(100, 60), RandomizeStrategy::FastOwen, 5);
        for (int waveStart = 0, waveSize = 1; waveStart < spp; waveStart += waveSize, waveSize *= 2)
            for (int y = 5; y < 10; ++y)
                for (int x = 61; x < 67; ++x)
                    for (int i = waveStart; i < std::min(spp, waveStart + waveSize); ++i) {
                        ZSobolSampler fresh(spp, Point2i(100, 60), RandomizeStrategy::FastOwen, 5);
                        reused.StartPixelSample(Point2i(x, y), i, 0);
                        fresh.StartPixelSample(Point2i(x, y), i, 0);
                        for (int d = 0; d < 70; ++d) {
                            ASSERT_EQ(reused.GetSampleIndex(), fresh.GetSampleIndex())
                                << spp << " (" << x << ", " << y << ") " << i << " " << d;
                            ASSERT_EQ(reused.Get1D(), fresh.Get1D());
                        }
                    }
    }
}

TEST(LowDiscrepancy, FastSobolBitsMatchMatrices) {
    // The bit-reversal and table paths of SobolBits equal the generator-matrix product.
    RNG rng(11);
    for (int dim = 0; dim < 3; ++dim) {
        std::span<const uint32_t> c = SobolMatrix(dim);
        for (int n = 0; n < 20000; ++n) {
            uint64_t a = n < 1000 ? uint64_t(n) : (uint64_t(rng.Uniform32()) << (n % 21)) ^ n;
            uint32_t v = 0;
            for (int i = 0; i < SobolMatrixSize; ++i)
                if ((a >> i) & 1) v ^= c[i];
            ASSERT_EQ(SobolBits(a, dim), v) << "dim " << dim << " index " << a;
        }
    }
}

}  // namespace
}  // namespace kiln
