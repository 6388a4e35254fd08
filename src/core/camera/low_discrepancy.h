// Low-discrepancy building blocks for the samplers: Sobol' generator matrices, binary
// scramblers (random digit permutation, Owen, fast hash-based Owen), Kensler's hashed
// permutations and Morton codes (pbrt-v4 semantics).
#pragma once

#include <cstdint>
#include <span>

#include "base/rng.h"
#include "base/vecmath.h"

namespace kiln {

// Sobol' generator matrices
//
// NSobolDimensions dimensions of 32-bit columns; column i (i < SobolMatrixSize) is XORed in
// when bit i of the sample index is set. Dimension 0 is the van der Corput sequence; the rest
// are derived from Joe & Kuo's primitive polynomials and direction numbers (see the .cpp).
inline constexpr int NSobolDimensions = 64;
inline constexpr int SobolMatrixSize = 52;
// The SobolMatrixSize columns of dimension `dim` (0 <= dim < NSobolDimensions).
std::span<const uint32_t> SobolMatrix(int dim);

// Bit and index helpers
inline uint32_t ReverseBits32(uint32_t n) {
    n = (n << 16) | (n >> 16);
    n = ((n & 0x00ff00ff) << 8) | ((n & 0xff00ff00) >> 8);
    n = ((n & 0x0f0f0f0f) << 4) | ((n & 0xf0f0f0f0) >> 4);
    n = ((n & 0x33333333) << 2) | ((n & 0xcccccccc) >> 2);
    n = ((n & 0x55555555) << 1) | ((n & 0xaaaaaaaa) >> 1);
    return n;
}

// Spreads the low 32 bits of x to the even bit positions of the result.
inline uint64_t LeftShift2(uint64_t x) {
    x &= 0xffffffff;
    x = (x ^ (x << 16)) & 0x0000ffff0000ffffULL;
    x = (x ^ (x << 8)) & 0x00ff00ff00ff00ffULL;
    x = (x ^ (x << 4)) & 0x0f0f0f0f0f0f0f0fULL;
    x = (x ^ (x << 2)) & 0x3333333333333333ULL;
    x = (x ^ (x << 1)) & 0x5555555555555555ULL;
    return x;
}
// Morton (Z-order) code: x in the even bits, y in the odd bits.
inline uint64_t EncodeMorton2(uint32_t x, uint32_t y) {
    return (LeftShift2(y) << 1) | LeftShift2(x);
}

// v / 2^32 truncated to the 24 bits a float holds: exact, below 1, and never rounded up
// across a dyadic interval boundary.
inline Float FixedToFloat(uint32_t v) { return Float(v >> 8) * 0x1p-24f; }

inline bool IsPowerOf2(int v) { return v > 0 && !(v & (v - 1)); }
inline int Log2Int(uint64_t v) { return v ? 63 - __builtin_clzll(v) : -1; }
inline int RoundUpPow2(int v) {
    int p = 1;
    while (p < v) p <<= 1;
    return p;
}

// Element i of a pseudo-random permutation of [0, n) selected by seed (Kensler 2013,
// "Correlated Multi-Jittered Sampling"; cycle-walking hash).
int PermutationElement(uint32_t i, uint32_t n, uint32_t seed);

// All 24 permutations of the four base-4 digit values.
inline constexpr uint8_t kBase4Permutations[24][4] = {
    {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 2, 1}, {0, 3, 1, 2},
    {1, 0, 2, 3}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 2, 0}, {1, 3, 0, 2},
    {2, 1, 0, 3}, {2, 1, 3, 0}, {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 3, 0, 1}, {2, 3, 1, 0},
    {3, 1, 2, 0}, {3, 1, 0, 2}, {3, 2, 1, 0}, {3, 2, 0, 1}, {3, 0, 2, 1}, {3, 0, 1, 2}};

// Randomizers of a 32-bit binary fraction
enum class RandomizeStrategy { None, PermuteDigits, FastOwen, Owen };

