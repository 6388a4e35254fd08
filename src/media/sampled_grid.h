// SampledGrid: values on an nx x ny x nz lattice over the unit cube, sample (x, y, z) at
// ((x + 0.5) / nx, (y + 0.5) / ny, (z + 0.5) / nz), interpolated trilinearly and zero beyond
// the outermost samples (pbrt-v4's SampledGrid): the density of a "uniformgrid" medium, its
// temperatures, an "rgbgrid" medium's coefficients.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

// Whether p is in [0, 1]^3 (false for NaN).
inline bool InsideUnitCube(Point3f p) {
    return p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1 && p.z >= 0 && p.z <= 1;
}

template <typename T>
class SampledGrid {
  public:
    SampledGrid() = default;
    // values in x-fastest order: values[(z * ny + y) * nx + x]
    SampledGrid(std::vector<T> values, int nx, int ny, int nz)
        : values(std::move(values)), nx(nx), ny(ny), nz(nz) {}

    int XSize() const { return nx; }
    int YSize() const { return ny; }
    int ZSize() const { return nz; }
    bool Empty() const { return values.empty(); }
    size_t BytesAllocated() const { return values.size() * sizeof(T); }

    bool Inside(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz;
    }
    // The sample at integer coordinates inside the lattice.
    const T& At(int x, int y, int z) const {
        return values[(size_t(z) * size_t(ny) + size_t(y)) * size_t(nx) + size_t(x)];
    }

    // Trilinear interpolation at p in the unit cube, of convert(sample).
    template <typename F>
    auto Lookup(Point3f p, F convert) const {
        Float sx = p.x * nx - 0.5f, sy = p.y * ny - 0.5f, sz = p.z * nz - 0.5f;
        Float fx = std::floor(sx), fy = std::floor(sy), fz = std::floor(sz);
        using R = std::decay_t<decltype(convert(std::declval<const T&>()))>;
        // Far outside (or NaN): nothing there, and no integer overflow below
        constexpr Float kFar = 1 << 30;
        if (!(std::abs(fx) < kFar && std::abs(fy) < kFar && std::abs(fz) < kFar)) return R{};
        int x = int(fx), y = int(fy), z = int(fz);
        Float dx = sx - fx, dy = sy - fy, dz = sz - fz;
        auto v = [&](int i, int j, int k) {
            return Inside(x + i, y + j, z + k) ? R(convert(At(x + i, y + j, z + k))) : R{};
        };
        auto lerp = [](Float t, auto a, auto b) { return a * (1 - t) + b * t; };
        auto d00 = lerp(dx, v(0, 0, 0), v(1, 0, 0)), d10 = lerp(dx, v(0, 1, 0), v(1, 1, 0));
        auto d01 = lerp(dx, v(0, 0, 1), v(1, 0, 1)), d11 = lerp(dx, v(0, 1, 1), v(1, 1, 1));
        return lerp(dz, lerp(dy, d00, d10), lerp(dy, d01, d11));
    }
    T Lookup(Point3f p) const {
        return Lookup(p, [](const T& v) { return v; });
    }

    // The largest convert(sample) among the samples whose interpolation reaches into bounds
    // (a box in the unit cube): a bound on Lookup there.
    template <typename F>
    Float MaxValue(const Bounds3f& bounds, F convert) const {
        auto lo = [](Float v, int n) { return std::max(int(std::floor(v * n - 0.5f)), 0); };
        auto hi = [](Float v, int n) { return std::min(int(std::floor(v * n - 0.5f)) + 1, n - 1); };
        Float m = 0;
        for (int z = lo(bounds.pMin.z, nz); z <= hi(bounds.pMax.z, nz); ++z)
            for (int y = lo(bounds.pMin.y, ny); y <= hi(bounds.pMax.y, ny); ++y)
                for (int x = lo(bounds.pMin.x, nx); x <= hi(bounds.pMax.x, nx); ++x)
                    m = std::max(m, convert(At(x, y, z)));
        return m;
    }

  private:
    std::vector<T> values;
    int nx = 0, ny = 0, nz = 0;
};

}  // namespace kiln
