// Small-vector maths: points, vectors, normals, bounds and frames.
//
// Geometry is single precision (kiln::Float), as in pbrt-v4 and Embree. Points, vectors and
// normals share one storage template but are distinct types so that transforms treat each
// correctly. Lengths are in scene units; angles in radians.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>

namespace kiln {

using Float = float;

// Constants
inline constexpr Float Pi = 3.14159265358979323846f;
inline constexpr Float InvPi = 0.31830988618379067154f;
inline constexpr Float Inv2Pi = 0.15915494309189533577f;
inline constexpr Float Inv4Pi = 0.07957747154594766788f;
inline constexpr Float PiOver2 = 1.57079632679489661923f;
inline constexpr Float PiOver4 = 0.78539816339744830961f;
inline constexpr Float Sqrt2 = 1.41421356237309504880f;
inline constexpr Float Infinity = std::numeric_limits<Float>::infinity();
inline constexpr Float MachineEpsilon = std::numeric_limits<Float>::epsilon() * 0.5f;
inline constexpr Float OneMinusEpsilon = 0x1.fffffep-1f;

// Scalar helpers
template <typename T>
constexpr T Sqr(T v) {
    return v * v;
}
template <typename T, typename U, typename V>
constexpr T Clamp(T val, U low, V high) {
    return val < low ? T(low) : (val > high ? T(high) : val);
}
inline Float Lerp(Float t, Float a, Float b) { return (1 - t) * a + t * b; }
inline Float SafeSqrt(Float x) { return std::sqrt(std::max<Float>(0, x)); }
inline double SafeSqrt(double x) { return std::sqrt(std::max(0.0, x)); }
inline Float SafeASin(Float x) { return std::asin(Clamp(x, -1, 1)); }
inline Float SafeACos(Float x) { return std::acos(Clamp(x, -1, 1)); }
inline Float Radians(Float deg) { return (Pi / 180) * deg; }
inline Float Degrees(Float rad) { return (180 / Pi) * rad; }
inline Float SmoothStep(Float x, Float a, Float b) {
    if (a == b) return (x < a) ? 0 : 1;
    Float t = Clamp((x - a) / (b - a), 0, 1);
    return t * t * (3 - 2 * t);
}
template <typename T>
inline bool IsNaN(T v) {
    return std::isnan(v);
}
inline bool IsFinite(Float v) { return std::isfinite(v); }
inline Float Sign(Float v) { return std::copysign(Float(1), v); }
// Polynomial evaluation by Horner's rule: c0 + t (c1 + t (c2 + ...)).
template <typename F, typename C>
constexpr F EvaluatePolynomial(F t, C c) {
    return c;
}
template <typename F, typename C, typename... Args>
constexpr F EvaluatePolynomial(F t, C c, Args... cRemaining) {
    return std::fma(t, EvaluatePolynomial(t, cRemaining...), c);
}
// Finds the largest index i in [0, size-2] with pred(i) true (pred monotone), as pbrt-v4.
template <typename Predicate>
inline size_t FindInterval(size_t sz, const Predicate& pred) {
    using ssize_t = std::make_signed_t<size_t>;
    ssize_t size = (ssize_t)sz - 2, first = 1;
    while (size > 0) {
        size_t half = (size_t)size >> 1, middle = first + half;
        bool predResult = pred(middle);
        first = predResult ? middle + 1 : first;
        size = predResult ? size - (half + 1) : half;
    }
    return (size_t)Clamp((ssize_t)first - 1, 0, (ssize_t)sz - 2);
}

// Tuple storage shared by points, vectors and normals
template <typename Child, typename T>
struct Tuple2 {
    T x{}, y{};
    constexpr Tuple2() = default;
    constexpr Tuple2(T x, T y) : x(x), y(y) {}
    T operator[](int i) const { return i == 0 ? x : y; }
    T& operator[](int i) { return i == 0 ? x : y; }
    Child operator+(Child c) const { return {x + c.x, y + c.y}; }
    Child operator-(Child c) const { return {x - c.x, y - c.y}; }
    Child operator*(T s) const { return {s * x, s * y}; }
    Child operator/(T d) const { return {x / d, y / d}; }
    Child operator-() const { return {-x, -y}; }
    bool operator==(const Tuple2& o) const { return x == o.x && y == o.y; }
    bool operator!=(const Tuple2& o) const { return !(*this == o); }
};

template <typename Child, typename T>
struct Tuple3 {
    T x{}, y{}, z{};
    constexpr Tuple3() = default;
    constexpr Tuple3(T x, T y, T z) : x(x), y(y), z(z) {}
    T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    Child operator*(T s) const { return {s * x, s * y, s * z}; }
    Child operator/(T d) const {
        T inv = T(1) / d;
        return {x * inv, y * inv, z * inv};
    }
    Child operator-() const { return {-x, -y, -z}; }
    Child& operator*=(T s) {
        x *= s, y *= s, z *= s;
        return static_cast<Child&>(*this);
    }
    Child& operator/=(T s) { return *this *= (T(1) / s); }
    bool operator==(const Tuple3& o) const { return x == o.x && y == o.y && z == o.z; }
    bool operator!=(const Tuple3& o) const { return !(*this == o); }
    bool HasNaN() const { return std::isnan(x) || std::isnan(y) || std::isnan(z); }
};
template <typename C, typename T>
inline C operator*(T s, const Tuple3<C, T>& t) {
    return t * s;
}
template <typename C, typename T>
inline C operator*(T s, const Tuple2<C, T>& t) {
    return t * s;
}

// 2D types
struct Vector2f : Tuple2<Vector2f, Float> {
    using Tuple2::Tuple2;
};
struct Point2f : Tuple2<Point2f, Float> {
    using Tuple2::Tuple2;
    using Tuple2::operator-;
    Point2f operator+(Vector2f v) const { return {x + v.x, y + v.y}; }
    Vector2f operator-(Point2f p) const { return {x - p.x, y - p.y}; }
    Point2f operator*(Float s) const { return {s * x, s * y}; }
    Point2f operator+(Point2f p) const { return {x + p.x, y + p.y}; }
};
struct Point2i : Tuple2<Point2i, int> {
    using Tuple2::Tuple2;
};
struct Vector2i : Tuple2<Vector2i, int> {
    using Tuple2::Tuple2;
};

// 3D types
struct Vector3f;
struct Normal3f;
struct Point3f;

struct Vector3f : Tuple3<Vector3f, Float> {
    using Tuple3::Tuple3;
    using Tuple3::operator-;
    explicit Vector3f(const Normal3f& n);
    explicit Vector3f(const Point3f& p);
    Vector3f operator+(Vector3f v) const { return {x + v.x, y + v.y, z + v.z}; }
    Vector3f operator-(Vector3f v) const { return {x - v.x, y - v.y, z - v.z}; }
    Vector3f& operator+=(Vector3f v) {
        x += v.x, y += v.y, z += v.z;
        return *this;
    }
    Vector3f& operator-=(Vector3f v) {
        x -= v.x, y -= v.y, z -= v.z;
        return *this;
    }
};

struct Normal3f : Tuple3<Normal3f, Float> {
    using Tuple3::Tuple3;
    using Tuple3::operator-;
    explicit Normal3f(const Vector3f& v) : Tuple3(v.x, v.y, v.z) {}
    Normal3f operator+(Normal3f n) const { return {x + n.x, y + n.y, z + n.z}; }
    Normal3f operator-(Normal3f n) const { return {x - n.x, y - n.y, z - n.z}; }
};

struct Point3f : Tuple3<Point3f, Float> {
    using Tuple3::Tuple3;
    using Tuple3::operator-;
    explicit Point3f(const Vector3f& v) : Tuple3(v.x, v.y, v.z) {}
    Point3f operator+(Vector3f v) const { return {x + v.x, y + v.y, z + v.z}; }
    Point3f operator-(Vector3f v) const { return {x - v.x, y - v.y, z - v.z}; }
    Vector3f operator-(Point3f p) const { return {x - p.x, y - p.y, z - p.z}; }
    Point3f& operator+=(Vector3f v) {
        x += v.x, y += v.y, z += v.z;
        return *this;
    }
    // Affine combinations (weighted sums of points), as used in interpolation.
    Point3f operator+(Point3f p) const { return {x + p.x, y + p.y, z + p.z}; }
};

inline Vector3f::Vector3f(const Normal3f& n) : Tuple3(n.x, n.y, n.z) {}
inline Vector3f::Vector3f(const Point3f& p) : Tuple3(p.x, p.y, p.z) {}

// Geometric operations
template <typename A, typename B>
inline Float Dot(const A& a, const B& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename A, typename B>
inline Float AbsDot(const A& a, const B& b) {
    return std::abs(Dot(a, b));
}
inline Vector3f Cross(const Vector3f& a, const Vector3f& b) {
    // Products in double avoid catastrophic cancellation (pbrt-v4 uses DifferenceOfProducts).
    double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    return {Float(ay * bz - az * by), Float(az * bx - ax * bz), Float(ax * by - ay * bx)};
}
inline Vector3f Cross(const Vector3f& a, const Normal3f& b) { return Cross(a, Vector3f(b)); }
inline Vector3f Cross(const Normal3f& a, const Vector3f& b) { return Cross(Vector3f(a), b); }
template <typename T>
inline Float LengthSquared(const T& v) {
    return Dot(v, v);
}
// Length and Normalize of vectors whose squared length leaves float's normal range (a
// component beyond ~1e19 or below ~1e-19: a sphere of radius 1e10 has dp/du near 1e10 and a
// cross product of its derivatives near 1e20; a hit within 1e-22 of a sphere's pole has dp/du
// near 1e-22) square in double; in float they would come out infinite or zero and the
// direction zero or NaN. Other vectors take the float path, bit for bit as before.
template <typename T>
inline double LengthDouble(const T& v) {
    return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}
constexpr Float kMinFloatSquaredLength = 1e-36f, kMaxFloatSquaredLength = 1e36f;
template <typename T>
inline Float Length(const T& v) {
    Float l2 = LengthSquared(v);
    if (l2 > kMinFloatSquaredLength && l2 < kMaxFloatSquaredLength) return std::sqrt(l2);
    return Float(LengthDouble(v));
}
template <typename T>
inline T Normalize(const T& v) {
    Float l2 = LengthSquared(v);
    if (l2 > kMinFloatSquaredLength && l2 < kMaxFloatSquaredLength) return v / std::sqrt(l2);
    double length = LengthDouble(v);
    return T(Float(v.x / length), Float(v.y / length), Float(v.z / length));
}
// Normalize(Cross(a, b)) without the cross product leaving float range in between (edges
// near 1e-30 have a cross product near 1e-60, which is 0 in float).
inline Vector3f NormalizedCross(const Vector3f& a, const Vector3f& b) {
    double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    double x = ay * bz - az * by, y = az * bx - ax * bz, z = ax * by - ay * bx;
    double l2 = x * x + y * y + z * z;
    if (l2 > kMinFloatSquaredLength && l2 < kMaxFloatSquaredLength)
        return Normalize(Vector3f(Float(x), Float(y), Float(z)));
    double length = std::sqrt(l2);
    return {Float(x / length), Float(y / length), Float(z / length)};
}
inline Float Distance(Point3f a, Point3f b) { return Length(a - b); }
inline Float DistanceSquared(Point3f a, Point3f b) { return LengthSquared(a - b); }
template <typename T>
inline T Abs(const T& v) {
    return T(std::abs(v.x), std::abs(v.y), std::abs(v.z));
}
template <typename T>
inline Float MaxComponentValue(const T& v) {
    return std::max({v.x, v.y, v.z});
}
template <typename T>
inline int MaxComponentIndex(const T& v) {
    return (v.x > v.y) ? ((v.x > v.z) ? 0 : 2) : ((v.y > v.z) ? 1 : 2);
}
template <typename T>
inline T Min(const T& a, const T& b) {
    return T(std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z));
}
template <typename T>
inline T Max(const T& a, const T& b) {
    return T(std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z));
}
template <typename T>
inline T Permute(const T& v, int i, int j, int k) {
    return T(v[i], v[j], v[k]);
}
inline Point3f Lerp(Float t, Point3f a, Point3f b) {
    return {Lerp(t, a.x, b.x), Lerp(t, a.y, b.y), Lerp(t, a.z, b.z)};
}
inline Normal3f FaceForward(Normal3f n, Vector3f v) { return Dot(n, v) < 0 ? -n : n; }
inline Vector3f FaceForward(Vector3f n, Vector3f v) { return Dot(n, v) < 0 ? -n : n; }
// Angle between two unit vectors, accurate for nearly parallel vectors.
inline Float AngleBetween(Vector3f v1, Vector3f v2) {
    if (Dot(v1, v2) < 0) return Pi - 2 * SafeASin(Length(v1 + v2) / 2);
    return 2 * SafeASin(Length(v2 - v1) / 2);
}
// Component of v orthogonal to unit vector w (Gram-Schmidt).
inline Vector3f GramSchmidt(Vector3f v, Vector3f w) { return v - Dot(v, w) * w; }

