// Sobol' generator matrices derived from primitive polynomials and initial direction numbers,
// and Kensler's hashed permutation.
#include "core/camera/low_discrepancy.h"

#include <array>
#include <vector>

namespace kiln {

namespace {

// Joe-Kuo direction numbers
//
// Source: S. Joe and F. Y. Kuo, "Constructing Sobol sequences with better two-dimensional
// projections", SIAM J. Sci. Comput. 30 (2008) 2635-2654; data file new-joe-kuo-6.21201
// (https://web.maths.unsw.edu.au/~fkuo/sobol/), rows d = 2..64. Each row: degree s of the
// primitive polynomial, its interior coefficients a (bit k-1 from the top is a_k) and the
// initial direction numbers m_1..m_s (odd, m_k < 2^k).
struct JoeKuoRow {
    int s;
    uint32_t a;
    std::array<uint32_t, 9> m;
};

constexpr JoeKuoRow kJoeKuo[] = {
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}},
    {5, 13, {1, 1, 1, 3, 11}},
    {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}},
    {6, 13, {1, 1, 1, 15, 21, 21}},
    {6, 16, {1, 3, 1, 13, 27, 49}},
    {6, 19, {1, 1, 1, 15, 7, 5}},
    {6, 22, {1, 3, 1, 15, 13, 25}},
    {6, 25, {1, 1, 5, 5, 19, 61}},
    {7, 1, {1, 3, 7, 11, 23, 15, 103}},
    {7, 4, {1, 3, 7, 13, 13, 15, 69}},
    {7, 7, {1, 1, 3, 13, 7, 35, 63}},
    {7, 8, {1, 3, 5, 9, 1, 25, 53}},
    {7, 14, {1, 3, 1, 13, 9, 35, 107}},
    {7, 19, {1, 3, 1, 5, 27, 61, 31}},
    {7, 21, {1, 1, 5, 11, 19, 41, 61}},
    {7, 28, {1, 3, 5, 3, 3, 13, 69}},
    {7, 31, {1, 1, 7, 13, 1, 19, 1}},
    {7, 32, {1, 3, 7, 5, 13, 19, 59}},
    {7, 37, {1, 1, 3, 9, 25, 29, 41}},
    {7, 41, {1, 3, 5, 13, 23, 1, 55}},
    {7, 42, {1, 3, 7, 3, 13, 59, 17}},
    {7, 50, {1, 3, 1, 3, 5, 53, 69}},
    {7, 55, {1, 1, 5, 5, 23, 33, 13}},
    {7, 56, {1, 1, 7, 7, 1, 61, 123}},
    {7, 59, {1, 1, 7, 9, 13, 61, 49}},
    {7, 62, {1, 3, 3, 5, 3, 55, 33}},
    {8, 14, {1, 3, 1, 15, 31, 13, 49, 245}},
    {8, 21, {1, 3, 5, 15, 31, 59, 63, 97}},
    {8, 22, {1, 3, 1, 11, 11, 11, 77, 249}},
    {8, 38, {1, 3, 1, 11, 27, 43, 71, 9}},
    {8, 47, {1, 1, 7, 15, 21, 11, 81, 45}},
    {8, 49, {1, 3, 7, 3, 25, 31, 65, 79}},
    {8, 50, {1, 3, 1, 1, 19, 11, 3, 205}},
    {8, 52, {1, 1, 5, 9, 19, 21, 29, 157}},
    {8, 56, {1, 3, 7, 11, 1, 33, 89, 185}},
    {8, 67, {1, 3, 3, 3, 15, 9, 79, 71}},
    {8, 70, {1, 3, 7, 11, 15, 39, 119, 27}},
    {8, 84, {1, 1, 3, 1, 11, 31, 97, 225}},
    {8, 97, {1, 1, 1, 3, 23, 43, 57, 177}},
    {8, 103, {1, 3, 7, 7, 17, 17, 37, 71}},
    {8, 115, {1, 3, 1, 5, 27, 63, 123, 213}},
    {8, 122, {1, 1, 3, 5, 11, 43, 53, 133}},
    {9, 8, {1, 3, 5, 5, 29, 17, 47, 173, 479}},
    {9, 13, {1, 3, 3, 11, 3, 1, 109, 9, 69}},
    {9, 16, {1, 1, 1, 5, 17, 39, 23, 5, 343}},
    {9, 22, {1, 3, 1, 5, 25, 15, 31, 103, 499}},
    {9, 25, {1, 1, 1, 11, 11, 17, 63, 105, 183}},
    {9, 44, {1, 1, 5, 11, 9, 29, 97, 231, 363}},
    {9, 47, {1, 1, 5, 15, 19, 45, 41, 7, 383}},
    {9, 52, {1, 3, 7, 7, 31, 19, 83, 137, 221}},
    {9, 55, {1, 1, 1, 3, 23, 15, 111, 223, 83}},
    {9, 59, {1, 1, 5, 13, 31, 15, 55, 25, 161}},
    {9, 62, {1, 1, 3, 13, 25, 47, 39, 87, 257}},
};
static_assert(std::size(kJoeKuo) == NSobolDimensions - 1);

// Direction numbers V_k = m_k / 2^k as 64-bit fractions, extended by Bratley & Fox's
// recurrence V_k = V_{k-s} ^ (V_{k-s} >> s) ^ XOR_{j<s, a_j set} V_{k-j}; each 32-bit column is
// the top half (the bits a float sample can use).
std::vector<uint32_t> ComputeSobolMatrices() {
    std::vector<uint32_t> c(size_t(NSobolDimensions) * SobolMatrixSize);
    for (int k = 0; k < SobolMatrixSize; ++k)
        c[k] = k < 32 ? (1u << (31 - k)) : 0;  // van der Corput
    for (int d = 1; d < NSobolDimensions; ++d) {
        const JoeKuoRow& row = kJoeKuo[d - 1];
        int s = row.s;
        uint64_t v[SobolMatrixSize + 1];  // 1-based
        for (int k = 1; k <= SobolMatrixSize; ++k) {
            if (k <= s) {
                v[k] = uint64_t(row.m[k - 1]) << (64 - k);
            } else {
                v[k] = v[k - s] ^ (v[k - s] >> s);
                for (int j = 1; j < s; ++j)
                    if ((row.a >> (s - 1 - j)) & 1) v[k] ^= v[k - j];
            }
            c[size_t(d) * SobolMatrixSize + k - 1] = uint32_t(v[k] >> 32);
        }
    }
    return c;
}

}  // namespace

std::span<const uint32_t> SobolMatrix(int dim) {
    static const std::vector<uint32_t> matrices = ComputeSobolMatrices();
    return std::span<const uint32_t>(matrices).subspan(size_t(dim) * SobolMatrixSize,
                                                       SobolMatrixSize);
}

int PermutationElement(uint32_t i, uint32_t l, uint32_t p) {
    uint32_t w = l - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= p;
        i *= 0xe170893d;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3f;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1 | p >> 27;
        i *= 0x6935fa69;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3;
        i ^= (i & w) >> 2;
        i *= 0xc860a3df;
        i &= w;
        i ^= i >> 5;
    } while (i >= l);
    return int((i + p) % l);
}

}  // namespace kiln