struct NoRandomizer {
    uint32_t operator()(uint32_t v) const { return v; }
};
// Random digit permutation: XOR with a per-dimension constant.
struct BinaryPermuteScrambler {
    explicit BinaryPermuteScrambler(uint32_t perm) : permutation(perm) {}
    uint32_t operator()(uint32_t v) const { return permutation ^ v; }
    uint32_t permutation;
};
// Hash-based nested uniform (Owen) scrambling in one pass (Laine & Karras 2011, with the
// improved hash of Burley 2020, "Practical Hash-based Owen Scrambling"): operate on the
// bit-reversed value, where each bit may only be flipped by functions of lower bits.
struct FastOwenScrambler {
    explicit FastOwenScrambler(uint32_t seed) : seed(seed) {}
    uint32_t operator()(uint32_t v) const {
        v = ReverseBits32(v);
        v ^= v * 0x3d20adea;
        v += seed;
        v *= (seed >> 16) | 1;
        v ^= v * 0x05526c56;
        v ^= v * 0x53a22864;
        return ReverseBits32(v);
    }
    uint32_t seed;
};
// Exact Owen scrambling: bit b flips according to a hash of the more significant bits.
struct OwenScrambler {
    explicit OwenScrambler(uint32_t seed) : seed(seed) {}
    uint32_t operator()(uint32_t v) const {
        if (seed & 1) v ^= 1u << 31;
        for (int b = 1; b < 32; ++b) {
            uint32_t mask = (~0u) << (32 - b);
            if (uint32_t(MixBits((v & mask) ^ seed)) & (1u << b)) v ^= 1u << (31 - b);
        }
        return v;
    }
    uint32_t seed;
};

// Fast generator products for the dimensions the samplers use
namespace sobol_detail {
// Dimension 1's columns: its polynomial x + 1 with m_1 = 1 gives V_k = V_{k-1} ^ (V_{k-1} >> 1)
// in 64-bit fractions (the Pascal matrix mod 2); each column is the top 32 bits.
inline constexpr int kDim1Bytes = (SobolMatrixSize + 7) / 8;
struct Dim1Tables {
    uint32_t t[kDim1Bytes][256];  // XOR of the columns selected by each byte of the index
};
constexpr Dim1Tables MakeDim1Tables() {
    uint32_t col[8 * kDim1Bytes] = {};
    uint64_t v = uint64_t(1) << 63;
    for (int k = 0; k < SobolMatrixSize; ++k) {
        col[k] = uint32_t(v >> 32);
        v ^= v >> 1;
    }
    Dim1Tables tables{};
    for (int b = 0; b < kDim1Bytes; ++b)
        for (int x = 0; x < 256; ++x) {
            uint32_t r = 0;
            for (int i = 0; i < 8; ++i)
                if (x & (1 << i)) r ^= col[8 * b + i];
            tables.t[b][x] = r;
        }
    return tables;
}
inline constexpr Dim1Tables kDim1 = MakeDim1Tables();
}  // namespace sobol_detail

// The unrandomized 32-bit Sobol' value of sample `a` in dimension `dim` (generator matrix
// times index over GF(2)). Dimension 0 (van der Corput) is a bit reversal and dimension 1 a few
// table lookups, both exactly equal to the product with SobolMatrix(dim) (test
// LowDiscrepancy.FastSobolBitsMatchMatrices).
inline uint32_t SobolBits(uint64_t a, int dim) {
    if (dim == 0) return ReverseBits32(uint32_t(a));
    if (dim == 1) {
        const auto& t = sobol_detail::kDim1.t;
        uint32_t v =
            t[0][a & 255] ^ t[1][(a >> 8) & 255] ^ t[2][(a >> 16) & 255] ^ t[3][(a >> 24) & 255];
        if (a >> 32) [[unlikely]]
            for (int b = 4; b < sobol_detail::kDim1Bytes; ++b) v ^= t[b][(a >> (8 * b)) & 255];
        return v;
    }
    std::span<const uint32_t> c = SobolMatrix(dim);
    uint32_t v = 0;
    for (int i = 0; a != 0 && i < SobolMatrixSize; a >>= 1, ++i)
        if (a & 1) v ^= c[i];
    return v;
}

// Sample `a` of Sobol' dimension `dim`, randomized, as a float in [0, 1).
template <typename R>
inline Float SobolSample(uint64_t a, int dim, R randomizer) {
    uint32_t v = randomizer(SobolBits(a, dim));
    return std::min(Float(v) * 0x1p-32f, OneMinusEpsilon);
}

// Dispatches on strategy; hash is the randomizer's seed.
inline Float SobolSample(uint64_t a, int dim, RandomizeStrategy strategy, uint32_t hash) {
    switch (strategy) {
        case RandomizeStrategy::None:
            return SobolSample(a, dim, NoRandomizer());
        case RandomizeStrategy::PermuteDigits:
            return SobolSample(a, dim, BinaryPermuteScrambler(hash));
        case RandomizeStrategy::FastOwen:
            return SobolSample(a, dim, FastOwenScrambler(hash));
        case RandomizeStrategy::Owen:
        default:
            return SobolSample(a, dim, OwenScrambler(hash));
    }
}

}  // namespace kiln