// Builds an orthonormal basis from unit v (Duff et al. 2017).
inline void CoordinateSystem(Vector3f v1, Vector3f* v2, Vector3f* v3) {
    Float sign = std::copysign(Float(1), v1.z);
    Float a = -1 / (sign + v1.z);
    Float b = v1.x * v1.y * a;
    *v2 = Vector3f(1 + sign * Sqr(v1.x) * a, sign * b, -sign * v1.x);
    *v3 = Vector3f(b, sign + Sqr(v1.y) * a, -v1.y);
}

// Spherical geometry in a local frame whose z axis is the normal
inline Float CosTheta(Vector3f w) { return w.z; }
inline Float Cos2Theta(Vector3f w) { return w.z * w.z; }
inline Float AbsCosTheta(Vector3f w) { return std::abs(w.z); }
inline Float Sin2Theta(Vector3f w) { return std::max<Float>(0, 1 - Cos2Theta(w)); }
inline Float SinTheta(Vector3f w) { return std::sqrt(Sin2Theta(w)); }
inline Float TanTheta(Vector3f w) { return SinTheta(w) / CosTheta(w); }
inline Float Tan2Theta(Vector3f w) { return Sin2Theta(w) / Cos2Theta(w); }
inline Float CosPhi(Vector3f w) {
    Float s = SinTheta(w);
    return (s == 0) ? 1 : Clamp(w.x / s, -1, 1);
}
inline Float SinPhi(Vector3f w) {
    Float s = SinTheta(w);
    return (s == 0) ? 0 : Clamp(w.y / s, -1, 1);
}
inline bool SameHemisphere(Vector3f w, Vector3f wp) { return w.z * wp.z > 0; }
inline Vector3f SphericalDirection(Float sinTheta, Float cosTheta, Float phi) {
    return {Clamp(sinTheta, -1, 1) * std::cos(phi), Clamp(sinTheta, -1, 1) * std::sin(phi),
            Clamp(cosTheta, -1, 1)};
}
inline Float SphericalTheta(Vector3f v) { return SafeACos(v.z); }
inline Float SphericalPhi(Vector3f v) {
    Float p = std::atan2(v.y, v.x);
    return (p < 0) ? (p + 2 * Pi) : p;
}

