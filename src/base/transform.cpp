#include "base/transform.h"

#include <cmath>

namespace kiln {

SquareMatrix4::SquareMatrix4(const Float v[16]) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m[i][j] = v[4 * i + j];
}

bool SquareMatrix4::IsIdentity() const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (m[i][j] != (i == j ? 1 : 0)) return false;
    return true;
}

bool SquareMatrix4::operator==(const SquareMatrix4& o) const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (m[i][j] != o.m[i][j]) return false;
    return true;
}

SquareMatrix4 SquareMatrix4::Transposed() const {
    SquareMatrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
    return r;
}

SquareMatrix4 operator*(const SquareMatrix4& a, const SquareMatrix4& b) {
    SquareMatrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += double(a.m[i][k]) * b.m[k][j];
            r.m[i][j] = Float(s);
        }
    return r;
}

std::optional<SquareMatrix4> Inverse(const SquareMatrix4& mat) {
    // Gauss-Jordan elimination with full pivoting, in double precision.
    double a[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 8; ++j) a[i][j] = (j < 4) ? mat.m[i][j] : (j - 4 == i ? 1 : 0);
    for (int c = 0; c < 4; ++c) {
        int piv = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
        if (a[piv][c] == 0 || !std::isfinite(a[piv][c])) return std::nullopt;
        if (piv != c)
            for (int j = 0; j < 8; ++j) std::swap(a[c][j], a[piv][j]);
        double inv = 1 / a[c][c];
        for (int j = 0; j < 8; ++j) a[c][j] *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            double f = a[r][c];
            if (f != 0)
                for (int j = 0; j < 8; ++j) a[r][j] -= f * a[c][j];
        }
    }
    SquareMatrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = Float(a[i][j + 4]);
    return r;
}

Transform::Transform(const SquareMatrix4& m) : m(m) {
    std::optional<SquareMatrix4> inv = Inverse(m);
    if (inv) {
        mInv = *inv;
    } else {
        // Singular (e.g. Scale 0): keep a NaN inverse, as pbrt-v4 does, so misuse is visible.
        Float nan = std::numeric_limits<Float>::quiet_NaN();
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) mInv.m[i][j] = nan;
    }
}

bool Transform::IsSingular() const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m.m[i][j]) || !std::isfinite(mInv.m[i][j])) return true;
    return false;
}

double Transform::LinearDeterminant() const {
    return double(m.m[0][0]) * (double(m.m[1][1]) * m.m[2][2] - double(m.m[1][2]) * m.m[2][1]) -
           double(m.m[0][1]) * (double(m.m[1][0]) * m.m[2][2] - double(m.m[1][2]) * m.m[2][0]) +
           double(m.m[0][2]) * (double(m.m[1][0]) * m.m[2][1] - double(m.m[1][1]) * m.m[2][0]);
}

bool Transform::SwapsHandedness() const { return LinearDeterminant() < 0; }

Float Transform::SimilarityScale() const {
    // The columns of the linear part: equal lengths, mutually orthogonal
    double c[3][3];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) c[j][i] = m.m[i][j];
    auto dot = [&](int a, int b) {
        return c[a][0] * c[b][0] + c[a][1] * c[b][1] + c[a][2] * c[b][2];
    };
    double s2 = dot(0, 0), tol = 1e-5 * s2;
    if (!(s2 > 0) || !std::isfinite(s2)) return 0;
    if (std::abs(dot(1, 1) - s2) > tol || std::abs(dot(2, 2) - s2) > tol ||
        std::abs(dot(0, 1)) > tol || std::abs(dot(0, 2)) > tol || std::abs(dot(1, 2)) > tol)
        return 0;
    return Float(std::sqrt(s2));
}

static Point3f ApplyPoint(const SquareMatrix4& m, Point3f p) {
    Float xp = m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + m.m[0][3];
    Float yp = m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + m.m[1][3];
    Float zp = m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + m.m[2][3];
    Float wp = m.m[3][0] * p.x + m.m[3][1] * p.y + m.m[3][2] * p.z + m.m[3][3];
    return (wp == 1) ? Point3f(xp, yp, zp) : Point3f(xp / wp, yp / wp, zp / wp);
}
static Vector3f ApplyVector(const SquareMatrix4& m, Vector3f v) {
    return {m.m[0][0] * v.x + m.m[0][1] * v.y + m.m[0][2] * v.z,
            m.m[1][0] * v.x + m.m[1][1] * v.y + m.m[1][2] * v.z,
            m.m[2][0] * v.x + m.m[2][1] * v.y + m.m[2][2] * v.z};
}
static Normal3f ApplyNormal(const SquareMatrix4& mInv, Normal3f n) {
    return {mInv.m[0][0] * n.x + mInv.m[1][0] * n.y + mInv.m[2][0] * n.z,
            mInv.m[0][1] * n.x + mInv.m[1][1] * n.y + mInv.m[2][1] * n.z,
            mInv.m[0][2] * n.x + mInv.m[1][2] * n.y + mInv.m[2][2] * n.z};
}

