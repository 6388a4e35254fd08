// Lens system tracing, thick-lens focusing and exit pupil bounds.
//
// The tracing works in "lens space", camera space mirrored in z (z_lens = -z_camera), where the
// film is at 0, the interfaces at negative z and a ray from the film travels towards -z.
#include "core/camera/lens_system.h"
#include "base/number_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/file_reading.h"

namespace kiln {

namespace {

Ray Mirrored(const Ray& r) {
    return Ray(Point3f(r.o.x, r.o.y, -r.o.z), Vector3f(r.d.x, r.d.y, -r.d.z), r.time);
}

// Intersection of a lens-space ray with the sphere of the given radius centred on the axis at
// zCenter: the hit on the element's cap (the nearer root when the ray travels towards +z and
// the radius is positive, or towards -z and it is negative; otherwise the farther), and the
// unit normal facing the ray's origin. False if the ray misses or the hit is behind it.
bool IntersectSphericalElement(Float radius, Float zCenter, const Ray& ray, Float* t, Vector3f* n) {
    Vector3f o(ray.o.x, ray.o.y, ray.o.z - zCenter);
    double a = double(LengthSquared(ray.d));
    double b = 2 * (double(ray.d.x) * o.x + double(ray.d.y) * o.y + double(ray.d.z) * o.z);
    double c = double(LengthSquared(o)) - double(radius) * radius;
    double discrim = b * b - 4 * a * c;
    if (a == 0 || discrim < 0) return false;
    double root = std::sqrt(discrim);
    double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    bool closer = (ray.d.z > 0) != (radius < 0);
    *t = Float(closer ? t0 : t1);
    if (!(*t >= 0)) return false;
    Vector3f normal = Normalize(o + *t * ray.d);
    *n = FaceForward(normal, -ray.d);
    return true;
}

// Refracts wi (unit, pointing away from the surface on the side of n) into the medium of
// relative index eta = eta_t / eta_i; false on total internal reflection.
bool RefractLens(Vector3f wi, Vector3f n, Float eta, Vector3f* wt) {
    Float cosI = Dot(n, wi);
    Float sin2I = std::max<Float>(0, 1 - Sqr(cosI));
    Float sin2T = sin2I / Sqr(eta);
    if (sin2T >= 1) return false;
    Float cosT = SafeSqrt(1 - sin2T);
    *wt = -wi / eta + (cosI / eta - cosT) * n;
    return true;
}

Float AirIfZero(Float eta) { return eta != 0 ? eta : 1; }

// Radical inverse of i in base 2 and base 3 (Halton's first two dimensions).
Float RadicalInverse2(uint32_t i) {
    uint32_t bits = i;
    bits = (bits << 16) | (bits >> 16);
    bits = ((bits & 0x55555555u) << 1) | ((bits & 0xAAAAAAAAu) >> 1);
    bits = ((bits & 0x33333333u) << 2) | ((bits & 0xCCCCCCCCu) >> 2);
    bits = ((bits & 0x0F0F0F0Fu) << 4) | ((bits & 0xF0F0F0F0u) >> 4);
    bits = ((bits & 0x00FF00FFu) << 8) | ((bits & 0xFF00FF00u) >> 8);
    return std::min<Float>(Float(bits * 0x1p-32), OneMinusEpsilon);
}
Float RadicalInverse3(uint32_t i) {
    double inv = 1.0 / 3, f = inv, r = 0;
    while (i > 0) {
        r += (i % 3) * f;
        i /= 3;
        f *= inv;
    }
    return std::min<Float>(Float(r), OneMinusEpsilon);
}

}  // namespace

LensSystem::LensSystem(std::vector<LensInterface> interfaces, Image aperture)
    : interfaces(std::move(interfaces)), aperture(std::move(aperture)) {}

Float LensSystem::FrontZ() const {
    Float z = 0;
    for (const LensInterface& e : interfaces) z += e.thickness;
    return z;
}

Float LensSystem::TraceFromFilm(const Ray& rCamera, Ray* rOut) const {
    return Trace(rCamera, rOut, false);
}

Float LensSystem::Trace(const Ray& rCamera, Ray* rOut, bool maskSupport) const {
    Float elementZ = 0, weight = 1;
    Ray r = Mirrored(rCamera);
    for (int i = int(interfaces.size()) - 1; i >= 0; --i) {
        const LensInterface& e = interfaces[i];
        elementZ -= e.thickness;
        bool isStop = e.curvatureRadius == 0;
        Float t;
        Vector3f n;
        if (isStop) {
            t = (elementZ - r.o.z) / r.d.z;
            if (!(t >= 0)) return 0;
        } else if (!IntersectSphericalElement(e.curvatureRadius, elementZ + e.curvatureRadius, r,
                                              &t, &n))
            return 0;
        Point3f pHit = r(t);
        if (isStop && aperture && maskSupport) {
            // The disk around the mask's square, half a texel wider (bilinear filtering)
            Float reach =
                e.apertureRadius * std::sqrt(2.f) *
                (1 + 1 / Float(std::min(aperture.Resolution().x, aperture.Resolution().y)));
            if (Sqr(pHit.x) + Sqr(pHit.y) > Sqr(reach)) return 0;
        } else if (isStop && aperture) {
            Point2f uv((pHit.x / e.apertureRadius + 1) / 2, (pHit.y / e.apertureRadius + 1) / 2);
            weight = aperture.BilerpChannel(uv, 0, WrapMode::Black);
            if (!(weight > 0)) return 0;
        } else if (Sqr(pHit.x) + Sqr(pHit.y) > Sqr(e.apertureRadius))
            return 0;
        r.o = pHit;
        if (!isStop) {
            // From the medium behind this interface into the one in front of it
            Float etaI = AirIfZero(e.eta), etaT = i > 0 ? AirIfZero(interfaces[i - 1].eta) : 1;
            Vector3f w;
            if (!RefractLens(Normalize(-r.d), n, etaT / etaI, &w)) return 0;
            r.d = w;
        }
    }
    if (rOut) *rOut = Mirrored(r);
    return weight;
}

bool LensSystem::TraceFromScene(const Ray& rCamera, Ray* rOut) const {
    Float elementZ = -FrontZ();
    Ray r = Mirrored(rCamera);
    for (size_t i = 0; i < interfaces.size(); ++i) {
        const LensInterface& e = interfaces[i];
        bool isStop = e.curvatureRadius == 0;
        Float t;
        Vector3f n;
        if (isStop) {
            t = (elementZ - r.o.z) / r.d.z;
            if (!(t >= 0)) return false;
        } else if (!IntersectSphericalElement(e.curvatureRadius, elementZ + e.curvatureRadius, r,
                                              &t, &n))
            return false;
        Point3f pHit = r(t);
        if (Sqr(pHit.x) + Sqr(pHit.y) > Sqr(e.apertureRadius)) return false;
        r.o = pHit;
        if (!isStop) {
            Float etaI = i > 0 ? AirIfZero(interfaces[i - 1].eta) : 1, etaT = AirIfZero(e.eta);
            Vector3f w;
            if (!RefractLens(Normalize(-r.d), n, etaT / etaI, &w)) return false;
            r.d = w;
        }
        elementZ += e.thickness;
    }
    if (rOut) *rOut = Mirrored(r);
    return true;
}

std::optional<std::array<CardinalPoints, 2>> LensSystem::ThickLensApproximation(Float x) const {
    // A ray parallel to the axis at height x in, the traced ray out: the focal point is where
    // the outgoing ray crosses the axis, the principal plane where it reaches height x
    auto cardinal = [](const Ray& in, const Ray& out) {
        Float tf = -out.o.x / out.d.x, tp = (in.o.x - out.o.x) / out.d.x;
        return CardinalPoints{out(tp).z, out(tf).z};
    };
    std::array<CardinalPoints, 2> c;
    Ray fromScene(Point3f(x, 0, FrontZ() + 1), Vector3f(0, 0, -1)), toFilm;
    if (!TraceFromScene(fromScene, &toFilm)) return std::nullopt;
    c[0] = cardinal(fromScene, toFilm);
    Ray fromFilm(Point3f(x, 0, RearZ() - 1), Vector3f(0, 0, 1)), toScene;
    if (TraceFromFilm(fromFilm, &toScene) == 0) return std::nullopt;
    c[1] = cardinal(fromFilm, toScene);
    return c;
}

std::optional<Float> LensSystem::FocusedRearThickness(Float focusDistance, Float x) const {
    std::optional<std::array<CardinalPoints, 2>> c = ThickLensApproximation(x);
    if (!c) return std::nullopt;
    // pbrt-v4 works in lens space (z negated): p' = -principalZ etc. The lens moves by delta
    // along the axis so that the thick-lens equation images the plane at focusDistance on the
    // film.
    Float pz0 = -(*c)[0].principalZ, fz0 = -(*c)[0].focalZ, pz1 = -(*c)[1].principalZ;
    Float f = fz0 - pz0, z = -focusDistance;
    Float disc = (pz1 - z - pz0) * (pz1 - z - 4 * f - pz0);
    if (!(disc > 0) || !std::isfinite(disc)) return std::nullopt;
    Float delta = (pz1 - z + pz0 - std::sqrt(disc)) / 2;
    return RearZ() + delta;
}

PupilBounds LensSystem::BoundExitPupil(Float x0, Float x1, int nSamples) const {
    PupilBounds pupil;
    Float rearRadius = RearRadius(), side = 3 * rearRadius;
    Point2f lo(-1.5f * rearRadius, -1.5f * rearRadius);
    for (int i = 0; i < nSamples; ++i) {
        Point3f pFilm(Lerp((i + 0.5f) / nSamples, x0, x1), 0, 0);
        Point3f pRear(lo.x + side * RadicalInverse2(uint32_t(i)),
                      lo.y + side * RadicalInverse3(uint32_t(i)), RearZ());
        Point2f p(pRear.x, pRear.y);
        if (!pupil.Inside(p) && Trace(Ray(pFilm, pRear - pFilm), nullptr, true) > 0) pupil.Add(p);
    }
    if (pupil.IsDegenerate()) return pupil;
    Float expand = 2 * std::sqrt(2.f) * side / std::sqrt(Float(nSamples));
    pupil.pMin = Point2f(pupil.pMin.x - expand, pupil.pMin.y - expand);
    pupil.pMax = Point2f(pupil.pMax.x + expand, pupil.pMax.y + expand);
    return pupil;
}

std::optional<std::vector<LensInterface>> ParseLensFile(const std::string& text,
                                                        const std::string& filename,
                                                        Float stopDiameterMm, bool* clamped,
                                                        std::string* error) {
    auto fail = [&](const std::string& msg) -> std::optional<std::vector<LensInterface>> {
        if (error) *error = filename + ": " + msg;
        return std::nullopt;
    };
    std::string numberError;
    std::optional<std::vector<Float>> numbers = ParseNumberText(text, &numberError);
    if (!numbers) return fail(numberError);
    const std::vector<Float>& v = *numbers;
    if (v.empty()) return fail("no values in lens file");
    if (v.size() % 4 != 0)
        return fail(
            "lens file needs four values per interface (radius, thickness, eta, "
            "aperture diameter); read " +
            std::to_string(v.size()));
    // Every camera ray and exit pupil sample is traced through every interface
    if (v.size() / 4 > kMaxLensInterfaces)
        return fail("more than " + std::to_string(kMaxLensInterfaces) +
                    " interfaces (a real lens has a few dozen)");
    if (clamped) *clamped = false;
    std::vector<LensInterface> interfaces;
    for (size_t i = 0; i < v.size(); i += 4) {
        LensInterface e{v[i] / 1000, v[i + 1] / 1000, v[i + 2], v[i + 3] / 1000};
        std::string row = "interface " + std::to_string(i / 4 + 1) + ": ";
        if (!(e.thickness >= 0)) return fail(row + "thickness must not be negative");
        if (!(e.eta >= 0)) return fail(row + "eta must not be negative");
        if (!(e.apertureRadius > 0)) return fail(row + "aperture diameter must be positive");
        if (e.curvatureRadius == 0) {
            if (stopDiameterMm / 1000 > e.apertureRadius) {
                if (clamped) *clamped = true;
            } else
                e.apertureRadius = stopDiameterMm / 1000;
        }
        e.apertureRadius /= 2;
        interfaces.push_back(e);
    }
    return interfaces;
}

std::optional<std::vector<LensInterface>> ReadLensFile(const std::string& filename,
                                                       Float stopDiameterMm, bool* clamped,
                                                       std::string* error) {
    std::string text, readError;
    if (!ReadFileBytes(filename, &text, &readError)) {
        if (error) *error = filename + ": cannot read lens file: " + readError;
        return std::nullopt;
    }
    return ParseLensFile(text, filename, stopDiameterMm, clamped, error);
}

}  // namespace kiln