// Orthonormal frame: converts between render space and a local space with z = normal.
struct Frame {
    Vector3f x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    Frame() = default;
    Frame(Vector3f x, Vector3f y, Vector3f z) : x(x), y(y), z(z) {}
    static Frame FromZ(Vector3f z) {
        Vector3f x, y;
        CoordinateSystem(z, &x, &y);
        return Frame(x, y, z);
    }
    static Frame FromXZ(Vector3f x, Vector3f z) { return Frame(x, Cross(z, x), z); }
    Vector3f ToLocal(Vector3f v) const { return {Dot(v, x), Dot(v, y), Dot(v, z)}; }
    Vector3f FromLocal(Vector3f v) const { return v.x * x + v.y * y + v.z * z; }
};

// Axis-aligned boxes
struct Bounds2i {
    Point2i pMin, pMax;  // half-open: [pMin, pMax)
    int64_t Area() const { return int64_t(pMax.x - pMin.x) * (pMax.y - pMin.y); }
    bool IsEmpty() const { return pMin.x >= pMax.x || pMin.y >= pMax.y; }
};
struct Bounds2f {
    Point2f pMin, pMax;
};
struct Bounds3f {
    Point3f pMin{Infinity, Infinity, Infinity}, pMax{-Infinity, -Infinity, -Infinity};
    Bounds3f() = default;
    explicit Bounds3f(Point3f p) : pMin(p), pMax(p) {}
    Bounds3f(Point3f a, Point3f b) : pMin(Min(a, b)), pMax(Max(a, b)) {}
    bool IsEmpty() const { return pMin.x > pMax.x || pMin.y > pMax.y || pMin.z > pMax.z; }
    Vector3f Diagonal() const { return pMax - pMin; }
    Point3f Centroid() const { return Point3f(0.5f * (Vector3f(pMin) + Vector3f(pMax))); }
    Point3f Corner(int c) const {
        return {(c & 1) ? pMax.x : pMin.x, (c & 2) ? pMax.y : pMin.y, (c & 4) ? pMax.z : pMin.z};
    }
    void BoundingSphere(Point3f* center, Float* radius) const {
        *center = Centroid();
        *radius = IsEmpty() ? 0 : Distance(*center, pMax);
    }
};
inline Bounds3f Union(const Bounds3f& b, Point3f p) {
    Bounds3f r;
    r.pMin = Min(b.pMin, p);
    r.pMax = Max(b.pMax, p);
    return r;
}
inline Bounds3f Union(const Bounds3f& a, const Bounds3f& b) {
    if (a.IsEmpty()) return b;
    if (b.IsEmpty()) return a;
    Bounds3f r;
    r.pMin = Min(a.pMin, b.pMin);
    r.pMax = Max(a.pMax, b.pMax);
    return r;
}

