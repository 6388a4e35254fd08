// PMJ02BNSampler (pbrt-v4): pixel samples and 2D samples from tables of pmj02 sequences.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "base/rng.h"
#include "base/vecmath.h"
#include "core/camera/low_discrepancy.h"
#include "core/camera/pmj02.h"

namespace kiln {

// Pixel positions: the 65536 points of table set 0 are spread over a tile of T x T pixels,
// T = 2^(8 - log4(spp rounded up to a power of 4)); pixel p (modulo the tile) takes, in
// sequence order, the first spp points that fall in its square (a (0,2)-net per pixel for a
// power-of-4 spp). 2D dimensions d, d + 1 use table set d / 2 at the sample number itself
// (sets 0-4; later ones at a per-pixel permutation of it, wrapping the sets), 1D dimension d
// the stratum (permuted sample number + offset) / spp; every value is then shifted modulo 1
// by a per-pixel offset (Cranley-Patterson rotation). pbrt-v4 reads those offsets from its 48
// blue-noise textures (and ignores the seed there). kiln's offset for dimension d comes from
// the pixel's Morton index within its 256 x 256 tile: each base-4 digit permuted by one of the
// 24 permutations chosen by a hash of the digits above it (the pixel block), d, the seed and
// the tile, then bit-reversed, with hashed low bits. In every aligned 2^k x 2^k block of
// pixels a dimension's offsets fall in distinct intervals of length 4^-k (neighbouring
// pixels' errors decorrelate, as zsobol orders them), while different dimensions pair up
// differently in every block, so across pixels they are independent. A spp that is not a power of 4
// warns at creation and is used as given (pbrt-v4); at most kPMJ02Samples.
class PMJ02BNSampler {
  public:
    PMJ02BNSampler(int samplesPerPixel, int seed = 0);
    int SamplesPerPixel() const { return samplesPerPixel; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int index, int dim) {
        if (p != pixel) {
            // New pixel: forget the cached offsets.
            if (++generation == 0) {
                cacheGeneration.fill(0);
                generation = 1;
            }
        }
        pixel = p;
        sampleIndex = index;
        dimension = std::max(2, dim);
    }
    Float Get1D() {
        uint64_t hash = DimensionHash(dimension);
        int index =
            PermutationElement(uint32_t(sampleIndex), uint32_t(samplesPerPixel), uint32_t(hash));
        Float delta = PixelOffset(dimension);
        ++dimension;
        return std::min((index + delta) / samplesPerPixel, OneMinusEpsilon);
    }
    Point2f Get2D();
    Point2f GetPixel2D() const {
        // The tile side is a power of two: the low bits are the position in the tile.
        int px = pixel.x & (tileSize - 1), py = pixel.y & (tileSize - 1);
        return (*pixelSamples)[size_t((px + py * tileSize) * samplesPerPixel + sampleIndex)];
    }
    int TileSize() const { return tileSize; }
    // The rotation of dimension d in the current pixel.
    Float PixelOffset(int d) const;

  private:
    // The key of the sample-number permutation of dimension d (1D, and 2D beyond the tables).
    uint64_t DimensionHash(int d) const { return Hash(pixel.x, pixel.y, d, seed); }

    Float ComputePixelOffset(int d) const;

    int samplesPerPixel, seed, tileSize;
    std::shared_ptr<const std::vector<Point2f>> pixelSamples;
    Point2i pixel{-1, -1};
    int sampleIndex = 0, dimension = 0;
    // The offsets depend on the pixel and dimension only: cached for the first dimensions of
    // the pixel being sampled (consecutive samples of a pixel reuse them). Pure memoisation:
    // values are identical with or without it.
    static constexpr int kCachedDimensions = 64;
    uint32_t generation = 1;  // of pixel; a cache entry is valid if its generation matches
    mutable std::array<uint32_t, kCachedDimensions> cacheGeneration{};
    mutable std::array<Float, kCachedDimensions> cachedOffset{};
};

}  // namespace kiln
