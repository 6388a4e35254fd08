// Majorants of a medium's extinction along a ray (pbrt-v4's RayMajorantSegment, MajorantGrid
// and its two iterators): delta and ratio tracking sample distances against sigma_maj, which
// must bound sigma_t = sigma_a + sigma_s everywhere on its segment.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "base/transform.h"
#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// sigma_maj bounds the extinction (per unit of the ray's parameter, for a unit direction) for
// t in [tMin, tMax].
struct RayMajorantSegment {
    Float tMin, tMax;
    SampledSpectrum sigma_maj;
};

// Per-voxel bounds on a density over bounds (16^3 voxels in pbrt-v4's grid media).
struct MajorantGrid {
    Bounds3f bounds;  // in the medium's space
    std::vector<Float> voxels;
    int res[3] = {0, 0, 0};

    MajorantGrid() = default;
    MajorantGrid(Bounds3f bounds, int resolution)
        : bounds(bounds),
          voxels(size_t(resolution) * resolution * resolution, Float(0)),
          res{resolution, resolution, resolution} {}
    Float Lookup(int x, int y, int z) const { return voxels[x + res[0] * (y + res[1] * z)]; }
    void Set(int x, int y, int z, Float v) { voxels[x + res[0] * (y + res[1] * z)] = v; }
    // Voxel (x, y, z) as a box in the unit cube.
    Bounds3f VoxelBounds(int x, int y, int z) const {
        return Bounds3f(
            Point3f(Float(x) / res[0], Float(y) / res[1], Float(z) / res[2]),
            Point3f(Float(x + 1) / res[0], Float(y + 1) / res[1], Float(z + 1) / res[2]));
    }
    // Fills every voxel with bound(voxel bounds in the unit cube).
    template <typename F>
    void Fill(F bound) {
        for (int z = 0; z < res[2]; ++z)
            for (int y = 0; y < res[1]; ++y)
                for (int x = 0; x < res[0]; ++x) Set(x, y, z, bound(VoxelBounds(x, y, z)));
    }
};

// Where a ray in the medium's space enters and leaves bounds, clipped to [0, tMax]; nullopt if
// it misses.
std::optional<std::pair<Float, Float>> ClipRayToBounds(const Bounds3f& bounds, Point3f o,
                                                       Vector3f d, Float tMax);

// A render-space ray over [0, tMax] in a medium's space (same parameter t), clipped to the
// medium's box; nullopt if it misses.
struct MediumRaySegment {
    Point3f o;
    Vector3f d;
    Float tMin, tMax;
};
inline std::optional<MediumRaySegment> RayInMedium(const Transform& renderFromMedium,
                                                   const Bounds3f& bounds, const Ray& ray,
                                                   Float tMax) {
    Point3f o = renderFromMedium.ApplyInverse(ray.o);
    Vector3f d = renderFromMedium.ApplyInverse(ray.d);
    std::optional<std::pair<Float, Float>> t = ClipRayToBounds(bounds, o, d, tMax);
    if (!t) return std::nullopt;
    return MediumRaySegment{o, d, t->first, t->second};
}

// The segments of a ray through a medium: one segment (homogeneous media, or a single bound
// over the whole medium) or the voxels of a MajorantGrid crossed by a 3D DDA; none when the
// ray misses the medium.
class MajorantIterator {
  public:
    MajorantIterator() = default;  // no segments
    MajorantIterator(Float tMin, Float tMax, const SampledSpectrum& sigma_maj)
        : tMin(tMin), tMax(tMax), sigma_t(sigma_maj) {}
    // ray: in the medium's space; [tMin, tMax]: its part inside grid->bounds; sigma_t: what a
    // voxel's value scales to (the majorant is sigma_t * voxel).
    MajorantIterator(Point3f o, Vector3f d, Float tMin, Float tMax, const MajorantGrid* grid,
                     const SampledSpectrum& sigma_t);

    std::optional<RayMajorantSegment> Next() {
        if (tMin >= tMax) return std::nullopt;
        if (!grid) {
            RayMajorantSegment seg{tMin, tMax, sigma_t};
            tMin = tMax;
            return seg;
        }
        return NextVoxel();
    }

  private:
    std::optional<RayMajorantSegment> NextVoxel();

    Float tMin = 1, tMax = 0;
    SampledSpectrum sigma_t;
    const MajorantGrid* grid = nullptr;
    Float nextCrossingT[3] = {0, 0, 0}, deltaT[3] = {0, 0, 0};
    int step[3] = {0, 0, 0}, voxelLimit[3] = {0, 0, 0}, voxel[3] = {0, 0, 0};
};

}  // namespace kiln
