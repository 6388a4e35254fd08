// Random numbers and hashing: PCG32 (O'Neill 2014) and 64-bit mixing for deterministic,
// per-pixel sample streams that do not depend on thread scheduling.
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

#include "base/vecmath.h"

namespace kiln {

// 64-bit finaliser (Stafford's variant 13 of MurmurHash3's fmix64).
inline uint64_t MixBits(uint64_t v) {
    v ^= (v >> 31);
    v *= 0x7fb5d329728ea185ULL;
    v ^= (v >> 27);
    v *= 0x81dadef4bc2dd44dULL;
    v ^= (v >> 33);
    return v;
}

// Hashes any number of trivially copyable values into 64 bits.
inline uint64_t HashBytes(const void* data, size_t n, uint64_t seed = 0) {
    // FNV-1a over the bytes, then mixed.
    uint64_t h = 0xcbf29ce484222325ULL ^ MixBits(seed + 0x9e3779b97f4a7c15ULL);
    auto p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ULL;
    }
    return MixBits(h);
}
// A 64-bit hash of many bytes (files, images): four independent multiply-rotate lanes over
// 8-byte words, the tail through HashBytes. HashBytes (FNV-1a) makes one dependent multiply per
// byte, several times slower on gigabytes.
inline uint64_t HashLargeBytes(const void* data, size_t n, uint64_t seed = 0) {
    auto p = static_cast<const unsigned char*>(data);
    uint64_t lane[4] = {seed ^ 0x9e3779b97f4a7c15ULL, seed + 0x632be59bd9b4e019ULL,
                        seed ^ 0x85ebca77c2b2ae63ULL, seed - 0xc2b2ae3d27d4eb4fULL};
    auto round = [](uint64_t h, uint64_t w) {
        h ^= w * 0x87c37b91114253d5ULL;
        h = (h << 31) | (h >> 33);
        return h * 0x4cf5ad432745937fULL;
    };
    size_t i = 0;
    for (; i + 32 <= n; i += 32)
        for (int k = 0; k < 4; ++k) {
            uint64_t w;
            std::memcpy(&w, p + i + 8 * k, 8);
            lane[k] = round(lane[k], w);
        }
    uint64_t h = MixBits(lane[0]) ^ MixBits(lane[1] + 1) ^ MixBits(lane[2] + 2) ^
                 MixBits(lane[3] + 3) ^ uint64_t(n);
    return HashBytes(p + i, n - i, h);
}
template <typename... Args>
inline uint64_t Hash(Args... args) {
    uint64_t h = 0x243f6a8885a308d3ULL;
    ((h = HashBytes(&args, sizeof(args), h)), ...);
    return h;
}
inline uint64_t HashString(std::string_view s) { return HashBytes(s.data(), s.size()); }

class RNG {
  public:
    RNG() = default;
    RNG(uint64_t seqIndex, uint64_t offset) { SetSequence(seqIndex, offset); }
    explicit RNG(uint64_t seqIndex) { SetSequence(seqIndex, MixBits(seqIndex)); }

    void SetSequence(uint64_t seqIndex, uint64_t offset) {
        state = 0u;
        inc = (seqIndex << 1u) | 1u;
        Uniform32();
        state += offset;
        Uniform32();
    }
    void SetSequence(uint64_t seqIndex) { SetSequence(seqIndex, MixBits(seqIndex)); }

    uint32_t Uniform32() {
        uint64_t old = state;
        state = old * 0x5851f42d4c957f2dULL + inc;
        uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = (uint32_t)(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
    }
    uint64_t Uniform64() { return (uint64_t(Uniform32()) << 32) | Uniform32(); }
    // Uniform in [0, 1).
    Float UniformFloat() { return std::min<Float>(OneMinusEpsilon, Uniform32() * 0x1p-32f); }
    // Uniform integer in [0, bound).
    uint32_t UniformBounded(uint32_t bound) {
        uint32_t threshold = (~bound + 1u) % bound;
        while (true) {
            uint32_t r = Uniform32();
            if (r >= threshold) return r % bound;
        }
    }
    void Advance(int64_t idelta);

  private:
    uint64_t state = 0x853c49e6748fea9bULL, inc = 0xda3e39cb94b95bdbULL;
};

inline void RNG::Advance(int64_t idelta) {
    uint64_t curMult = 0x5851f42d4c957f2dULL, curPlus = inc, accMult = 1u;
    uint64_t accPlus = 0u, delta = (uint64_t)idelta;
    while (delta > 0) {
        if (delta & 1) {
            accMult *= curMult;
            accPlus = accPlus * curMult + curPlus;
        }
        curPlus = (curMult + 1) * curPlus;
        curMult *= curMult;
        delta /= 2;
    }
    state = accMult * state + accPlus;
}

}  // namespace kiln