Point3f Transform::operator()(Point3f p) const { return ApplyPoint(m, p); }
Vector3f Transform::operator()(Vector3f v) const { return ApplyVector(m, v); }
Normal3f Transform::operator()(Normal3f n) const { return ApplyNormal(mInv, n); }
Point3f Transform::ApplyInverse(Point3f p) const { return ApplyPoint(mInv, p); }
Vector3f Transform::ApplyInverse(Vector3f v) const { return ApplyVector(mInv, v); }
Normal3f Transform::ApplyInverse(Normal3f n) const { return ApplyNormal(m, n); }

Bounds3f Transform::operator()(const Bounds3f& b) const {
    Bounds3f r;
    if (b.IsEmpty()) return r;
    for (int i = 0; i < 8; ++i) r = Union(r, (*this)(b.Corner(i)));
    return r;
}

Transform Transform::operator*(const Transform& t2) const {
    return Transform(m * t2.m, t2.mInv * mInv);
}

Transform Translate(Vector3f d) {
    SquareMatrix4 m, mi;
    m.m[0][3] = d.x, m.m[1][3] = d.y, m.m[2][3] = d.z;
    mi.m[0][3] = -d.x, mi.m[1][3] = -d.y, mi.m[2][3] = -d.z;
    return Transform(m, mi);
}

Transform Scale(Float x, Float y, Float z) {
    SquareMatrix4 m;
    m.m[0][0] = x, m.m[1][1] = y, m.m[2][2] = z;
    return Transform(m);
}

Transform Rotate(Float theta, Vector3f axis) {
    Vector3f a = Normalize(axis);
    Float sinTheta = std::sin(Radians(theta)), cosTheta = std::cos(Radians(theta));
    SquareMatrix4 m;
    m.m[0][0] = a.x * a.x + (1 - a.x * a.x) * cosTheta;
    m.m[0][1] = a.x * a.y * (1 - cosTheta) - a.z * sinTheta;
    m.m[0][2] = a.x * a.z * (1 - cosTheta) + a.y * sinTheta;
    m.m[1][0] = a.x * a.y * (1 - cosTheta) + a.z * sinTheta;
    m.m[1][1] = a.y * a.y + (1 - a.y * a.y) * cosTheta;
    m.m[1][2] = a.y * a.z * (1 - cosTheta) - a.x * sinTheta;
    m.m[2][0] = a.x * a.z * (1 - cosTheta) - a.y * sinTheta;
    m.m[2][1] = a.y * a.z * (1 - cosTheta) + a.x * sinTheta;
    m.m[2][2] = a.z * a.z + (1 - a.z * a.z) * cosTheta;
    return Transform(m, m.Transposed());
}

std::optional<Transform> LookAt(Point3f pos, Point3f look, Vector3f up) {
    SquareMatrix4 worldFromCamera;
    worldFromCamera.m[0][3] = pos.x, worldFromCamera.m[1][3] = pos.y;
    worldFromCamera.m[2][3] = pos.z;
    Vector3f dir = look - pos;
    if (LengthSquared(dir) == 0 || LengthSquared(up) == 0) return std::nullopt;
    dir = Normalize(dir);
    Vector3f upn = Normalize(up);
    if (LengthSquared(Cross(upn, dir)) == 0) return std::nullopt;
    Vector3f right = Normalize(Cross(upn, dir));
    Vector3f newUp = Cross(dir, right);
    for (int i = 0; i < 3; ++i) {
        worldFromCamera.m[i][0] = right[i];
        worldFromCamera.m[i][1] = newUp[i];
        worldFromCamera.m[i][2] = dir[i];
    }
    std::optional<SquareMatrix4> cameraFromWorld = Inverse(worldFromCamera);
    if (!cameraFromWorld) return std::nullopt;
    return Transform(*cameraFromWorld, worldFromCamera);
}

Transform Orthographic(Float zNear, Float zFar) {
    return Scale(1, 1, 1 / (zFar - zNear)) * Translate(Vector3f(0, 0, -zNear));
}

Transform Perspective(Float fov, Float n, Float f) {
    Float v[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, f / (f - n), -f * n / (f - n), 0, 0, 1, 0};
    SquareMatrix4 persp(v);
    Float invTanAng = 1 / std::tan(Radians(fov) / 2);
    return Scale(invTanAng, invTanAng, 1) * Transform(persp);
}

}  // namespace kiln
