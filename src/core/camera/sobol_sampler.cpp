// SobolSampler and the pixel-to-index mapping.
#include "core/camera/sobol_sampler.h"

#include <stdexcept>

#include "base/rng.h"

namespace kiln {

namespace {

// The first m bits of dimensions 0 and 1 for index a, packed as (x bits << m) | y bits.
uint64_t TopBits(uint64_t a, int m) {
    if (m == 0) return 0;
    uint64_t x = SobolBits(a, 0) >> (32 - m), y = SobolBits(a, 1) >> (32 - m);
    return (x << m) | y;
}

}  // namespace

SobolIntervalToIndex::SobolIntervalToIndex(int log2Scale) : m(log2Scale) {
    if (m < 0 || m > 20) throw std::invalid_argument("SobolIntervalToIndex: scale too large");
    int n = 2 * m;
    // Gauss-Jordan elimination on [M | I]: row r of M holds, for target bit r, which index
    // bits set it; reduce to [I | M^-1].
    std::array<uint64_t, 64> rows{}, inv{};
    for (int c = 0; c < n; ++c) {
        uint64_t col = TopBits(uint64_t(1) << c, m);
        for (int r = 0; r < n; ++r)
            if ((col >> r) & 1) rows[size_t(r)] |= uint64_t(1) << c;
    }
    for (int r = 0; r < n; ++r) inv[size_t(r)] = uint64_t(1) << r;
    for (int c = 0; c < n; ++c) {
        int pivot = c;
        while (pivot < n && !((rows[size_t(pivot)] >> c) & 1)) ++pivot;
        if (pivot == n) throw std::logic_error("Sobol' dimensions 0 and 1 are not a (0,2)-net");
        std::swap(rows[size_t(pivot)], rows[size_t(c)]);
        std::swap(inv[size_t(pivot)], inv[size_t(c)]);
        for (int r = 0; r < n; ++r)
            if (r != c && ((rows[size_t(r)] >> c) & 1)) {
                rows[size_t(r)] ^= rows[size_t(c)];
                inv[size_t(r)] ^= inv[size_t(c)];
            }
    }
    // Now j bit c = XOR over target bits r of inv[c] bit r: column r of M^-1 collects the j
    // bits that target bit r sets.
    for (int c = 0; c < n; ++c)
        for (int r = 0; r < n; ++r)
            if ((inv[size_t(c)] >> r) & 1) inverse[size_t(r)] |= uint64_t(1) << c;
    for (int c = 0; n + c < SobolMatrixSize && c < 64; ++c)
        frameColumns[size_t(c)] = TopBits(uint64_t(1) << (n + c), m);
}

uint64_t SobolIntervalToIndex::Index(uint64_t frame, Point2i p) const {
    if (m == 0) return frame;
    uint64_t target = (uint64_t(uint32_t(p.x)) << m) | uint64_t(uint32_t(p.y));
    for (int c = 0; frame >> c; ++c)
        if ((frame >> c) & 1) target ^= frameColumns[size_t(c)];
    uint64_t j = 0;
    for (int r = 0; target >> r; ++r)
        if ((target >> r) & 1) j ^= inverse[size_t(r)];
    return (frame << (2 * m)) | j;
}

SobolSampler::SobolSampler(int samplesPerPixel, Point2i fullResolution, RandomizeStrategy randomize,
                           int seed)
    : samplesPerPixel(samplesPerPixel),
      seed(seed),
      randomize(randomize),
      toIndex(Log2Int(uint64_t(RoundUpPow2(std::max({fullResolution.x, fullResolution.y, 1}))))) {}

Point2f SobolSampler::GetPixel2D() const {
    // The bits below the first m are the position inside the pixel.
    int m = toIndex.Log2Scale();
    uint32_t x = SobolBits(sobolIndex, 0) << m, y = SobolBits(sobolIndex, 1) << m;
    return {FixedToFloat(x), FixedToFloat(y)};
}

Float SobolSampler::SampleDimension(int d) const {
    if (randomize == RandomizeStrategy::None) return SobolSample(sobolIndex, d, NoRandomizer());
    uint32_t hash = uint32_t(Hash(d, seed));
    return SobolSample(sobolIndex, d, randomize, hash);
}

}  // namespace kiln
