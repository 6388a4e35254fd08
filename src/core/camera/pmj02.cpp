// pmj02 sequence generation (Christensen, Kensler & Kilpatrick 2018).
#include "core/camera/pmj02.h"

#include <stdexcept>

#include "base/rng.h"
#include "core/camera/low_discrepancy.h"

namespace kiln {

namespace {

// Which elementary intervals of a 2^m-point (0,m,2)-net are occupied: for each shape i
// (2^i columns, 2^(m-i) rows) one flag per interval.
class IntervalOccupancy {
  public:
    explicit IntervalOccupancy(int m) : m(m), flags(size_t(m + 1) << m, 0) {}
    // Interval of shape i holding the point whose first m bits are X and Y.
    size_t Cell(int i, uint32_t xPrefix, uint32_t yPrefix) const {
        return (size_t(i) << m) | (size_t(xPrefix) << (m - i)) | size_t(yPrefix);
    }
    bool Occupied(int i, uint32_t xPrefix, uint32_t yPrefix) const {
        return flags[Cell(i, xPrefix, yPrefix)];
    }
    void Mark(const FixedPoint2& p) {
        uint32_t X = m ? p[0] >> (32 - m) : 0, Y = m ? p[1] >> (32 - m) : 0;
        for (int i = 0; i <= m; ++i) flags[Cell(i, X >> (m - i), Y >> i)] = 1;
    }
    int Level() const { return m; }

  private:
    int m;
    std::vector<uint8_t> flags;
};

// Depth-first search for the first m bits (X, Y) of a point in the sub-square whose first q
// bits are (qx, qy), such that no elementary interval of level m holding it is occupied.
class PositionSearch {
  public:
    PositionSearch(const IntervalOccupancy& occ, RNG& rng) : occ(occ), rng(rng) {}
    bool Find(int q, uint32_t qx, uint32_t qy, uint32_t& X, uint32_t& Y) {
        int m = occ.Level();
        // Intervals whose x and y prefixes the sub-square already fixes.
        for (int i = m - q; i <= q; ++i)
            if (i >= 0 && i <= m && occ.Occupied(i, qx >> (q - i), qy >> (q - (m - i))))
                return false;
        return Extend(q, qx, q, qy, X, Y);
    }

  private:
    bool Extend(int xLen, uint32_t x, int yLen, uint32_t y, uint32_t& X, uint32_t& Y) {
        int m = occ.Level();
        if (xLen == m && yLen == m) {
            X = x, Y = y;
            return true;
        }
        uint32_t first = rng.Uniform32() & 1;
        for (uint32_t t = 0; t < 2; ++t) {
            uint32_t bit = first ^ t;
            if (xLen < m) {
                // Shape xLen + 1 is checkable once y has its m - xLen - 1 first bits.
                uint32_t nx = (x << 1) | bit;
                int i = xLen + 1, yNeed = m - i;
                if (yNeed <= yLen && occ.Occupied(i, nx, y >> (yLen - yNeed))) continue;
                if (Extend(xLen + 1, nx, yLen, y, X, Y)) return true;
            } else {
                // x complete: shape m - yLen - 1 is checkable with the new y bit.
                uint32_t ny = (y << 1) | bit;
                int i = m - (yLen + 1);
                if (occ.Occupied(i, x >> (m - i), ny)) continue;
                if (Extend(xLen, x, yLen + 1, ny, X, Y)) return true;
            }
        }
        return false;
    }

    const IntervalOccupancy& occ;
    RNG& rng;
};

// Random low bits below the first m.
uint32_t Jitter(RNG& rng, uint32_t prefix, int m) {
    if (m == 0) return rng.Uniform32();
    if (m >= 32) return prefix;
    return (prefix << (32 - m)) | (rng.Uniform32() >> m);
}

// Places points [begin, end) into the sub-squares (resolution 2^q) given by `squares`, so
// that the first `end` points form a (0,m,2)-net with m = log2(end). Returns false if some
// point had no valid position.
bool PlaceLevel(std::vector<FixedPoint2>& pts, size_t begin, size_t end, int q,
                const std::vector<std::array<uint32_t, 2>>& squares, RNG& rng) {
    int m = Log2Int(uint64_t(end));
    IntervalOccupancy occ(m);
    for (size_t j = 0; j < begin; ++j) occ.Mark(pts[j]);
    PositionSearch search(occ, rng);
    for (size_t j = begin; j < end; ++j) {
        uint32_t X, Y;
        if (!search.Find(q, squares[j - begin][0], squares[j - begin][1], X, Y)) return false;
        pts[j] = {Jitter(rng, X, m), Jitter(rng, Y, m)};
        occ.Mark(pts[j]);
    }
    return true;
}

uint32_t Bits(uint32_t v, int n) { return n ? v >> (32 - n) : 0; }

}  // namespace

std::vector<FixedPoint2> GeneratePMJ02(int log4Count, uint64_t seed, int* restarts) {
    if (log4Count < 0 || log4Count > 8) throw std::invalid_argument("GeneratePMJ02: count");
    RNG rng(seed);
    std::vector<FixedPoint2> pts(size_t(1) << (2 * log4Count));
    int nRestarts = 0;
    auto place = [&](size_t begin, size_t end, int q,
                     const std::vector<std::array<uint32_t, 2>>& squares) {
        while (!PlaceLevel(pts, begin, end, q, squares, rng))
            if (++nRestarts > 1000) throw std::logic_error("GeneratePMJ02: no valid position");
    };
    pts[0] = {rng.Uniform32(), rng.Uniform32()};
    for (int k = 0; k < log4Count; ++k) {
        size_t n = size_t(1) << (2 * k);
        int q = k + 1;  // sub-square resolution 2^q
        // 4^k -> 2 4^k: the sub-square diagonally opposite each point's own. A search that
        // finds no position restarts the level with new random bits.
        std::vector<std::array<uint32_t, 2>> squares(n);
        for (size_t i = 0; i < n; ++i)
            squares[i] = {Bits(pts[i][0], q) ^ 1u, Bits(pts[i][1], q) ^ 1u};
        place(n, 2 * n, q, squares);
        // 2 4^k -> 4 4^k: the two remaining sub-squares, the x- or y-flipped one first at
        // random; the other for point 3 4^k + i.
        std::vector<std::array<uint32_t, 2>> squares2(2 * n);
        for (size_t i = 0; i < n; ++i) {
            uint32_t sx = Bits(pts[i][0], q), sy = Bits(pts[i][1], q);
            bool xFirst = rng.Uniform32() & 1;
            squares2[i] = xFirst ? std::array<uint32_t, 2>{sx ^ 1u, sy}
                                 : std::array<uint32_t, 2>{sx, sy ^ 1u};
            squares2[n + i] = xFirst ? std::array<uint32_t, 2>{sx, sy ^ 1u}
                                     : std::array<uint32_t, 2>{sx ^ 1u, sy};
        }
        place(2 * n, 4 * n, q, squares2);
    }
    if (restarts) *restarts = nRestarts;
    return pts;
}

std::span<const FixedPoint2> PMJ02Set(int set) {
    static const std::vector<std::vector<FixedPoint2>> sets = [] {
        std::vector<std::vector<FixedPoint2>> s;
        for (int i = 0; i < kPMJ02Sets; ++i)
            s.push_back(GeneratePMJ02(8, 0x706d6a3032ULL + uint64_t(i)));
        return s;
    }();
    return sets[size_t(set)];
}

}  // namespace kiln
