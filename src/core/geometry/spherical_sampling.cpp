#include "core/geometry/spherical_sampling.h"

#include "core/geometry/shape_util.h"

namespace kiln {

namespace {

// Double-precision vector for the angle computations.
struct V3d {
    double x, y, z;
};
V3d ToD(Vector3f v) { return {v.x, v.y, v.z}; }
V3d operator+(V3d a, V3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3d operator-(V3d a, V3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3d operator-(V3d a) { return {-a.x, -a.y, -a.z}; }
V3d operator*(double s, V3d a) { return {s * a.x, s * a.y, s * a.z}; }
double Dot(V3d a, V3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3d Cross(V3d a, V3d b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double Len2(V3d a) { return Dot(a, a); }
V3d Norm(V3d a) { return (1 / std::sqrt(Len2(a))) * a; }
double Angle(V3d a, V3d b) {
    if (Dot(a, b) < 0) return M_PI - 2 * std::asin(std::min(1.0, std::sqrt(Len2(a + b)) / 2));
    return 2 * std::asin(std::min(1.0, std::sqrt(Len2(b - a)) / 2));
}

// Unit directions to the vertices and the spherical angles at them; false if degenerate.
bool SphericalAngles(const std::array<Point3f, 3>& v, Point3f p, V3d* a, V3d* b, V3d* c,
                     double* alpha, double* beta, double* gamma) {
    V3d da = ToD(v[0] - p), db = ToD(v[1] - p), dc = ToD(v[2] - p);
    if (Len2(da) == 0 || Len2(db) == 0 || Len2(dc) == 0) return false;
    *a = Norm(da), *b = Norm(db), *c = Norm(dc);
    V3d nab = Cross(*a, *b), nbc = Cross(*b, *c), nca = Cross(*c, *a);
    if (Len2(nab) == 0 || Len2(nbc) == 0 || Len2(nca) == 0) return false;
    nab = Norm(nab), nbc = Norm(nbc), nca = Norm(nca);
    *alpha = Angle(nab, -nca);
    *beta = Angle(nbc, -nab);
    *gamma = Angle(nca, -nbc);
    return true;
}

}  // namespace

Float SphericalTriangleArea(const std::array<Point3f, 3>& v, Point3f p) {
    V3d a = ToD(v[0] - p), b = ToD(v[1] - p), c = ToD(v[2] - p);
    if (Len2(a) == 0 || Len2(b) == 0 || Len2(c) == 0) return 0;
    a = Norm(a), b = Norm(b), c = Norm(c);
    return Float(
        std::abs(2 * std::atan2(Dot(a, Cross(b, c)), 1 + Dot(a, b) + Dot(a, c) + Dot(b, c))));
}

// Spherical triangle sampling
std::array<Float, 3> SampleSphericalTriangle(const std::array<Point3f, 3>& v, Point3f p, Point2f u,
                                             Float* pdf) {
    *pdf = 0;
    V3d a, b, c;
    double alpha, beta, gamma;
    if (!SphericalAngles(v, p, &a, &b, &c, &alpha, &beta, &gamma)) return {};
    double A = alpha + beta + gamma - M_PI;
    if (A <= 0) return {};
    *pdf = Float(1 / A);

    // Find the vertex c' on arc a-c that cuts off the sub-triangle of area u0 A.
    double Ap = u[0] * A + M_PI;  // A' + pi
    double cosAlpha = std::cos(alpha), sinAlpha = std::sin(alpha);
    double sinPhi = std::sin(Ap) * cosAlpha - std::cos(Ap) * sinAlpha;
    double cosPhi = std::cos(Ap) * cosAlpha + std::sin(Ap) * sinAlpha;
    double k1 = cosPhi + cosAlpha;
    double k2 = sinPhi - sinAlpha * Dot(a, b);
    double cosBp =
        (k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / ((k2 * sinPhi + k1 * cosPhi) * sinAlpha);
    if (std::isnan(cosBp)) cosBp = 1;
    cosBp = std::clamp(cosBp, -1.0, 1.0);
    double sinBp = std::sqrt(std::max(0.0, 1 - cosBp * cosBp));
    V3d cPerp = c - Dot(c, a) * a;
    V3d cp = cosBp * a + sinBp * (Len2(cPerp) > 0 ? Norm(cPerp) : cPerp);

    // Sample along the arc b-c'.
    double cosTheta = 1 - u[1] * (1 - Dot(cp, b));
    double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    V3d cpPerp = cp - Dot(cp, b) * b;
    V3d w = cosTheta * b + sinTheta * (Len2(cpPerp) > 0 ? Norm(cpPerp) : cpPerp);

    // Barycentrics of the ray p + t w with the triangle's plane.
    V3d e1 = ToD(v[1] - v[0]), e2 = ToD(v[2] - v[0]);
    V3d s1 = Cross(w, e2);
    double divisor = Dot(s1, e1);
    if (divisor == 0) return {1.f / 3, 1.f / 3, 1.f / 3};
    V3d s = ToD(p - v[0]);
    double b1 = Dot(s, s1) / divisor, b2 = Dot(w, Cross(s, e1)) / divisor;
    b1 = std::clamp(b1, 0.0, 1.0), b2 = std::clamp(b2, 0.0, 1.0);
    if (b1 + b2 > 1) {
        double sum = b1 + b2;
        b1 /= sum, b2 /= sum;
    }
    return {Float(1 - b1 - b2), Float(b1), Float(b2)};
}

// Inversion (after Arvo's SphTri.C)
Point2f InvertSphericalTriangleSample(const std::array<Point3f, 3>& v, Point3f p, Vector3f wf) {
    V3d a, b, c;
    double alpha, beta, gamma;
    if (!SphericalAngles(v, p, &a, &b, &c, &alpha, &beta, &gamma)) return {0.5f, 0.5f};
    double A = alpha + beta + gamma - M_PI;
    V3d w = Norm(ToD(wf));
    // c' lies on the great circles through (b, w) and (a, c).
    V3d cp = Cross(Cross(b, w), Cross(c, a));
    if (Len2(cp) == 0) return {0.5f, 0.5f};
    cp = Norm(cp);
    if (Dot(cp, a + c) < 0) cp = -cp;
    // Second sample value: position of w along the arc b-c' (0 if the arc is degenerate).
    double denom = 1 - Dot(cp, b);
    double u1 = denom > 0 ? (1 - Dot(w, b)) / denom : 0;
    u1 = std::isnan(u1) ? 0 : std::clamp(u1, 0.0, 1.0);
    // First sample value: area of the sub-triangle a-b-c' over A. pbrt-v4 (in float) snaps c'
    // within 0.1 degree of a to u0 = 0, which is off by up to ~0.07 for triangles near
    // MinSphericalSampleArea; in double a far smaller angle (~1e-7 rad) is safe.
    if (A <= 0 || 1 - Dot(a, cp) < 1e-14) return {0, Float(u1)};
    V3d nab = Norm(Cross(a, b));
    V3d cpxb = Cross(cp, b), axcp = Cross(a, cp);
    if (Len2(cpxb) == 0 || Len2(axcp) == 0) return {0.5f, 0.5f};
    cpxb = Norm(cpxb), axcp = Norm(axcp);
    double subArea = alpha + Angle(nab, cpxb) + Angle(axcp, -cpxb) - M_PI;
    double u0 = subArea / A;
    u0 = std::isnan(u0) ? 0 : std::clamp(u0, 0.0, 1.0);
    return {Float(u0), Float(u1)};
}

}  // namespace kiln
