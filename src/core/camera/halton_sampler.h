// HaltonSampler (pbrt-v4): the Halton sequence with one global index per (pixel, sample).
#pragma once

#include "base/vecmath.h"
#include "core/camera/low_discrepancy.h"
#include "core/camera/radical_inverse.h"

namespace kiln {

// Dimension d >= 2 of a sample is the radical inverse of its global index in base Primes()[d]
// (dimensions wrap back to 2 after the 1000 primes, as pbrt-v4). Dimensions 0 and 1 (bases 2
// and 3) place the samples on the film: the image's first min(res, 128) columns and rows are
// covered by 2^e0 and 3^e1 strata, and the index of a pixel's i-th sample is the i-th integer
// whose low base-2 digits (reversed) give the pixel's column and whose low base-3 digits give
// its row modulo those scales (Chinese remainder theorem with the two multiplicative
// inverses); GetPixel2D is the remaining digits' radical inverse, the position inside the pixel.
// Randomization: None, PermuteDigits (seeded digit permutations, pbrt-v4's default) or Owen
// (per-dimension nested scrambling); pixel positions are never randomized (pbrt-v4).
class HaltonSampler {
  public:
    static constexpr int kMaxResolution = 128;
    HaltonSampler(int samplesPerPixel, Point2i fullResolution,
                  RandomizeStrategy randomize = RandomizeStrategy::PermuteDigits, int seed = 0);
    int SamplesPerPixel() const { return samplesPerPixel; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int sampleIndex, int dim);
    Float Get1D() {
        if (dimension >= kPrimeTableSize) dimension = 2;
        return SampleDimension(dimension++);
    }
    Point2f Get2D() {
        if (dimension + 1 >= kPrimeTableSize) dimension = 2;
        int d = dimension;
        dimension += 2;
        return {SampleDimension(d), SampleDimension(d + 1)};
    }
    Point2f GetPixel2D() {
        return {RadicalInverse(0, uint64_t(haltonIndex) >> baseExponents[0]),
                RadicalInverse(1, uint64_t(haltonIndex) / uint64_t(baseScales[1]))};
    }
    // The global Halton index of the current sample.
    int64_t HaltonIndex() const { return haltonIndex; }
    // 2^e0 and 3^e1: the pixel strata of dimensions 0 and 1.
    Point2i BaseScales() const { return baseScales; }

  private:
    Float SampleDimension(int d) const;

    int samplesPerPixel, seed;
    RandomizeStrategy randomize;
    DigitPermutations permutations;
    Point2i baseScales, baseExponents;
    int64_t multInverse[2];
    int64_t haltonIndex = 0;
    int dimension = 0;
};

}  // namespace kiln
