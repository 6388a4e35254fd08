#include "lights/projection_light.h"

#include <algorithm>

namespace kiln {

namespace {

// pbrt-v4's near plane: directions with z below it (unit length) receive nothing
constexpr Float kHither = 1e-3f;

Float Area(const Bounds2f& b) { return (b.pMax.x - b.pMin.x) * (b.pMax.y - b.pMin.y); }

// The point of b at fractions t (in [0, 1]^2) of its extent, and back
Point2f LerpBounds(const Bounds2f& b, Point2f t) {
    return {Lerp(t.x, b.pMin.x, b.pMax.x), Lerp(t.y, b.pMin.y, b.pMax.y)};
}
Point2f OffsetIn(const Bounds2f& b, Point2f p) {
    return {(p.x - b.pMin.x) / (b.pMax.x - b.pMin.x), (p.y - b.pMin.y) / (b.pMax.y - b.pMin.y)};
}

RGB PixelRGB(const Image& image, Point2i p) {
    return RGB(std::max<Float>(0, image.GetChannel(p, 0)),
               std::max<Float>(0, image.GetChannel(p, 1)),
               std::max<Float>(0, image.GetChannel(p, 2)));
}

// cos^3 theta of the direction through screen point s (the plane at z = 1 holds s tan)
Float CosCubed(Point2f s, Float tanHalfFov) {
    Float cosTheta = 1 / std::sqrt(Sqr(s.x * tanHalfFov) + Sqr(s.y * tanHalfFov) + 1);
    return cosTheta * cosTheta * cosTheta;
}

// The solid angle of pixel (x, y), exactly: seen from the origin, the rectangle [X0, X1] x
// [Y0, Y1] of the plane z = 1 subtends F(X1, Y1) - F(X0, Y1) - F(X1, Y0) + F(X0, Y0) with
// F(X, Y) = atan(X Y / sqrt(1 + X^2 + Y^2))
double PixelSolidAngle(const Bounds2f& screen, Point2i res, int x, int y, Float tanHalfFov) {
    auto F = [](double X, double Y) { return std::atan(X * Y / std::sqrt(1 + X * X + Y * Y)); };
    Point2f s0 = LerpBounds(screen, Point2f(Float(x) / res.x, Float(y) / res.y));
    Point2f s1 = LerpBounds(screen, Point2f(Float(x + 1) / res.x, Float(y + 1) / res.y));
    double X0 = double(s0.x) * tanHalfFov, X1 = double(s1.x) * tanHalfFov;
    double Y0 = double(s0.y) * tanHalfFov, Y1 = double(s1.y) * tanHalfFov;
    return F(X1, Y1) - F(X0, Y1) - F(X1, Y0) + F(X0, Y0);
}

}  // namespace

Bounds2f ProjectionLight::ScreenBounds(Point2i resolution) {
    Float aspect = Float(resolution.x) / Float(resolution.y);
    if (aspect > 1) return {Point2f(-aspect, -1), Point2f(aspect, 1)};
    return {Point2f(-1, -1 / aspect), Point2f(1, 1 / aspect)};
}

double ProjectionLight::LuminousIntegral(const Image& image, const RGBColorSpace& cs,
                                         Float fovDegrees) {
    Point2i res = image.Resolution();
    Bounds2f screen = ScreenBounds(res);
    Float tanHalf = std::tan(Radians(fovDegrees) / 2);
    const ColorMatrix& m = cs.XYZFromRGB();
    double sum = 0;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            double lum = 0;
            for (int c = 0; c < 3; ++c) lum += m[1][c] * double(image.GetChannel({x, y}, c));
            sum += lum * PixelSolidAngle(screen, res, x, y, tanHalf);
        }
    return sum;
}

ProjectionLight::ProjectionLight(const Transform& renderFromLight, Image image,
                                 const RGBColorSpace* imageColorSpace, Float scale,
                                 Float fovDegrees)
    : renderFromProjector(renderFromLight * Scale(1, -1, 1)),
      position(renderFromLight(Point3f(0, 0, 0))),
      image(std::move(image)),
      colorSpace(imageColorSpace),
      scale(scale),
      tanHalfFov(std::tan(Radians(fovDegrees) / 2)) {
    Point2i res = this->image.Resolution();
    screen = ScreenBounds(res);
    // Each pixel in proportion to its value (the mean of its channels) times its solid angle
    std::vector<Float> d(size_t(res.x) * size_t(res.y));
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            RGB rgb = PixelRGB(this->image, {x, y});
            d[size_t(y) * res.x + x] =
                Float((rgb.r + rgb.g + rgb.b) / 3 * PixelSolidAngle(screen, res, x, y, tanHalfFov));
        }
    distribution = PiecewiseConstant2D(d, res.x, res.y);
}