// The largest render-space coordinate kiln traces rays at. Embree refuses ray origins and
// directions with a component beyond 1.844e18; a shadow ray runs from a surface point to a
// point up to twice the scene's bounding radius beyond it (infinite and distant lights), so
// shapes and camera rays stay within a tenth of that. Shapes beyond it are skipped at their
// directive, cameras that would start rays beyond it are errors at theirs.
constexpr Float kMaxRenderCoordinate = 1e17f;
// Whether b lies within +-kMaxRenderCoordinate on every axis (false for NaN or infinite bounds).
inline bool InRenderRange(const Bounds3f& b) {
    for (Point3f p : {b.pMin, b.pMax})
        if (!(std::abs(p.x) <= kMaxRenderCoordinate && std::abs(p.y) <= kMaxRenderCoordinate &&
              std::abs(p.z) <= kMaxRenderCoordinate))
            return false;
    return true;
}

// Rays: origin, unit (or not) direction, and scene time (cameras map a sample in [0, 1) into
// their shutter interval, as pbrt-v4; moving objects are placed at this time).
struct Ray {
    Point3f o;
    Vector3f d;
    Float time = 0;
    Ray() = default;
    Ray(Point3f o, Vector3f d, Float time = 0) : o(o), d(d), time(time) {}
    Point3f operator()(Float t) const { return o + d * t; }
};

