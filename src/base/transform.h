// Affine and projective transforms as 4x4 matrices with cached inverses.
#pragma once

#include <optional>

#include "base/vecmath.h"

namespace kiln {

struct SquareMatrix4 {
    Float m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    SquareMatrix4() = default;
    explicit SquareMatrix4(const Float v[16]);
    bool IsIdentity() const;
    bool operator==(const SquareMatrix4& o) const;
    SquareMatrix4 Transposed() const;
};
SquareMatrix4 operator*(const SquareMatrix4& a, const SquareMatrix4& b);
// Inverse by cofactors in double precision; nullopt when singular.
std::optional<SquareMatrix4> Inverse(const SquareMatrix4& m);

class Transform {
  public:
    Transform() = default;
    explicit Transform(const SquareMatrix4& m);
    Transform(const SquareMatrix4& m, const SquareMatrix4& mInv) : m(m), mInv(mInv) {}

    const SquareMatrix4& Matrix() const { return m; }
    const SquareMatrix4& InverseMatrix() const { return mInv; }
    bool IsIdentity() const { return m.IsIdentity(); }
    bool operator==(const Transform& t) const { return t.m == m; }
    bool SwapsHandedness() const;
    // The determinant of the linear (upper-left 3x3) part
    double LinearDeterminant() const;
    // s for a similarity (rotation or reflection, uniform scale s > 0, translation): lengths
    // scale by s in every direction (within 1e-5); 0 for any other map.
    Float SimilarityScale() const;
    // No finite inverse (e.g. Scale 0, or a matrix whose inverse overflows): points and
    // vectors still transform, but normals and the inverse give NaN.
    bool IsSingular() const;

    Point3f operator()(Point3f p) const;
    Vector3f operator()(Vector3f v) const;
    // Normals transform by the inverse transpose.
    Normal3f operator()(Normal3f n) const;
    Ray operator()(const Ray& r) const { return Ray((*this)(r.o), (*this)(r.d), r.time); }
    Bounds3f operator()(const Bounds3f& b) const;
    Transform operator*(const Transform& t2) const;

    Point3f ApplyInverse(Point3f p) const;
    Vector3f ApplyInverse(Vector3f v) const;
    Normal3f ApplyInverse(Normal3f n) const;

    friend Transform Inverse(const Transform& t) { return Transform(t.mInv, t.m); }
    friend Transform Transpose(const Transform& t) {
        return Transform(t.m.Transposed(), t.mInv.Transposed());
    }

  private:
    SquareMatrix4 m, mInv;
};

Transform Translate(Vector3f delta);
Transform Scale(Float x, Float y, Float z);
// Rotation by theta degrees about axis (normalised internally).
Transform Rotate(Float thetaDegrees, Vector3f axis);
// Camera-from-world... pbrt convention: returns the world-to-camera transform.
std::optional<Transform> LookAt(Point3f pos, Point3f look, Vector3f up);
Transform Orthographic(Float zNear, Float zFar);
Transform Perspective(Float fovDegrees, Float zNear, Float zFar);

}  // namespace kiln
