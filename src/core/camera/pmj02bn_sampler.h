// PMJ02BNSampler (pbrt-v4): pixel samples and 2D samples from tables of pmj02 sequences.
#pragma once

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
// by per-pixel offsets (Cranley-Patterson rotation). pbrt-v4 reads those offsets from its 48
// blue-noise textures and ignores the seed there; kiln draws them from a hash of pixel,
// dimension and seed (white noise across pixels). A spp that is not a power of 4 warns at
// creation and is used as given (pbrt-v4); at most kPMJ02Samples.
class PMJ02BNSampler {
  public:
    PMJ02BNSampler(int samplesPerPixel, int seed = 0);
    int SamplesPerPixel() const { return samplesPerPixel; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int index, int dim) {
        pixel = p;
        sampleIndex = index;
        dimension = std::max(2, dim);
    }
    Float Get1D() {
        uint64_t hash = DimensionHash(dimension);
        int index =
            PermutationElement(uint32_t(sampleIndex), uint32_t(samplesPerPixel), uint32_t(hash));
        Float delta = Offset(hash);
        ++dimension;
        return std::min((index + delta) / samplesPerPixel, OneMinusEpsilon);
    }
    Point2f Get2D();
    Point2f GetPixel2D() const {
        int px = pixel.x % tileSize, py = pixel.y % tileSize;
        return (*pixelSamples)[size_t((px + py * tileSize) * samplesPerPixel + sampleIndex)];
    }
    int TileSize() const { return tileSize; }

  private:
    uint64_t DimensionHash(int d) const { return Hash(pixel.x, pixel.y, d, seed); }
    // The rotation for a dimension: the hash's upper 32 bits as a fraction.
    static Float Offset(uint64_t hash) { return Float(uint32_t(hash >> 32)) * 0x1p-32f; }

    int samplesPerPixel, seed, tileSize;
    std::shared_ptr<const std::vector<Point2f>> pixelSamples;
    Point2i pixel;
    int sampleIndex = 0, dimension = 0;
};

}  // namespace kiln