// Robust ray origins
//
// Moves p off a surface with geometric normal n, to the side of w, by an amount that scales
// with the magnitude of p's coordinates. Integer-ULP offsets follow Waechter & Binder,
// "A Fast and Robust Method for Avoiding Self-Intersection" (Ray Tracing Gems, 2019), so
// scenes far from the origin (1e6 units) stay free of self-intersection.
inline Float FloatBitsOffset(Float p, Float nComponent) {
    constexpr Float origin = 1.0f / 32.0f, floatScale = 1.0f / 65536.0f, intScale = 256.0f;
    int32_t ofi = int32_t(intScale * nComponent);
    int32_t bits;
    std::memcpy(&bits, &p, sizeof(bits));
    bits += (p < 0) ? -ofi : ofi;
    Float pi;
    std::memcpy(&pi, &bits, sizeof(pi));
    return std::abs(p) < origin ? p + floatScale * nComponent : pi;
}
// error: the half-extent, in every axis, of a box around p that the surface may pass through
// (pbrt-v4's pError where it is more than rounding: a curve's hit width); p first moves
// Dot(|n|, (error, error, error)) along n towards w, as pbrt-v4's OffsetRayOrigin.
inline Point3f OffsetRayOrigin(Point3f p, Normal3f n, Vector3f w, Float error = 0) {
    Normal3f nf = Dot(n, w) < 0 ? -n : n;
    if (error > 0) p = p + error * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z)) * Vector3f(nf);
    return {FloatBitsOffset(p.x, nf.x), FloatBitsOffset(p.y, nf.y), FloatBitsOffset(p.z, nf.z)};
}

inline std::ostream& operator<<(std::ostream& os, const Point3f& p) {
    return os << "[" << p.x << ", " << p.y << ", " << p.z << "]";
}
inline std::ostream& operator<<(std::ostream& os, const Vector3f& p) {
    return os << "[" << p.x << ", " << p.y << ", " << p.z << "]";
}

}  // namespace kiln
