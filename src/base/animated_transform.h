// AnimatedTransform: a transform that moves over the shutter interval (pbrt-v4's
// ActiveTransform / TransformTimes motion blur).
//
// The start and end transforms are each decomposed as M = T R S (translation, rotation as a unit
// quaternion, and the symmetric stretch of the polar decomposition, as pbrt-v4 does). Between
// startTime and endTime, T and S are interpolated linearly and R by spherical linear
// interpolation along the shorter arc; before startTime the start transform applies, after
// endTime the end transform. Times are the scene's (the camera's shutteropen/shutterclose
// units), as Ray::time.
#pragma once

#include "base/transform.h"

namespace kiln {

struct Quaternion {
    double w = 1, x = 0, y = 0, z = 0;
};

class AnimatedTransform {
  public:
    AnimatedTransform() = default;
    explicit AnimatedTransform(const Transform& t) : start(t), end(t) {}
    AnimatedTransform(const Transform& start, Float startTime, const Transform& end, Float endTime);

    // The start and end transforms differ (and endTime > startTime).
    bool IsAnimated() const { return animated; }
    const Transform& Start() const { return start; }
    const Transform& End() const { return end; }
    Float StartTime() const { return startTime; }
    Float EndTime() const { return endTime; }

    // The transform at `time`, with its inverse.
    Transform Interpolate(Float time) const;
    // The matrix at `time` only (no inverse): for mapping many points one way.
    SquareMatrix4 MatrixAt(Float time) const;
    Point3f operator()(Point3f p, Float time) const;
    Vector3f operator()(Vector3f v, Float time) const;
    Ray operator()(const Ray& r) const;

    // A box holding b under every transform of the motion. Rigorous: the box of the corners at
    // 65 evenly spaced times, padded by the most a corner can move between two of them (a
    // bound on its speed: translation, rotation rate times its distance from the centre of
    // rotation, and stretch).
    Bounds3f MotionBounds(const Bounds3f& b) const;

  private:
    struct Decomposed {
        Vector3f t;
        Quaternion r;
        double s[3][3];
    };
    static Decomposed Decompose(const Transform& m);
    SquareMatrix4 Compose(double u) const;  // u in [0, 1] between start and end

    Transform start, end;
    Float startTime = 0, endTime = 1;
    bool animated = false;
    Decomposed d[2];
    double rotationAngle = 0;  // between R[0] and R[1], radians
};

// Spherical linear interpolation along the arc from a to b (unit quaternions), u in [0, 1].
Quaternion Slerp(double u, const Quaternion& a, const Quaternion& b);
// The rotation matrix of a unit quaternion, and the unit quaternion of a rotation matrix
// (upper-left 3x3, determinant +1).
void RotationMatrix(const Quaternion& q, double r[3][3]);
Quaternion QuaternionOfRotation(const double r[3][3]);

}  // namespace kiln
