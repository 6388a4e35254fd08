#include "base/sphere_mappings.h"

namespace kiln {

// Equal-area octahedral mapping
Vector3f EqualAreaSquareToSphere(Point2f p) {
    // Move p to [-1,1]^2 and fold it into the first quadrant
    Float u = 2 * p.x - 1, v = 2 * p.y - 1;
    Float up = std::abs(u), vp = std::abs(v);

    // Radius r: distance from the diagonal |u| + |v| = 1 (the equator), sign: the hemisphere
    Float signedDistance = 1 - (up + vp);
    Float r = 1 - std::abs(signedDistance);

    // Azimuth within the quadrant, from the position along the diamond's edge
    Float phi = (r == 0 ? 1 : (vp - up) / r + 1) * PiOver4;

    // Height: equal area needs z = 1 - r^2 (with the hemisphere's sign)
    Float z = std::copysign(1 - Sqr(r), signedDistance);

    // Unfold the quadrant
    Float cosPhi = std::copysign(std::cos(phi), u), sinPhi = std::copysign(std::sin(phi), v);
    Float s = r * SafeSqrt(2 - Sqr(r));
    return {cosPhi * s, sinPhi * s, z};
}

Point2f EqualAreaSphereToSquare(Vector3f d) {
    // Work in the first octant
    Float x = std::abs(d.x), y = std::abs(d.y), z = std::min<Float>(std::abs(d.z), 1);

    // Radius from the height, azimuth in [0, 1] over the quadrant
    Float r = SafeSqrt(1 - z);
    Float phi = (x == 0 && y == 0) ? 0 : std::atan2(y, x) * (2 * InvPi);

    // Position along the diamond's edge in the first quadrant
    Float vq = phi * r, uq = r - vq;

    // Lower hemisphere: reflect across the edge into the corner triangle
    if (d.z < 0) {
        std::swap(uq, vq);
        uq = 1 - uq;
        vq = 1 - vq;
    }

    // Restore the signs and move to [0,1]^2
    uq = std::copysign(uq, d.x);
    vq = std::copysign(vq, d.y);
    return {Clamp(0.5f * (uq + 1), 0, 1), Clamp(0.5f * (vq + 1), 0, 1)};
}

Point2f WrapEqualAreaSquare(Point2f p) {
    // The octahedral layout's edges: the edge u = 0 (or 1) meets itself mirrored about v = 1/2,
    // and likewise for v
    if (p.x < 0) {
        p.x = -p.x;
        p.y = 1 - p.y;
    } else if (p.x > 1) {
        p.x = 2 - p.x;
        p.y = 1 - p.y;
    }
    if (p.y < 0) {
        p.x = 1 - p.x;
        p.y = -p.y;
    } else if (p.y > 1) {
        p.x = 1 - p.x;
        p.y = 2 - p.y;
    }
    return p;
}

// Equirectangular mapping
Vector3f EquirectSquareToSphere(Point2f p) {
    Float theta = Pi * Clamp(p.y, 0, 1), phi = 2 * Pi * p.x;
    return SphericalDirection(std::sin(theta), std::cos(theta), phi);
}

Point2f EquirectSphereToSquare(Vector3f d) {
    Float u = SphericalPhi(d) * Inv2Pi, v = SphericalTheta(d) * InvPi;
    return {Clamp(u, 0, 1), Clamp(v, 0, 1)};
}

}  // namespace kiln
