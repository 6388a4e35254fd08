// HaltonSampler implementation.
#include "core/camera/halton_sampler.h"

#include <algorithm>

#include "base/rng.h"

namespace kiln {

namespace {

// x with a x = 1 (mod n), for coprime a and n >= 1 (extended Euclid).
int64_t MultiplicativeInverse(int64_t a, int64_t n) {
    int64_t r0 = n, r1 = a % n, s0 = 0, s1 = 1;
    while (r1 != 0) {
        int64_t q = r0 / r1;
        std::swap(r0, r1);
        r1 -= q * r0;
        std::swap(s0, s1);
        s1 -= q * s0;
    }
    return ((s0 % n) + n) % n;
}

int64_t Mod(int64_t a, int64_t n) { return ((a % n) + n) % n; }

}  // namespace

HaltonSampler::HaltonSampler(int samplesPerPixel, Point2i fullResolution,
                             RandomizeStrategy randomize, int seed)
    : samplesPerPixel(samplesPerPixel),
      seed(seed),
      randomize(randomize),
      permutations(uint32_t(seed)) {
    // The smallest powers of 2 and 3 covering the image's first 128 columns and rows.
    for (int i = 0; i < 2; ++i) {
        int base = i == 0 ? 2 : 3, scale = 1, exponent = 0;
        while (scale < std::min(fullResolution[i], kMaxResolution)) {
            scale *= base;
            ++exponent;
        }
        baseScales[i] = scale;
        baseExponents[i] = exponent;
    }
    multInverse[0] = MultiplicativeInverse(baseScales[1], baseScales[0]);
    multInverse[1] = MultiplicativeInverse(baseScales[0], baseScales[1]);
}

void HaltonSampler::StartPixelSample(Point2i p, int sampleIndex, int dim) {
    int64_t stride = int64_t(baseScales[0]) * baseScales[1];
    haltonIndex = 0;
    if (stride > 1) {
        // The index modulo 2^e0 whose reversed base-2 digits are the column, and modulo 3^e1
        // whose reversed base-3 digits are the row; combined modulo their product.
        for (int i = 0; i < 2; ++i) {
            int64_t pm = Mod(p[i], kMaxResolution);
            int64_t offset =
                int64_t(InverseRadicalInverse(uint64_t(pm), i == 0 ? 2 : 3, baseExponents[i]));
            haltonIndex += offset * (stride / baseScales[i]) * multInverse[i];
        }
        haltonIndex %= stride;
    }
    haltonIndex += int64_t(sampleIndex) * stride;
    dimension = std::max(2, dim);
}

Float HaltonSampler::SampleDimension(int d) const {
    switch (randomize) {
        case RandomizeStrategy::None:
            return RadicalInverse(d, uint64_t(haltonIndex));
        case RandomizeStrategy::Owen:
            // pbrt-v4 keys the scrambling by the dimension alone; kiln adds the seed.
            return OwenScrambledRadicalInverse(
                d, uint64_t(haltonIndex),
                uint32_t(MixBits(1 + (uint64_t(d) << 4)) ^ MixBits(uint64_t(uint32_t(seed)))));
        default:
            return ScrambledRadicalInverse(d, uint64_t(haltonIndex), permutations);
    }
}

}  // namespace kiln