std::optional<Point2f> ProjectionLight::ScreenPoint(Vector3f w) const {
    if (w.z < kHither) return std::nullopt;
    Point2f s(w.x / (w.z * tanHalfFov), w.y / (w.z * tanHalfFov));
    if (s.x < screen.pMin.x || s.x > screen.pMax.x || s.y < screen.pMin.y || s.y > screen.pMax.y)
        return std::nullopt;
    return s;
}

Float ProjectionLight::SolidAnglePerScreenArea(Point2f s) const {
    return Sqr(tanHalfFov) * CosCubed(s, tanHalfFov);
}

SampledSpectrum ProjectionLight::I(Vector3f wProjector, const SampledWavelengths& lambda) const {
    std::optional<Point2f> s = ScreenPoint(wProjector);
    if (!s) return SampledSpectrum(0.f);
    Point2f uv = OffsetIn(screen, *s);
    Point2i res = image.Resolution();
    Point2i p(Clamp(int(uv.x * res.x), 0, res.x - 1), Clamp(int(uv.y * res.y), 0, res.y - 1));
    return scale * RGBIlluminantSpectrum(*colorSpace, PixelRGB(image, p)).Sample(lambda);
}

std::optional<LightLiSample> ProjectionLight::SampleLi(const LightSampleContext& ctx, Point2f,
                                                       const SampledWavelengths& lambda,
                                                       bool) const {
    Float d2 = DistanceSquared(position, ctx.p);
    if (d2 == 0) return {};
    Vector3f wi = (position - ctx.p) / std::sqrt(d2);
    SampledSpectrum Li = I(Normalize(renderFromProjector.ApplyInverse(-wi)), lambda) / d2;
    if (!Li) return {};
    return LightLiSample{Li, wi, 1, Interaction(position, Normal3f(), Point2f())};
}

std::optional<LightLeSample> ProjectionLight::SampleLe(Point2f u1, Point2f,
                                                       const SampledWavelengths& lambda) const {
    Float pdf = 0;
    Point2f uv = distribution.Sample(u1, &pdf);
    if (!(pdf > 0)) return {};
    Point2f s = LerpBounds(screen, uv);
    Vector3f w = Normalize(Vector3f(s.x * tanHalfFov, s.y * tanHalfFov, 1));
    SampledSpectrum L = I(w, lambda);
    if (!L) return {};
    Float pdfDir = pdf / (Area(screen) * SolidAnglePerScreenArea(s));
    return LightLeSample{L, Ray(position, Normalize(renderFromProjector(w))), std::nullopt, 1,
                         pdfDir};
}

LightLePDF ProjectionLight::PDF_Le(const Ray& ray) const {
    std::optional<Point2f> s = ScreenPoint(Normalize(renderFromProjector.ApplyInverse(ray.d)));
    if (!s) return {0, 0};
    return {0,
            distribution.PDF(OffsetIn(screen, *s)) / (Area(screen) * SolidAnglePerScreenArea(*s))};
}

SampledSpectrum ProjectionLight::Phi(const SampledWavelengths& lambda) const {
    Point2i res = image.Resolution();
    SampledSpectrum sum(0.f);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            sum += RGBIlluminantSpectrum(*colorSpace, PixelRGB(image, {x, y})).Sample(lambda) *
                   Float(PixelSolidAngle(screen, res, x, y, tanHalfFov));
    return scale * sum;
}

LightBounds ProjectionLight::Bounds() const {
    Vector3f corner =
        Normalize(Vector3f(screen.pMax.x * tanHalfFov, screen.pMax.y * tanHalfFov, 1));
    Vector3f axis = Normalize(renderFromProjector(Vector3f(0, 0, 1)));
    return LightBounds(Bounds3f(position), axis, 0, 1, corner.z, false);
}

}  // namespace kiln
