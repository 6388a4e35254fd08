#include "media/majorant_grid.h"

#include <cmath>

namespace kiln {

std::optional<std::pair<Float, Float>> ClipRayToBounds(const Bounds3f& bounds, Point3f o,
                                                       Vector3f d, Float tMax) {
    Float t0 = 0, t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        // Slab test; division by zero gives infinities that compare correctly, and a NaN (origin
        // on a slab plane with d = 0) leaves the interval unchanged
        Float invD = 1 / d[axis];
        Float tNear = (bounds.pMin[axis] - o[axis]) * invD;
        Float tFar = (bounds.pMax[axis] - o[axis]) * invD;
        if (tNear > tFar) std::swap(tNear, tFar);
        // Widened by 2 gamma_3 (Higham's bound on three rounded operations), as pbrt-v4
        tFar *= 1 + 2 * (3 * MachineEpsilon) / (1 - 3 * MachineEpsilon);
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
        if (t0 > t1) return std::nullopt;
    }
    return std::make_pair(t0, t1);
}

MajorantIterator::MajorantIterator(Point3f o, Vector3f d, Float tMin, Float tMax,
                                   const MajorantGrid* grid, const SampledSpectrum& sigma_t)
    : tMin(tMin), tMax(tMax), sigma_t(sigma_t), grid(grid) {
    // The ray in the grid's unit cube
    Vector3f diag = grid->bounds.Diagonal();
    Point3f og((o.x - grid->bounds.pMin.x) / diag.x, (o.y - grid->bounds.pMin.y) / diag.y,
               (o.z - grid->bounds.pMin.z) / diag.z);
    Vector3f dg(d.x / diag.x, d.y / diag.y, d.z / diag.z);
    Point3f entry = og + dg * tMin;
    for (int axis = 0; axis < 3; ++axis) {
        int n = grid->res[axis];
        voxel[axis] = Clamp(int(entry[axis] * n), 0, n - 1);
        deltaT[axis] = 1 / (std::abs(dg[axis]) * n);
        if (dg[axis] == -0.f) dg[axis] = 0.f;
        if (dg[axis] >= 0) {
            Float next = Float(voxel[axis] + 1) / n;
            nextCrossingT[axis] = tMin + (next - entry[axis]) / dg[axis];
            step[axis] = 1;
            voxelLimit[axis] = n;
        } else {
            Float next = Float(voxel[axis]) / n;
            nextCrossingT[axis] = tMin + (next - entry[axis]) / dg[axis];
            step[axis] = -1;
            voxelLimit[axis] = -1;
        }
    }
}

std::optional<RayMajorantSegment> MajorantIterator::NextVoxel() {
    // The axis whose voxel boundary the ray crosses first
    int bits = ((nextCrossingT[0] < nextCrossingT[1]) << 2) +
               ((nextCrossingT[0] < nextCrossingT[2]) << 1) +
               ((nextCrossingT[1] < nextCrossingT[2]));
    constexpr int cmpToAxis[8] = {2, 1, 2, 1, 2, 2, 0, 0};
    int axis = cmpToAxis[bits];
    Float tExit = std::min(tMax, nextCrossingT[axis]);
    RayMajorantSegment seg{tMin, tExit, sigma_t * grid->Lookup(voxel[0], voxel[1], voxel[2])};
    tMin = tExit;
    if (nextCrossingT[axis] > tMax) tMin = tMax;
    voxel[axis] += step[axis];
    if (voxel[axis] == voxelLimit[axis]) tMin = tMax;
    nextCrossingT[axis] += deltaT[axis];
    return seg;
}

}  // namespace kiln
