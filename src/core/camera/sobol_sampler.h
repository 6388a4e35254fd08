// SobolSampler (pbrt-v4): one global Sobol' sequence over the whole image.
#pragma once

#include <algorithm>
#include <array>

#include "base/vecmath.h"
#include "core/camera/low_discrepancy.h"

namespace kiln {

// SobolIntervalToIndex: dimensions 0 and 1 of the Sobol' sequence form a (0,2)-sequence, so
// every aligned block of 4^m consecutive indices puts exactly one point in each of the
// 2^m x 2^m squares of side 2^-m. Index(frame, p) is the index of block `frame` whose point
// lies in square p: its low 2m bits j solve, over GF(2), M j = (p.x, p.y) + F frame, where M
// maps j to the first m bits of dimensions 0 and 1 and F gives the frame bits' contribution
// to those same bits. M^-1 and F's columns are computed once per m.
class SobolIntervalToIndex {
  public:
    explicit SobolIntervalToIndex(int log2Scale);
    int Log2Scale() const { return m; }
    uint64_t Index(uint64_t frame, Point2i p) const;

  private:
    int m;
    // Column k of M^-1: the j for target bit k (bits 0..m-1: y's first m bits, lowest =
    // least significant; bits m..2m-1: x's).
    std::array<uint64_t, 64> inverse{};
    // Column c of F: the target bits that index bit 2m + c sets.
    std::array<uint64_t, 64> frameColumns{};
};

// The sample of pixel p with number i is the i-th point of the global sequence (image scaled
// to the smallest power-of-two square holding it) that lands in p; GetPixel2D is its position
// inside the pixel (unrandomized, as pbrt-v4). Dimensions d >= 2 are randomized with a hash of
// (d, seed); after the last Sobol' dimension (NSobolDimensions = 64; pbrt-v4 has 1024) they
// wrap back to 2, as pbrt-v4 does.
class SobolSampler {
  public:
    SobolSampler(int samplesPerPixel, Point2i fullResolution, RandomizeStrategy randomize,
                 int seed = 0);
    int SamplesPerPixel() const { return samplesPerPixel; }
    int Seed() const { return seed; }
    void StartPixelSample(Point2i p, int sampleIndex, int dim) {
        pixel = p;
        dimension = std::max(2, dim);
        sobolIndex = toIndex.Index(uint64_t(sampleIndex), p);
    }
    Float Get1D() {
        if (dimension >= NSobolDimensions) dimension = 2;
        return SampleDimension(dimension++);
    }
    Point2f Get2D() {
        if (dimension + 1 >= NSobolDimensions) dimension = 2;
        Point2f u(SampleDimension(dimension), SampleDimension(dimension + 1));
        dimension += 2;
        return u;
    }
    Point2f GetPixel2D() const;
    uint64_t SobolIndex() const { return sobolIndex; }
    int Scale() const { return 1 << toIndex.Log2Scale(); }

  private:
    Float SampleDimension(int d) const;

    int samplesPerPixel, seed;
    RandomizeStrategy randomize;
    SobolIntervalToIndex toIndex;
    Point2i pixel;
    int dimension = 0;
    uint64_t sobolIndex = 0;
};

}  // namespace kiln
