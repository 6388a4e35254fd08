#include "base/animated_transform.h"

#include <algorithm>
#include <cmath>

namespace kiln {

// Quaternions
Quaternion Slerp(double u, const Quaternion& a, const Quaternion& b) {
    double cosTheta = std::clamp(a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z, -1.0, 1.0);
    double theta = std::acos(cosTheta), wa, wb;
    if (theta < 1e-7) {
        wa = 1 - u, wb = u;  // the arc is a chord to double precision
    } else {
        double s = std::sin(theta);
        wa = std::sin((1 - u) * theta) / s, wb = std::sin(u * theta) / s;
    }
    Quaternion q{wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y,
                 wa * a.z + wb * b.z};
    double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

void RotationMatrix(const Quaternion& q, double r[3][3]) {
    double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    r[0][0] = 1 - 2 * (yy + zz), r[0][1] = 2 * (xy - wz), r[0][2] = 2 * (xz + wy);
    r[1][0] = 2 * (xy + wz), r[1][1] = 1 - 2 * (xx + zz), r[1][2] = 2 * (yz - wx);
    r[2][0] = 2 * (xz - wy), r[2][1] = 2 * (yz + wx), r[2][2] = 1 - 2 * (xx + yy);
}

Quaternion QuaternionOfRotation(const double r[3][3]) {
    // Shoemake's method: divide by the largest of 4w^2, 4x^2, 4y^2, 4z^2
    double trace = r[0][0] + r[1][1] + r[2][2];
    Quaternion q;
    if (trace > 0) {
        double s = 2 * std::sqrt(trace + 1);
        q = {s / 4, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
    } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
        double s = 2 * std::sqrt(std::max(0.0, 1 + r[0][0] - r[1][1] - r[2][2]));
        q = {(r[2][1] - r[1][2]) / s, s / 4, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
    } else if (r[1][1] >= r[2][2]) {
        double s = 2 * std::sqrt(std::max(0.0, 1 + r[1][1] - r[0][0] - r[2][2]));
        q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, s / 4, (r[1][2] + r[2][1]) / s};
    } else {
        double s = 2 * std::sqrt(std::max(0.0, 1 + r[2][2] - r[0][0] - r[1][1]));
        q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, s / 4};
    }
    double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// 3x3 helpers in double precision
namespace {

double Det3(const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// The inverse transpose of a (cofactors over the determinant); false when singular.
bool InverseTranspose3(const double a[3][3], double out[3][3]) {
    double det = Det3(a);
    if (det == 0 || !std::isfinite(det)) return false;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            out[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
        }
    return true;
}

double Length3(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace

// AnimatedTransform
AnimatedTransform::Decomposed AnimatedTransform::Decompose(const Transform& transform) {
    const SquareMatrix4& m = transform.Matrix();
    Decomposed dec;
    dec.t = Vector3f(m.m[0][3], m.m[1][3], m.m[2][3]);
    double a[3][3], r[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[i][j] = r[i][j] = m.m[i][j];
    // Polar decomposition A = R S by averaging R with its inverse transpose (pbrt-v4's
    // iteration, run here to convergence in double precision)
    bool singular = false;
    for (int it = 0; it < 100; ++it) {
        double rit[3][3];
        if (!InverseTranspose3(r, rit)) {
            singular = true;
            break;
        }
        double change = 0;
        for (int i = 0; i < 3; ++i) {
            double rowChange = 0;
            for (int j = 0; j < 3; ++j) {
                double next = (r[i][j] + rit[i][j]) / 2;
                rowChange += std::abs(next - r[i][j]);
                r[i][j] = next;
            }
            change = std::max(change, rowChange);
        }
        if (change < 1e-13) break;
    }
    if (singular) {
        // No rotation can be separated (a flattening scale): all of A is stretch
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r[i][j] = i == j;
    } else if (Det3(r) < 0) {
        // A mirror: R has determinant -1; -R is a rotation and -S the stretch that goes with it
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r[i][j] = -r[i][j];
    }
    // S = R^T A
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            dec.s[i][j] = r[0][i] * a[0][j] + r[1][i] * a[1][j] + r[2][i] * a[2][j];
    dec.r = QuaternionOfRotation(r);
    return dec;
}

AnimatedTransform::AnimatedTransform(const Transform& start, Float startTime, const Transform& end,
                                     Float endTime)
    : start(start), end(end), startTime(startTime), endTime(endTime) {
    animated = !(start == end) && endTime > startTime;
    if (!animated) return;
    d[0] = Decompose(start);
    d[1] = Decompose(end);
    Quaternion& q0 = d[0].r;
    Quaternion& q1 = d[1].r;
    double dot = q0.w * q1.w + q0.x * q1.x + q0.y * q1.y + q0.z * q1.z;
    if (dot < 0) {  // the shorter arc
        q1 = {-q1.w, -q1.x, -q1.y, -q1.z};
        dot = -dot;
    }
    rotationAngle = 2 * std::acos(std::min(1.0, dot));
}

SquareMatrix4 AnimatedTransform::Compose(double u) const {
    Quaternion q = Slerp(u, d[0].r, d[1].r);
    double r[3][3];
    RotationMatrix(q, r);
    SquareMatrix4 m;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double rs = 0;
            for (int k = 0; k < 3; ++k) rs += r[i][k] * ((1 - u) * d[0].s[k][j] + u * d[1].s[k][j]);
            m.m[i][j] = Float(rs);
        }
        m.m[i][3] = Float((1 - u) * d[0].t[i] + u * d[1].t[i]);
    }
    return m;
}

SquareMatrix4 AnimatedTransform::MatrixAt(Float time) const {
    if (!animated || time <= startTime) return start.Matrix();
    if (time >= endTime) return end.Matrix();
    return Compose((double(time) - startTime) / (double(endTime) - startTime));
}

Transform AnimatedTransform::Interpolate(Float time) const {
    if (!animated || time <= startTime) return start;
    if (time >= endTime) return end;
    return Transform(Compose((double(time) - startTime) / (double(endTime) - startTime)));
}

Point3f AnimatedTransform::operator()(Point3f p, Float time) const {
    if (!animated) return start(p);
    return Transform(MatrixAt(time), SquareMatrix4())(p);
}

Vector3f AnimatedTransform::operator()(Vector3f v, Float time) const {
    if (!animated) return start(v);
    return Transform(MatrixAt(time), SquareMatrix4())(v);
}

Ray AnimatedTransform::operator()(const Ray& r) const {
    if (!animated) return start(r);
    Transform t(MatrixAt(r.time), SquareMatrix4());
    return Ray(t(r.o), t(r.d), r.time);
}

Bounds3f AnimatedTransform::MotionBounds(const Bounds3f& b) const {
    if (!animated || b.IsEmpty()) return start(b);
    constexpr int steps = 64;
    Bounds3f bounds;
    for (int k = 0; k <= steps; ++k)
        bounds = Union(bounds, Transform(Compose(double(k) / steps), SquareMatrix4())(b));
    // Speed bound of each corner x(u) = T(u) + R(u) S(u) p over u in [0, 1]
    double dt[3] = {double(d[1].t.x) - d[0].t.x, double(d[1].t.y) - d[0].t.y,
                    double(d[1].t.z) - d[0].t.z};
    double speed = 0;
    for (int c = 0; c < 8; ++c) {
        Point3f p = b.Corner(c);
        double pc[3] = {p.x, p.y, p.z}, s0p[3], s1p[3], dsp[3];
        for (int i = 0; i < 3; ++i) {
            s0p[i] = d[0].s[i][0] * pc[0] + d[0].s[i][1] * pc[1] + d[0].s[i][2] * pc[2];
            s1p[i] = d[1].s[i][0] * pc[0] + d[1].s[i][1] * pc[1] + d[1].s[i][2] * pc[2];
            dsp[i] = s1p[i] - s0p[i];
        }
        double v =
            Length3(dt) + rotationAngle * std::max(Length3(s0p), Length3(s1p)) + Length3(dsp);
        speed = std::max(speed, v);
    }
    // Between samples a corner is at most half a step from one; plus float rounding
    double magnitude =
        std::max({std::abs(bounds.pMin.x), std::abs(bounds.pMin.y), std::abs(bounds.pMin.z),
                  std::abs(bounds.pMax.x), std::abs(bounds.pMax.y), std::abs(bounds.pMax.z)});
    Float pad = Float(speed / (2 * steps) * (1 + 1e-6) + 1e-6 * magnitude);
    Vector3f v(pad, pad, pad);
    return Bounds3f(bounds.pMin - v, bounds.pMax + v);
}

}  // namespace kiln
