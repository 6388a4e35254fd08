#include "lights/portal_infinite_light.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/sampling.h"
#include "base/sphere_mappings.h"
#include "spectral/color.h"

namespace kiln {

// PortalInfiniteLight construction
PortalInfiniteLight::PortalInfiniteLight(const Transform& renderFromLight,
                                         const Image& equalAreaImage,
                                         const RGBColorSpace* colorSpace, Float scale,
                                         const std::array<Point3f, 4>& portal)
    : portal(portal), colorSpace(colorSpace ? colorSpace : &RGBColorSpace::sRGB()), scale(scale) {
    Point2i res = equalAreaImage.Resolution();
    if (res.x != res.y || res.x == 0)
        throw std::invalid_argument(
            "an infinite light with a portal needs a square equal-area environment map, not " +
            std::to_string(res.x) + " x " + std::to_string(res.y) + " pixels");
    int r = equalAreaImage.ChannelIndex("R"), g = equalAreaImage.ChannelIndex("G"),
        b = equalAreaImage.ChannelIndex("B");
    if (r < 0 || g < 0 || b < 0)
        throw std::invalid_argument("the environment map must have R, G and B channels");
    // The portal's frame: x along corner 0 -> 3, y along 0 -> 1, z their normal (pbrt-v4)
    Vector3f p01 = portal[1] - portal[0], p03 = portal[3] - portal[0];
    if (!(Length(p01) > 0) || !(Length(p03) > 0) || !(Length(Cross(p03, p01)) > 0))
        throw std::invalid_argument("the portal's corners do not span a rectangle");
    Vector3f x = Normalize(p03), y = Normalize(p01);
    portalFrame = Frame(x, y, Cross(x, y));

    // The environment resampled over the portal's parameterisation, and the sampling density
    // in uv: radiance times solid angle per uv area
    image = Image(PixelFormat::Float, res, {"R", "G", "B"});
    std::vector<Float> density(size_t(res.x) * res.y);
    for (int py = 0; py < res.y; ++py)
        for (int px = 0; px < res.x; ++px) {
            Point2f uv((px + 0.5f) / res.x, (py + 0.5f) / res.y);
            Float dw_duv;
            Vector3f w = Normalize(renderFromLight.ApplyInverse(RenderFromImage(uv, &dw_duv)));
            Point2f st = EqualAreaSphereToSquare(w);
            Float sum = 0;
            int channel[3] = {r, g, b};
            for (int c = 0; c < 3; ++c) {
                Float v = std::max<Float>(
                    0, equalAreaImage.BilerpChannel(st, channel[c], WrapMode::OctahedralSphere));
                image.SetChannel({px, py}, c, v);
                sum += v;
            }
            density[size_t(py) * res.x + px] = sum / 3 * dw_duv;
        }
    distribution = WindowedPiecewiseConstant2D(density, res.x, res.y);
}

void PortalInfiniteLight::Preprocess(const Bounds3f& sceneBounds) const {
    sceneBounds.BoundingSphere(&sceneCenter, &sceneRadius);
}

// The portal parameterisation
std::optional<Point2f> PortalInfiniteLight::ImageFromRender(Vector3f wRender, Float* dw_duv) const {
    Vector3f w = portalFrame.ToLocal(wRender);
    if (!(w.z > 0)) return std::nullopt;
    if (dw_duv) *dw_duv = Sqr(Pi) * (Sqr(w.y) + Sqr(w.z)) * (Sqr(w.x) + Sqr(w.z)) / w.z;
    Float alpha = std::atan2(w.x, w.z), beta = std::atan2(w.y, w.z);
    return Point2f(Clamp((alpha + Pi / 2) / Pi, 0, 1), Clamp((beta + Pi / 2) / Pi, 0, 1));
}

Vector3f PortalInfiniteLight::RenderFromImage(Point2f uv, Float* dw_duv) const {
    Float alpha = -Pi / 2 + uv.x * Pi, beta = -Pi / 2 + uv.y * Pi;
    Vector3f w = Normalize(Vector3f(std::tan(alpha), std::tan(beta), 1));
    if (dw_duv) *dw_duv = Sqr(Pi) * (Sqr(w.y) + Sqr(w.z)) * (Sqr(w.x) + Sqr(w.z)) / w.z;
    return portalFrame.FromLocal(w);
}

std::optional<Bounds2f> PortalInfiniteLight::ImageBounds(Point3f p) const {
    std::optional<Point2f> a = ImageFromRender(Normalize(portal[0] - p));
    std::optional<Point2f> b = ImageFromRender(Normalize(portal[2] - p));
    if (!a || !b) return std::nullopt;
    return Bounds2f{Point2f(std::min(a->x, b->x), std::min(a->y, b->y)),
                    Point2f(std::max(a->x, b->x), std::max(a->y, b->y))};
}

// Radiance
SampledSpectrum PortalInfiniteLight::ImageLookup(Point2f uv,
                                                 const SampledWavelengths& lambda) const {
    RGB rgb;
    for (int c = 0; c < 3; ++c) rgb[c] = std::max<Float>(0, image.LookupNearestChannel(uv, c));
    return scale * RGBIlluminantSpectrum(*colorSpace, rgb).Sample(lambda);
}

SampledSpectrum PortalInfiniteLight::Le(const Ray& ray, const SampledWavelengths& lambda) const {
    std::optional<Point2f> uv = ImageFromRender(Normalize(ray.d));
    std::optional<Bounds2f> b = ImageBounds(ray.o);
    if (!uv || !b || uv->x < b->pMin.x || uv->x > b->pMax.x || uv->y < b->pMin.y ||
        uv->y > b->pMax.y)
        return SampledSpectrum(0);
    return ImageLookup(*uv, lambda);
}

// Sampling: directions through the portal only
std::optional<LightLiSample> PortalInfiniteLight::SampleLi(const LightSampleContext& ctx, Point2f u,
                                                           const SampledWavelengths& lambda,
                                                           bool) const {
    std::optional<Bounds2f> b = ImageBounds(ctx.p);
    if (!b) return std::nullopt;
    Float mapPDF = 0;
    std::optional<Point2f> uv = distribution.Sample(u, *b, &mapPDF);
    if (!uv) return std::nullopt;
    Float dw_duv;
    Vector3f wi = RenderFromImage(*uv, &dw_duv);
    // Grazing directions whose Jacobian rounds to 0 on the way back are not sampled, as
    // PDF_Li gives them density 0
    Float dwBack = 0;
    if (!(dw_duv > 0) || !ImageFromRender(wi, &dwBack) || !(dwBack > 0)) return std::nullopt;
    Point3f pOutside = ctx.p + wi * (2 * sceneRadius);
    return LightLiSample{ImageLookup(*uv, lambda), wi, mapPDF / dw_duv,
                         Interaction(pOutside, Normal3f(), Point2f())};
}

Float PortalInfiniteLight::PDF_Li(const LightSampleContext& ctx, Vector3f w, bool) const {
    Float dw_duv;
    std::optional<Point2f> uv = ImageFromRender(w, &dw_duv);
    if (!uv || !(dw_duv > 0)) return 0;
    std::optional<Bounds2f> b = ImageBounds(ctx.p);
    if (!b) return 0;
    return distribution.PDF(*uv, *b) / dw_duv;
}

// Light tracing
std::optional<LightLeSample> PortalInfiniteLight::SampleLe(Point2f u1, Point2f u2,
                                                           const SampledWavelengths& lambda) const {
    if (!(sceneRadius > 0)) return {};
    Float mapPDF = 0;
    std::optional<Point2f> uv =
        distribution.Sample(u1, Bounds2f{Point2f(0, 0), Point2f(1, 1)}, &mapPDF);
    if (!uv) return {};
    Float dw_duv;
    Vector3f w = -RenderFromImage(*uv, &dw_duv);
    Float dwBack = 0;  // (as in SampleLi)
    if (!(dw_duv > 0) || !ImageFromRender(-w, &dwBack) || !(dwBack > 0)) return {};
    Frame frame = Frame::FromZ(-w);
    Point2f cd = SampleUniformDiskConcentric(u2);
    Point3f pDisk = sceneCenter + sceneRadius * frame.FromLocal(Vector3f(cd.x, cd.y, 0));
    SampledSpectrum L = ImageLookup(*uv, lambda);
    if (!L) return {};
    return LightLeSample{L, Ray(pDisk - sceneRadius * w, w), std::nullopt,
                         1 / (Pi * Sqr(sceneRadius)), mapPDF / dw_duv};
}

LightLePDF PortalInfiniteLight::PDF_Le(const Ray& ray) const {
    Float dw_duv;
    std::optional<Point2f> uv = ImageFromRender(-Normalize(ray.d), &dw_duv);
    if (!uv || !(dw_duv > 0)) return {};
    return {1 / (Pi * Sqr(sceneRadius)),
            distribution.PDF(*uv, Bounds2f{Point2f(0, 0), Point2f(1, 1)}) / dw_duv};
}

// Power
SampledSpectrum PortalInfiniteLight::Phi(const SampledWavelengths& lambda) const {
    Point2i res = image.Resolution();
    SampledSpectrum sum(0);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            Float dw_duv;
            Vector3f w = portalFrame.ToLocal(
                RenderFromImage(Point2f((x + 0.5f) / res.x, (y + 0.5f) / res.y), &dw_duv));
            RGB rgb(image.GetChannel({x, y}, 0), image.GetChannel({x, y}, 1),
                    image.GetChannel({x, y}, 2));
            sum += RGBIlluminantSpectrum(*colorSpace, rgb).Sample(lambda) * (dw_duv * w.z);
        }
    Float area = Length(portal[1] - portal[0]) * Length(portal[3] - portal[0]);
    return scale * area * sum / (Float(res.x) * res.y);
}

}  // namespace kiln
