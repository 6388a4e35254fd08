// What every shape shares: ray hits, and points sampled on the shape (pbrt-v4's
// ShapeIntersection, ShapeSample and ShapeSampleContext).
#pragma once

#include "base/interaction.h"
#include "base/vecmath.h"

namespace kiln {

// A ray hit: the surface interaction and the ray parameter t of the hit.
struct ShapeIntersection {
    SurfaceInteraction intr;
    Float tHit = 0;
};

// A point sampled on a shape (intr.p, intr.n, intr.uv set) with its density: per unit area
// (m^-2 in scene units) from Sample(u), per steradian from Sample(ctx, u).
struct ShapeSample {
    Interaction intr;
    Float pdf = 0;
};

// The reference point from which a shape is sampled by solid angle: render-space position,
// geometric and shading normals (zero for points not on a surface) and time.
struct ShapeSampleContext {
    Point3f p;
    Normal3f n, ns;
    Float time = 0;

    ShapeSampleContext() = default;
    ShapeSampleContext(Point3f p, Normal3f n, Normal3f ns, Float time)
        : p(p), n(n), ns(ns), time(time) {}
    ShapeSampleContext(const SurfaceInteraction& si)
        : p(si.p), n(si.n), ns(si.shading.n), time(si.time) {}

    Point3f OffsetRayOrigin(Vector3f w) const {
        return n != Normal3f(0, 0, 0) ? kiln::OffsetRayOrigin(p, n, w) : p;
    }
    Ray SpawnRay(Vector3f w) const { return Ray(OffsetRayOrigin(w), w, time); }
};

}  // namespace kiln
