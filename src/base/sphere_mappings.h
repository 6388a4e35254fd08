// Maps between the unit square and the unit sphere of directions, used to store environment
// maps in images (infinite lights) and to lay the sphere of directions on the film (spherical
// camera).
//
// Equal-area octahedral mapping (Clarberg, "Fast Equal-Area Mapping of the (Hemi)Sphere using
// SIMD", JGT 2008), pbrt-v4's EqualAreaSquareToSphere / EqualAreaSphereToSquare: the upper
// hemisphere (z > 0) fills the inner diamond |u'| + |v'| < 1 of [-1,1]^2, the lower one the four
// corner triangles; every region of the square maps to a spherical region of 4 pi times its area.
//
// Equirectangular (latitude-longitude) mapping, pbrt-v3's convention: u = phi / (2 pi) with phi
// measured from +x towards +y, v = theta / pi with theta measured from +z; the solid angle per
// unit (u, v) area is 2 pi^2 sin(theta).
#pragma once

#include "base/vecmath.h"

namespace kiln {

// [0,1]^2 -> unit vector; inverse of EqualAreaSphereToSquare.
Vector3f EqualAreaSquareToSphere(Point2f p);
// Unit vector -> [0,1]^2.
Point2f EqualAreaSphereToSquare(Vector3f d);
// Folds a point outside [0,1]^2 (at most one square beyond it) back into the square so that
// EqualAreaSquareToSphere stays continuous across the square's edges (pbrt-v4's
// WrapEqualAreaSquare): beyond u = 0 or u = 1 the point is mirrored across that edge and across
// v = 1/2, beyond v = 0 or v = 1 across that edge and across u = 1/2. Points inside are
// returned unchanged.
Point2f WrapEqualAreaSquare(Point2f p);

// [0,1]^2 -> unit vector (u = phi / 2 pi, v = theta / pi).
Vector3f EquirectSquareToSphere(Point2f p);
// Unit vector -> [0,1]^2.
Point2f EquirectSphereToSquare(Vector3f d);
// d(omega) / d(u, v) at p: 2 pi^2 sin(theta), sr per unit square area.
inline Float EquirectJacobian(Point2f p) { return 2 * Pi * Pi * std::sin(Pi * Clamp(p.y, 0, 1)); }

}  // namespace kiln
