// Radical inverses in prime bases for the Halton sampler (pbrt-v4 semantics): the first
// kPrimeTableSize primes, the plain, digit-permuted and Owen-scrambled radical inverse, its
// inverse for pixel coordinates, and the seeded per-digit permutations.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

// The first kPrimeTableSize primes (2, 3, 5, ..., 7919), by a sieve of Eratosthenes.
inline constexpr int kPrimeTableSize = 1000;
std::span<const int> Primes();

// Sum over digits k >= 0 of d_k base^-(k+1), where a = sum d_k base^k and base =
// Primes()[baseIndex]: the van der Corput value of a in that base, in [0, 1).
Float RadicalInverse(int baseIndex, uint64_t a);

// The integer whose first nDigits base-`base` digits are those of `inverse` in reverse order:
// RadicalInverse(base, InverseRadicalInverse(v, base, n)) = v / base^n for v < base^n.
uint64_t InverseRadicalInverse(uint64_t inverse, int base, int nDigits);

// DigitPermutations: for every prime base and every digit position k that a float can
// resolve, a permutation of the digit values [0, base) chosen by the seed (pbrt-v4's
// DigitPermutation). Permutation (base, k, seed) is Kensler's hashed permutation
// (PermutationElement) with key Hash(base, k, seed). Positions k run while
// (base - 1) base^-(k+1) is still visible next to 1 in single precision, so trailing zero
// digits of an index are permuted too. The first kTabulatedBases bases are tabulated at
// construction (shared between copies); larger bases are computed when asked, with the same
// values.
class DigitPermutations {
  public:
    static constexpr int kTabulatedBases = 128;
    explicit DigitPermutations(uint32_t seed);
    // Number of permuted digit positions for base Primes()[baseIndex].
    static int NumDigits(int base);
    int Permute(int baseIndex, int digitIndex, int digitValue) const;
    uint32_t Seed() const { return seed; }

  private:
    uint32_t seed;
    // offsets[b] is where base index b's first permutation starts in table.
    std::shared_ptr<const std::vector<uint16_t>> table;
    std::shared_ptr<const std::vector<uint32_t>> offsets;
};

// The radical inverse with digit k of `a` (including the zero digits above its highest)
// replaced by its permutation perm.Permute(baseIndex, k, digit).
Float ScrambledRadicalInverse(int baseIndex, uint64_t a, const DigitPermutations& perm);

// Nested uniform (Owen) scrambling in base Primes()[baseIndex]: digit k is permuted by a
// permutation keyed by the hash and the already scrambled digits 0..k-1 (pbrt-v4's
// OwenScrambledRadicalInverse).
Float OwenScrambledRadicalInverse(int baseIndex, uint64_t a, uint32_t hash);

}  // namespace kiln
