// Prime table, radical inverses and seeded digit permutations.
#include "core/camera/radical_inverse.h"

#include <algorithm>

#include "base/rng.h"
#include "core/camera/low_discrepancy.h"

namespace kiln {

namespace {

std::vector<int> SievePrimes(int count) {
    // The 1000th prime is 7919; sieve up to a bound that holds count primes.
    int limit = 8000;
    std::vector<int> primes;
    while (true) {
        std::vector<bool> composite(size_t(limit) + 1, false);
        primes.clear();
        for (int i = 2; i <= limit && int(primes.size()) < count; ++i) {
            if (composite[size_t(i)]) continue;
            primes.push_back(i);
            for (int64_t j = int64_t(i) * i; j <= limit; j += i) composite[size_t(j)] = true;
        }
        if (int(primes.size()) == count) return primes;
        limit *= 2;
    }
}

// Accumulates reversed digits while the next digit cannot overflow 64 bits; returns the value
// reversedDigits * base^-nDigits as a float below 1.
Float ToUnit(uint64_t reversedDigits, double invBaseM) {
    return std::min(Float(double(reversedDigits) * invBaseM), OneMinusEpsilon);
}

uint16_t PermuteDigit(int base, int digitIndex, uint32_t seed, int digitValue) {
    uint32_t key = uint32_t(Hash(base, digitIndex, seed));
    return uint16_t(PermutationElement(uint32_t(digitValue), uint32_t(base), key));
}

}  // namespace

std::span<const int> Primes() {
    static const std::vector<int> primes = SievePrimes(kPrimeTableSize);
    return primes;
}

Float RadicalInverse(int baseIndex, uint64_t a) {
    uint64_t base = uint64_t(Primes()[size_t(baseIndex)]);
    uint64_t limit = ~uint64_t(0) / base - base;
    double invBase = 1.0 / double(base), invBaseM = 1;
    uint64_t reversedDigits = 0;
    while (a && reversedDigits < limit) {
        uint64_t next = a / base;
        reversedDigits = reversedDigits * base + (a - next * base);
        invBaseM *= invBase;
        a = next;
    }
    return ToUnit(reversedDigits, invBaseM);
}

uint64_t InverseRadicalInverse(uint64_t inverse, int base, int nDigits) {
    uint64_t index = 0;
    for (int i = 0; i < nDigits; ++i) {
        index = index * uint64_t(base) + inverse % uint64_t(base);
        inverse /= uint64_t(base);
    }
    return index;
}

int DigitPermutations::NumDigits(int base) {
    // Digits whose largest contribution (base - 1) base^-(k+1) still changes 1 - it in float.
    int n = 0;
    Float invBase = Float(1) / Float(base), invBaseM = 1;
    while (1 - Float(base - 1) * invBaseM < 1) {
        ++n;
        invBaseM *= invBase;
    }
    return n;
}

DigitPermutations::DigitPermutations(uint32_t seed) : seed(seed) {
    std::span<const int> primes = Primes();
    auto offs = std::make_shared<std::vector<uint32_t>>(kTabulatedBases + 1, 0);
    for (int b = 0; b < kTabulatedBases; ++b)
        (*offs)[size_t(b) + 1] =
            (*offs)[size_t(b)] + uint32_t(NumDigits(primes[size_t(b)]) * primes[size_t(b)]);
    auto tab = std::make_shared<std::vector<uint16_t>>(offs->back());
    for (int b = 0; b < kTabulatedBases; ++b) {
        int base = primes[size_t(b)], nDigits = NumDigits(base);
        uint16_t* perm = tab->data() + (*offs)[size_t(b)];
        for (int k = 0; k < nDigits; ++k)
            for (int d = 0; d < base; ++d) perm[k * base + d] = PermuteDigit(base, k, seed, d);
    }
    table = std::move(tab);
    offsets = std::move(offs);
}

int DigitPermutations::Permute(int baseIndex, int digitIndex, int digitValue) const {
    int base = Primes()[size_t(baseIndex)];
    if (baseIndex < kTabulatedBases)
        return (*table)[(*offsets)[size_t(baseIndex)] + size_t(digitIndex * base + digitValue)];
    return PermuteDigit(base, digitIndex, seed, digitValue);
}

Float ScrambledRadicalInverse(int baseIndex, uint64_t a, const DigitPermutations& perm) {
    int base = Primes()[size_t(baseIndex)];
    uint64_t limit = ~uint64_t(0) / uint64_t(base) - uint64_t(base);
    double invBase = 1.0 / base, invBaseM = 1;
    uint64_t reversedDigits = 0;
    int nDigits = DigitPermutations::NumDigits(base);
    for (int k = 0; k < nDigits && reversedDigits < limit; ++k) {
        uint64_t next = a / uint64_t(base);
        int digit = int(a - next * uint64_t(base));
        reversedDigits =
            reversedDigits * uint64_t(base) + uint64_t(perm.Permute(baseIndex, k, digit));
        invBaseM *= invBase;
        a = next;
    }
    return ToUnit(reversedDigits, invBaseM);
}

Float OwenScrambledRadicalInverse(int baseIndex, uint64_t a, uint32_t hash) {
    int base = Primes()[size_t(baseIndex)];
    uint64_t limit = ~uint64_t(0) / uint64_t(base) - uint64_t(base);
    double invBase = 1.0 / base;
    uint64_t reversedDigits = 0;
    // Scramble digits until base^-k is below single-precision resolution of 1.
    Float invBaseMf = 1;
    double invBaseM = 1;
    while (1 - invBaseMf < 1 && reversedDigits < limit) {
        uint64_t next = a / uint64_t(base);
        int digit = int(a - next * uint64_t(base));
        // The permutation of this digit depends on the scrambled digits before it.
        uint32_t digitHash = uint32_t(MixBits(uint64_t(hash) ^ reversedDigits));
        digit = PermutationElement(uint32_t(digit), uint32_t(base), digitHash);
        reversedDigits = reversedDigits * uint64_t(base) + uint64_t(digit);
        invBaseM *= invBase;
        invBaseMf *= Float(invBase);
        a = next;
    }
    return ToUnit(reversedDigits, invBaseM);
}

}  // namespace kiln
