// Sample generators (pbrt-v4 samplers): independent, stratified, padded Sobol' and
// Morton-ordered ("z") Sobol'.
//
// Each is a small value type; every rendering thread owns a copy. Values depend only on
// (pixel, sample index, dimension, seed), never on call order across pixels or threads:
// StartPixelSample(p, i, d) fully resets the stream. Get1D/Get2D/GetPixel2D return values in
// [0, 1) and advance the dimension by 1 or 2.
#pragma once

#include <array>

#include "base/rng.h"
#include "base/vecmath.h"
#include "core/camera/low_discrepancy.h"

namespace kiln {

// IndependentSampler: uniform random values from a PCG32 stream per (pixel, seed).
class IndependentSampler {
  public:
    IndependentSampler(int samplesPerPixel, int seed = 0)
        : samplesPerPixel(samplesPerPixel), seed(seed) {}
    int SamplesPerPixel() const { return samplesPerPixel; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int sampleIndex, int dimension) {
        rng.SetSequence(Hash(p.x, p.y, seed));
        rng.Advance(int64_t(sampleIndex) * 65536 + dimension);
    }
    Float Get1D() { return rng.UniformFloat(); }
    Point2f Get2D() {
        Float x = rng.UniformFloat();
        return {x, rng.UniformFloat()};
    }
    Point2f GetPixel2D() { return Get2D(); }

  private:
    int samplesPerPixel, seed;
    RNG rng;
};

// StratifiedSampler: xPixelSamples x yPixelSamples strata, visited in a hashed order that
// differs per pixel and dimension (padding), optionally jittered within each stratum.
class StratifiedSampler {
  public:
    StratifiedSampler(int xPixelSamples, int yPixelSamples, bool jitter, int seed = 0)
        : xPixelSamples(xPixelSamples), yPixelSamples(yPixelSamples), seed(seed), jitter(jitter) {}
    int SamplesPerPixel() const { return xPixelSamples * yPixelSamples; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int index, int dim) {
        pixel = p;
        sampleIndex = index;
        dimension = dim;
        rng.SetSequence(Hash(p.x, p.y, seed));
        rng.Advance(int64_t(sampleIndex) * 65536 + dimension);
    }
    Float Get1D();
    Point2f Get2D();
    Point2f GetPixel2D() { return Get2D(); }

  private:
    uint64_t DimensionHash() const;
    int xPixelSamples, yPixelSamples, seed;
    bool jitter;
    RNG rng;
    Point2i pixel;
    int sampleIndex = 0, dimension = 0;
};

// PaddedSobolSampler: the first two Sobol' dimensions, with the sample index permuted
// independently per pixel and dimension and each value scrambled.
class PaddedSobolSampler {
  public:
    PaddedSobolSampler(int samplesPerPixel, RandomizeStrategy randomize, int seed = 0)
        : samplesPerPixel(samplesPerPixel), seed(seed), randomize(randomize) {}
    int SamplesPerPixel() const { return samplesPerPixel; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int index, int dim) {
        pixel = p;
        sampleIndex = index;
        dimension = dim;
    }
    Float Get1D();
    Point2f Get2D();
    Point2f GetPixel2D() { return Get2D(); }

  private:
    uint64_t DimensionHash() const;
    int samplesPerPixel, seed;
    RandomizeStrategy randomize;
    Point2i pixel;
    int sampleIndex = 0, dimension = 0;
};

// ZSobolSampler (Ahmed & Wonka 2020, "Screen-Space Blue-Noise Diffusion of Monte Carlo
// Sampling Error via Hierarchical Ordering of Pixels", as in pbrt-v4): one global (0,2)
// Sobol' sequence indexed by the Morton code of the pixel followed by the sample index, with
// base-4 digits permuted per dimension, so each pixel's spp samples form a (0,m,2)-net in
// every dimension pair while neighbouring pixels' errors decorrelate.
class ZSobolSampler {
  public:
    ZSobolSampler(int samplesPerPixel, Point2i fullResolution, RandomizeStrategy randomize,
                  int seed = 0);
    // Rounded up to a power of two.
    int SamplesPerPixel() const { return 1 << log2SamplesPerPixel; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int index, int dim) {
        dimension = dim;
        uint64_t pixelMorton = EncodeMorton2(uint32_t(p.x), uint32_t(p.y));
        if (pixelMorton != cachedPixel) {
            // New pixel: forget the cached high digits.
            cachedPixel = pixelMorton;
            if (++generation == 0) {
                cacheGeneration.fill(0);
                generation = 1;
            }
        }
        mortonIndex = (pixelMorton << log2SamplesPerPixel) | uint64_t(index);
    }
    Float Get1D();
    Point2f Get2D();
    Point2f GetPixel2D() { return Get2D(); }
    // The Sobol' index of the current sample in the current dimension.
    uint64_t GetSampleIndex() const;

  private:
    // Permuted base-4 digits of the sample index from digit firstDigit up; each depends on
    // the digits above it and the dimension only.
    uint64_t PermutedDigits(int firstDigit, int lastDigit) const;

    RandomizeStrategy randomize;
    int seed, log2SamplesPerPixel, nBase4Digits;
    uint64_t mortonIndex = 0;
    int dimension = 0;
    // The digits above the sample-number digits depend only on the pixel and the dimension:
    // they are cached per dimension for the pixel being sampled (consecutive samples of a
    // pixel reuse them). Those above the pixel's lowest digit depend only on its 2x2 block
    // (Morton order): cached per dimension for the last block, they survive the move to the
    // next pixel of the block and to the next wave of samples (a pixel's samples come in
    // waves of 1, 2, 4, ...). Pure memoisation: values are identical with or without it.
    static constexpr int kCachedDimensions = 64;
    uint64_t cachedPixel = ~uint64_t(0);
    uint32_t generation = 1;  // of cachedPixel; a cache entry is valid if its generation matches
    mutable std::array<uint32_t, kCachedDimensions> cacheGeneration{};
    mutable std::array<uint64_t, kCachedDimensions> cachedHighDigits{};
    mutable std::array<uint64_t, kCachedDimensions> blockKey = MakeEmptyBlockKeys();
    mutable std::array<uint64_t, kCachedDimensions> blockDigits{};
    static std::array<uint64_t, kCachedDimensions> MakeEmptyBlockKeys() {
        std::array<uint64_t, kCachedDimensions> keys;
        keys.fill(~uint64_t(0));  // no block: a key is mortonIndex shifted right at least 2 bits
        return keys;
    }
};

}  // namespace kiln
