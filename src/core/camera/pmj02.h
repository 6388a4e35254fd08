// Progressive multi-jittered (0,2) sequences: Christensen, Kensler & Kilpatrick 2018,
// "Progressive Multi-Jittered Sample Sequences", Computer Graphics Forum 37(4) (EGSR), and the
// tables of them that pbrt-v4's PMJ02BNSampler draws from (generated here by kiln's own code).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "base/vecmath.h"
#include "core/camera/low_discrepancy.h"

namespace kiln {

// A point with coordinates x / 2^32 and y / 2^32.
using FixedPoint2 = std::array<uint32_t, 2>;

// 4^log4Count points of a pmj02 sequence, determined by `seed`. Every prefix of 2^m points is
// a (0,m,2)-net in base 2 (each of the m + 1 partitions of the unit square into 2^m equal
// elementary intervals 2^-i x 2^-(m-i) holds one point), and every prefix of 4^k points has
// one point in each square of the 2^k x 2^k grid (progressive jittering). Construction as in
// the paper: from 4^k points, point 4^k + i goes into the sub-square of point i's grid square
// diagonally opposite point i's own (giving 2 4^k points), then points 2 4^k + i and
// 3 4^k + i into that square's two remaining sub-squares (in random order). Inside its
// sub-square a point takes a random position whose elementary intervals of the level being
// completed are all still empty: a depth-first search over the bits of x, then of y, that
// checks each interval as soon as its bits are known (random bit order, backtracking). No
// blue-noise selection among the valid positions (the paper's pmj02bn variant): the net and
// sub-square constraints leave a new point very few valid cells of side 2^-m (one, for each
// point enumerated at level 2^11), so candidates differ mostly by their jitter inside it; a
// best-of-8 selection measured +3 to +6 % mean nearest-neighbour distance for 16x the time.
// log4Count <= 8. A level whose search fails for some point is placed again with new random
// bits; `restarts` (if given) receives how many times that happened.
std::vector<FixedPoint2> GeneratePMJ02(int log4Count, uint64_t seed, int* restarts = nullptr);

// pbrt-v4's table shape: kPMJ02Sets independent sequences of kPMJ02Samples points each,
// generated once per process (seeds 0..kPMJ02Sets-1) on first use.
inline constexpr int kPMJ02Sets = 5;
inline constexpr int kPMJ02Samples = 65536;
std::span<const FixedPoint2> PMJ02Set(int set);

inline Point2f PMJ02Sample(int set, int index) {
    const FixedPoint2& p = PMJ02Set(set % kPMJ02Sets)[size_t(index % kPMJ02Samples)];
    return {FixedToFloat(p[0]), FixedToFloat(p[1])};
}

}  // namespace kiln
