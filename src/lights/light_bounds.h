// Spatial and directional bounds of a light's emission and its importance at a receiving point
// (pbrt-v4's DirectionCone and LightBounds, Sec. 12.6.3), for the BVH light sampler.
#pragma once

#include "base/vecmath.h"

namespace kiln {

// The directions within angle acos(cosTheta) of w (cosTheta = -1: the entire sphere).
struct DirectionCone {
    Vector3f w;
    Float cosTheta = Infinity;  // empty

    DirectionCone() = default;
    DirectionCone(Vector3f w, Float cosTheta) : w(Normalize(w)), cosTheta(cosTheta) {}
    explicit DirectionCone(Vector3f w) : DirectionCone(w, 1) {}
    static DirectionCone EntireSphere() { return DirectionCone(Vector3f(0, 0, 1), -1); }
    bool IsEmpty() const { return cosTheta == Infinity; }
};
DirectionCone Union(const DirectionCone& a, const DirectionCone& b);
// The cone of directions from p towards the box (its bounding sphere); entire sphere inside.
DirectionCone BoundSubtendedDirections(const Bounds3f& b, Point3f p);

// Emitters inside `bounds` with total power phi (W) whose surface normals lie in the cone
// (w, cosTheta_o) and which emit within angle acos(cosTheta_e) of their normal, on both sides
// of the surface when twoSided.
struct LightBounds {
    Bounds3f bounds;
    Point3f center;  // power-weighted centre of the emitters (kiln; pbrt-v4 uses the box's)
    Float phi = 0;
    Vector3f w;
    Float cosTheta_o = 1, cosTheta_e = 1;
    bool twoSided = false;
    // From Finish(): the bounding sphere, and the clamp of the squared distance (pbrt-v4 clamps
    // it to half the box's diagonal)
    Point3f sphereCenter;
    Float sphereRadius = 0, minDistance2 = 0;

    LightBounds() = default;
    LightBounds(const Bounds3f& b, Vector3f w, Float phi, Float cosTheta_o, Float cosTheta_e,
                bool twoSided)
        : bounds(b),
          center(b.Centroid()),
          phi(phi),
          w(Normalize(w)),
          cosTheta_o(cosTheta_o),
          cosTheta_e(cosTheta_e),
          twoSided(twoSided) {}

    Point3f Centroid() const { return bounds.Centroid(); }
    // Precomputes the bounds' bounding sphere for Importance (call once the bounds are final).
    void Finish() {
        bounds.BoundingSphere(&sphereCenter, &sphereRadius);
        minDistance2 = Length(bounds.Diagonal()) / 2;
    }
    // An estimate of the light's contribution at p with surface normal n (zero normal: a point
    // in a medium): phi cos(theta') / d^2, times the cosine bound at the receiver (pbrt-v4's
    // LightBounds::Importance), with d the distance to the power-weighted centre: a node
    // whose power sits in one small hot spot of a large cool mesh is as near as the hot spot.
    Float Importance(Point3f p, Normal3f n) const;
};
LightBounds Union(const LightBounds& a, const LightBounds& b);

}  // namespace kiln
