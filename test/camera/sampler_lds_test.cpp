// Halton, global Sobol' and pmj02bn samplers: their building blocks (primes, radical inverses,
// digit permutations, the Sobol' pixel-to-index map, pmj02 generation) and the per-pixel
// stratification, uniformity, seeding and convergence of the samplers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "base/statistics.h"
#include "core/camera/sampler.h"

namespace kiln {
namespace {

// Every box of a grid nx x ny (nx ny = number of points) holds exactly one point.
::testing::AssertionResult OnePerBox(const std::vector<Point2f>& pts, int nx, int ny) {
    std::vector<int> count(size_t(nx) * ny, 0);
    for (Point2f p : pts) ++count[size_t(int(p.y * ny)) * nx + size_t(int(p.x * nx))];
    for (size_t i = 0; i < count.size(); ++i)
        if (count[i] != 1)
            return ::testing::AssertionFailure()
                   << "box " << i << " of " << nx << "x" << ny << " holds " << count[i];
    return ::testing::AssertionSuccess();
}

// All elementary intervals 2^-k x 2^-(m-k) of a 2^m-point set hold one point each.
::testing::AssertionResult IsBase2Net(const std::vector<Point2f>& pts) {
    int m = Log2Int(uint64_t(pts.size()));
    if (size_t(1) << m != pts.size()) return ::testing::AssertionFailure() << "not 2^m points";
    for (int k = 0; k <= m; ++k) {
        auto r = OnePerBox(pts, 1 << k, 1 << (m - k));
        if (!r) return r;
    }
    return ::testing::AssertionSuccess();
}

// The pixel positions and the 2D samples at dimensions (d, d+1) of one pixel's samples.
std::vector<Point2f> PixelSamples(Sampler s, Point2i p, int dim = -1) {
    std::vector<Point2f> pts;
    for (int i = 0; i < s.SamplesPerPixel(); ++i) {
        s.StartPixelSample(p, i, std::max(dim, 0));
        pts.push_back(dim < 0 ? s.GetPixel2D() : s.Get2D());
    }
    return pts;
}

TEST(RadicalInverse, PrimesAndValues) {
    std::span<const int> primes = Primes();
    ASSERT_EQ(primes.size(), size_t(kPrimeTableSize));
    EXPECT_EQ(primes[0], 2);
    EXPECT_EQ(primes[4], 11);
    EXPECT_EQ(primes[999], 7919);
    for (size_t i = 0; i < primes.size(); ++i) {
        if (i) {
            ASSERT_GT(primes[i], primes[i - 1]);
        }
        for (int d = 2; d * d <= primes[i]; ++d) ASSERT_NE(primes[i] % d, 0) << primes[i];
    }
    // Base 2 is the bit reversal; base 3: 1 -> 1/3, 5 = 12_3 -> 2/3 + 1/9.
    for (uint64_t a : {1ull, 6ull, 12345ull})
        EXPECT_EQ(RadicalInverse(0, a), Float(ReverseBits32(uint32_t(a)) * 0x1p-32));
    EXPECT_FLOAT_EQ(RadicalInverse(1, 1), 1.0f / 3);
    EXPECT_FLOAT_EQ(RadicalInverse(1, 5), 2.0f / 3 + 1.0f / 9);
    for (int base : {2, 3, 7})
        for (uint64_t v = 0; v < 49; ++v) {
            uint64_t a = InverseRadicalInverse(v, base, 2);
            EXPECT_FLOAT_EQ(RadicalInverse(base == 2   ? 0
                                           : base == 3 ? 1
                                                       : 3,
                                           a),
                            Float(v) / Float(base * base));
            if (v + 1 >= uint64_t(base * base)) break;
        }
}

TEST(RadicalInverse, DigitPermutationsArePermutationsFromTheSeed) {
    DigitPermutations a(7), b(7), c(8);
    int differing = 0;
    // Tabulated bases and bases computed on demand (index >= kTabulatedBases).
    for (int bi : {0, 1, 5, DigitPermutations::kTabulatedBases - 1,
                   DigitPermutations::kTabulatedBases, 999}) {
        int base = Primes()[size_t(bi)];
        int nDigits = DigitPermutations::NumDigits(base);
        EXPECT_GE(nDigits, 2);
        for (int k = 0; k < nDigits; ++k) {
            std::set<int> values;
            for (int d = 0; d < base; ++d) {
                values.insert(a.Permute(bi, k, d));
                ASSERT_EQ(a.Permute(bi, k, d), b.Permute(bi, k, d));
                differing += a.Permute(bi, k, d) != c.Permute(bi, k, d);
            }
            ASSERT_EQ(values.size(), size_t(base)) << "base " << base << " digit " << k;
        }
    }
    EXPECT_GT(differing, 1000);
    // Digits while 1 - (base - 1) base^-k < 1 in float: 2^-24 is the last one visible.
    EXPECT_EQ(DigitPermutations::NumDigits(2), 25);
}

TEST(HaltonSampler, PixelIndexLandsInPixel) {
    // 200 x 100 image: bases scaled to 2^7 = 128 and 3^5 = 243 (both capped by 128 pixels).
    HaltonSampler h(16, Point2i(200, 100), RandomizeStrategy::PermuteDigits, 1);
    EXPECT_EQ(h.BaseScales(), Point2i(128, 243));
    for (Point2i p : {Point2i(0, 0), Point2i(5, 3), Point2i(127, 99), Point2i(150, 42)})
        for (int i : {0, 1, 15}) {
            h.StartPixelSample(p, i, 0);
            int64_t index = h.HaltonIndex();
            EXPECT_EQ(int(RadicalInverse(0, uint64_t(index)) * 128), p.x % 128);
            EXPECT_EQ(int(RadicalInverse(1, uint64_t(index)) * 243), p.y % 128);
            // Consecutive samples of a pixel are one stride (128 * 243) apart.
            EXPECT_EQ(index / (128 * 243), i);
        }
}

TEST(HaltonSampler, ElementaryIntervalsInBases2And3) {
    // 72 = 2^3 3^2 samples: pixel positions one per 8 x 9 box (the first 24 one per 8 x 3, the
    // first 36 one per 4 x 9); dimensions 2, 3 (bases 5, 7):
    // the first 35 samples one per 5 x 7 box; dimension 4 (base 11) one per 1/11.
    for (RandomizeStrategy r :
         {RandomizeStrategy::PermuteDigits, RandomizeStrategy::Owen, RandomizeStrategy::None}) {
        Sampler s = HaltonSampler(72, Point2i(40, 30), r, 4);
        for (Point2i p : {Point2i(0, 0), Point2i(17, 29)}) {
            std::vector<Point2f> pixel = PixelSamples(s, p);
            EXPECT_TRUE(OnePerBox(pixel, 8, 9)) << int(r);
            EXPECT_TRUE(OnePerBox({pixel.begin(), pixel.begin() + 24}, 8, 3)) << int(r);
            EXPECT_TRUE(OnePerBox({pixel.begin(), pixel.begin() + 36}, 4, 9)) << int(r);
            std::vector<Point2f> d23 = PixelSamples(s, p, 2);
            d23.resize(35);
            EXPECT_TRUE(OnePerBox(d23, 5, 7)) << int(r);
            std::set<int> strata;
            for (int i = 0; i < 11; ++i) {
                s.StartPixelSample(p, i, 4);
                strata.insert(int(s.Get1D() * 11));
            }
            EXPECT_EQ(strata.size(), 11u) << int(r);
        }
    }
}

TEST(SobolSampler, IntervalToIndexLandsInPixel) {
    for (int m : {0, 1, 3, 6}) {
        SobolIntervalToIndex map(m);
        int n = 1 << m;
        for (int frame : {0, 1, 5, 37})
            for (int y = 0; y < n; y += std::max(1, n / 5))
                for (int x = 0; x < n; x += std::max(1, n / 7)) {
                    uint64_t index = map.Index(uint64_t(frame), Point2i(x, y));
                    ASSERT_EQ(index >> (2 * m), uint64_t(frame));
                    if (m == 0) continue;
                    ASSERT_EQ(int(SobolBits(index, 0) >> (32 - m)), x) << m << " " << frame;
                    ASSERT_EQ(int(SobolBits(index, 1) >> (32 - m)), y) << m << " " << frame;
                }
    }
}

TEST(SobolSampler, PixelSamplesAreNets) {
    // A pixel's first 2^k samples are the points of the first 2^k blocks of 4^m global points
    // inside it: a (0,k,2)-net in the pixel, for any randomization of the later dimensions.
    for (int spp : {4, 16, 64}) {
        Sampler s = SobolSampler(spp, Point2i(50, 20), RandomizeStrategy::FastOwen, 2);
        for (Point2i p : {Point2i(0, 0), Point2i(49, 19), Point2i(33, 7)})
            EXPECT_TRUE(IsBase2Net(PixelSamples(s, p))) << spp << " " << p.x;
    }
}

TEST(PMJ02, EveryPrefixIsANet) {
    for (uint64_t seed : {1u, 2u}) {
        int restarts = -1;
        std::vector<FixedPoint2> pts = GeneratePMJ02(5, seed, &restarts);
        EXPECT_EQ(restarts, 0);
        ASSERT_EQ(pts.size(), 1024u);
        for (int m = 0; m <= 10; ++m) {
            std::vector<Point2f> prefix;
            for (size_t i = 0; i < (size_t(1) << m); ++i)
                prefix.push_back({FixedToFloat(pts[i][0]), FixedToFloat(pts[i][1])});
            ASSERT_TRUE(IsBase2Net(prefix)) << "seed " << seed << " prefix " << (1 << m);
        }
        // Deterministic in the seed, different between seeds.
        EXPECT_EQ(pts, GeneratePMJ02(5, seed));
        EXPECT_NE(pts, GeneratePMJ02(5, seed + 2));
    }
    // The tables the sampler uses: all 65536 points of each set (checked on their integer
    // bits, exactly), every power-of-two prefix.
    for (int set = 0; set < kPMJ02Sets; ++set) {
        std::span<const FixedPoint2> t = PMJ02Set(set);
        ASSERT_EQ(t.size(), size_t(kPMJ02Samples));
        for (int m = 0; m <= 16; m += (m < 12 ? 1 : 2))
            for (int k = 0; k <= m; ++k) {
                std::vector<uint8_t> seen(size_t(1) << m, 0);
                for (size_t i = 0; i < (size_t(1) << m); ++i) {
                    uint32_t X = m ? t[i][0] >> (32 - m) : 0, Y = m ? t[i][1] >> (32 - m) : 0;
                    size_t box = (size_t(X >> (m - k)) << (m - k)) | size_t(Y >> k);
                    ASSERT_FALSE(seen[box]) << "set " << set << " m " << m << " k " << k;
                    seen[box] = 1;
                }
            }
    }
}

// Cyclic gaps between sorted values of a stratified set shifted modulo 1 stay below 2/n.
double MaxCyclicGap(std::vector<Float> v) {
    std::sort(v.begin(), v.end());
    double gap = 1 - v.back() + v.front();
    for (size_t i = 1; i < v.size(); ++i) gap = std::max(gap, double(v[i] - v[i - 1]));
    return gap;
}

TEST(PMJ02BNSampler, PixelSamplesAreNetsAndLaterDimensionsStratified) {
    for (int spp : {1, 4, 16, 64}) {
        PMJ02BNSampler pmj(spp, 3);
        EXPECT_EQ(pmj.TileSize() * pmj.TileSize() * spp, kPMJ02Samples);
        Sampler s = pmj;
        for (Point2i p : {Point2i(0, 0), Point2i(7, 300), Point2i(255, 3)}) {
            EXPECT_TRUE(IsBase2Net(PixelSamples(s, p))) << spp;
            // Dimensions 2-3 (table set 1) and 12-13 (permuted set 1) rotated per pixel.
            for (int dim : {2, 12}) {
                std::vector<Float> xs, ys, ones;
                for (Point2f u : PixelSamples(s, p, dim)) xs.push_back(u.x), ys.push_back(u.y);
                for (int i = 0; i < spp; ++i) {
                    s.StartPixelSample(p, i, dim + 1);
                    ones.push_back(s.Get1D());
                }
                EXPECT_LT(MaxCyclicGap(xs), 2.0 / spp + 1e-6) << spp << " dim " << dim;
                EXPECT_LT(MaxCyclicGap(ys), 2.0 / spp + 1e-6) << spp << " dim " << dim;
                // 1D: a rotated regular grid.
                EXPECT_NEAR(MaxCyclicGap(ones), 1.0 / spp, 1e-5) << spp << " dim " << dim;
            }
        }
    }
}

TEST(PMJ02BNSampler, PixelOffsetsStratifiedOverPixelBlocks) {
    // In every aligned 2^k x 2^k block the rotations of a dimension fall in distinct 4^-k
    // intervals; dimensions and seeds get different offsets. With 1 spp, Get1D is the offset.
    PMJ02BNSampler a(1, 5), b(1, 6);
    for (int dim : {2, 3, 17}) {
        for (int k : {1, 2, 3}) {
            int side = 1 << k;
            for (Point2i corner : {Point2i(0, 0), Point2i(8, 16), Point2i(256 + 40, 72)}) {
                std::set<int> bins;
                int differing = 0;
                for (int y = 0; y < side; ++y)
                    for (int x = 0; x < side; ++x) {
                        Point2i p(corner.x + x, corner.y + y);
                        a.StartPixelSample(p, 0, dim);
                        Float offset = a.PixelOffset(dim);
                        EXPECT_EQ(a.Get1D(), offset);
                        bins.insert(int(offset * side * side));
                        a.StartPixelSample(p, 0, dim);
                        differing += offset != a.PixelOffset(dim + 1);
                        b.StartPixelSample(p, 0, dim);
                        differing += offset != b.PixelOffset(dim);
                    }
                EXPECT_EQ(bins.size(), size_t(side * side)) << dim << " " << k;
                EXPECT_EQ(differing, 2 * side * side);
            }
        }
    }
}

TEST(PMJ02BNSampler, OffsetCacheIsTransparent) {
    // A sampler reused across samples and pixels (and beyond the cached dimensions) returns
    // what a fresh one returns.
    PMJ02BNSampler reused(16, 5);
    for (Point2i p : {Point2i(3, 4), Point2i(3, 4), Point2i(300, 59), Point2i(3, 4)})
        for (int i = 0; i < 16; i += 5) {
            PMJ02BNSampler fresh(16, 5);
            reused.StartPixelSample(p, i, 0);
            fresh.StartPixelSample(p, i, 0);
            for (int d = 0; d < 90; ++d) ASSERT_EQ(reused.Get1D(), fresh.Get1D()) << d;
        }
}

std::vector<Sampler> NewSamplers(int spp, int seed = 7) {
    return {HaltonSampler(spp, Point2i(32, 32), RandomizeStrategy::PermuteDigits, seed),
            HaltonSampler(spp, Point2i(32, 32), RandomizeStrategy::Owen, seed),
            SobolSampler(spp, Point2i(32, 32), RandomizeStrategy::FastOwen, seed),
            SobolSampler(spp, Point2i(32, 32), RandomizeStrategy::Owen, seed),
            PMJ02BNSampler(spp, seed)};
}

// Pairs of dimensions are jointly uniform over many pixels: chi-square on 8 x 8 bins for
// (pixel x, 1D dim 2), (2D dims 3, 4), (dim 4, dim 9) and (dim 7, dim 20).
TEST(Sampler, NewSamplersUniformAndIndependentAcrossDimensions) {
    const int nb = 8, pairs = 4;
    for (Sampler s : NewSamplers(16)) {
        std::vector<std::vector<double>> observed(pairs, std::vector<double>(nb * nb, 0));
        int n = 0;
        for (int py = 0; py < 24; ++py)
            for (int px = 0; px < 24; ++px)
                for (int i = 0; i < 16; ++i) {
                    s.StartPixelSample(Point2i(px, py), i);
                    std::vector<Float> v;
                    Point2f u = s.GetPixel2D();
                    v.push_back(u.x), v.push_back(u.y);
                    while (v.size() < 22) {
                        v.push_back(s.Get1D());
                        u = s.Get2D();
                        v.push_back(u.x), v.push_back(u.y);
                    }
                    int dims[pairs][2] = {{0, 2}, {3, 4}, {4, 9}, {7, 20}};
                    for (int k = 0; k < pairs; ++k)
                        observed[size_t(k)][size_t(int(v[size_t(dims[k][1])] * nb) * nb +
                                                   int(v[size_t(dims[k][0])] * nb))] += 1;
                    ++n;
                }
        std::vector<double> expected(nb * nb, double(n) / (nb * nb));
        for (int k = 0; k < pairs; ++k) {
            ChiSquareResult r = ChiSquareTest(observed[size_t(k)], expected, 0.01, 5 * pairs);
            EXPECT_TRUE(r.passed) << "sampler " << s.Index() << " pair " << k << ": " << r.message;
        }
    }
}

TEST(Sampler, NewSamplersSeededAndDistinctPerPixel) {
    for (int k = 0; k < 5; ++k) {
        Sampler a = NewSamplers(16)[size_t(k)];
        Sampler b = NewSamplers(16)[size_t(k)];
        auto stream = [](Sampler& s, Point2i p, int i) {
            s.StartPixelSample(p, i);
            std::vector<Float> v;
            for (int d = 0; d < 8; ++d) v.push_back(s.Get1D());
            return v;
        };
        // Same seed, same values; another seed changes dimensions >= 2.
        Sampler c = NewSamplers(16, 8)[size_t(k)];
        EXPECT_EQ(stream(a, Point2i(3, 4), 5), stream(b, Point2i(3, 4), 5)) << k;
        EXPECT_NE(stream(a, Point2i(3, 4), 5), stream(c, Point2i(3, 4), 5)) << k;
        // Every pixel of a 16 x 16 block and every sample gets its own values.
        std::set<std::vector<Float>> seen;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                for (int i = 0; i < 4; ++i) seen.insert(stream(a, Point2i(x, y), i));
        EXPECT_EQ(seen.size(), 16u * 16 * 4) << k;
    }
}

// Mean absolute error over pixels of a smooth integral over the pixel's positions (dims 0-1)
// and over dims 3-4 against independent sampling at 64 spp.
double MeanError(Sampler s, bool pixelDims) {
    auto f = [](Point2f u) { return std::exp(-Sqr(u.x - 0.3f) - 2 * Sqr(u.y - 0.6f)) * u.x; };
    double ref = 0;
    const int n = 512;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) ref += f(Point2f((x + 0.5f) / n, (y + 0.5f) / n));
    ref /= double(n) * n;
    double err = 0;
    const int npixels = 64;
    for (int p = 0; p < npixels; ++p) {
        double sum = 0;
        for (int i = 0; i < s.SamplesPerPixel(); ++i) {
            s.StartPixelSample(Point2i(p % 8, p / 8), i);
            Point2f u = s.GetPixel2D();
            s.Get1D();
            Point2f w = s.Get2D();
            sum += f(pixelDims ? u : w);
        }
        err += std::abs(sum / s.SamplesPerPixel() - ref);
    }
    return err / npixels;
}

TEST(Sampler, NewSamplersConvergeFasterThanIndependent) {
    double indep = MeanError(IndependentSampler(64, 1), true);
    for (Sampler s : NewSamplers(64))
        for (bool pixelDims : {true, false}) {
            double e = MeanError(s, pixelDims);
            // Independent error ~ sigma / 8 at 64 spp; stratified sets gain far more than 4.
            EXPECT_LT(e * 4, indep) << "sampler " << s.Index() << " pixel dims " << pixelDims
                                    << ": " << e << " vs " << indep;
        }
}

}  // namespace
}  // namespace kiln
