#include "lights/image_infinite_light.h"

#include <stdexcept>
#include <vector>

#include "base/sphere_mappings.h"
#include "spectral/color.h"

namespace kiln {

namespace {

// The RGB of pixel p, negative values clamped to zero.
RGB PixelRGB(const Image& image, Point2i p) {
    return RGB(std::max<Float>(0, image.GetChannel(p, 0)),
               std::max<Float>(0, image.GetChannel(p, 1)),
               std::max<Float>(0, image.GetChannel(p, 2)));
}

}  // namespace

// ImageInfiniteLight construction
ImageInfiniteLight::ImageInfiniteLight(const Transform& renderFromLight, const Image& im,
                                       const RGBColorSpace* colorSpace, Float scale,
                                       const std::string& filename)
    : renderFromLight(renderFromLight),
      colorSpace(colorSpace ? colorSpace : &RGBColorSpace::sRGB()),
      scale(scale) {
    // Does the transform keep directions unit length (a rotation, in either direction)?
    preservesLengths = true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            Vector3f a(i == 0, i == 1, i == 2), b(j == 0, j == 1, j == 2);
            Float expected = i == j ? 1 : 0;
            if (std::abs(Dot(renderFromLight(a), renderFromLight(b)) - expected) > 1e-4f ||
                std::abs(Dot(renderFromLight.ApplyInverse(a), renderFromLight.ApplyInverse(b)) -
                         expected) > 1e-4f)
                preservesLengths = false;
        }
    // Keep the R, G, B channels only
    if (im.ChannelIndex("R") < 0 || im.ChannelIndex("G") < 0 || im.ChannelIndex("B") < 0)
        throw std::invalid_argument(filename +
                                    ": image used for an infinite light must have R, G and B "
                                    "channels");
    image = im.SelectChannels({"R", "G", "B"});

    // The mapping follows the image's shape
    Point2i res = image.Resolution();
    if (res.x > 0 && res.x == res.y) {
        mapping = EnvironmentMapping::EqualAreaOctahedral;
        wrapMode = WrapMode::OctahedralSphere;
    } else if (res.y > 0 && res.x == 2 * res.y) {
        mapping = EnvironmentMapping::Equirectangular;
        wrapMode = WrapMode::Clamp;
    } else {
        throw std::invalid_argument(filename + ": image resolution (" + std::to_string(res.x) +
                                    ", " + std::to_string(res.y) +
                                    ") is neither square (equal-area octahedral map) nor 2:1 "
                                    "(equirectangular map)");
    }

    // Radiance per unit st area at each pixel: channel average times the solid angle per unit
    // st at the pixel centre (constant for the equal-area map)
    int nu = res.x, nv = res.y;
    std::vector<Float> L(size_t(nu) * nv), d(size_t(nu) * nv), jac(nv);
    for (int y = 0; y < nv; ++y) {
        Point2f st(0.5f, (y + 0.5f) / nv);
        jac[y] = SolidAnglePerUnitST(DirectionFromST(st));
        for (int x = 0; x < nu; ++x) {
            RGB rgb = PixelRGB(image, {x, y});
            L[size_t(y) * nu + x] = (rgb.r + rgb.g + rgb.b) / 3;
            d[size_t(y) * nu + x] = L[size_t(y) * nu + x] * jac[y];
        }
    }
    distribution = PiecewiseConstant2D(d, nu, nv);

    // Compensated distribution (pbrt-v4): radiance above the solid-angle mean only
    double sumL = 0, sumJ = 0;
    for (int y = 0; y < nv; ++y)
        for (int x = 0; x < nu; ++x) {
            sumL += double(L[size_t(y) * nu + x]) * jac[y];
            sumJ += jac[y];
        }
    Float average = sumJ > 0 ? Float(sumL / sumJ) : 0;
    bool allZero = true;
    for (int y = 0; y < nv; ++y)
        for (int x = 0; x < nu; ++x) {
            Float v = std::max<Float>(L[size_t(y) * nu + x] - average, 0) * jac[y];
            d[size_t(y) * nu + x] = v;
            allZero &= (v == 0);
        }
    if (allZero)
        for (int y = 0; y < nv; ++y)
            for (int x = 0; x < nu; ++x) d[size_t(y) * nu + x] = jac[y];
    compensatedDistribution = PiecewiseConstant2D(d, nu, nv);
}

// Mappings
Vector3f ImageInfiniteLight::DirectionFromST(Point2f st) const {
    return mapping == EnvironmentMapping::EqualAreaOctahedral ? EqualAreaSquareToSphere(st)
                                                              : EquirectSquareToSphere(st);
}

Point2f ImageInfiniteLight::STFromDirection(Vector3f w) const {
    return mapping == EnvironmentMapping::EqualAreaOctahedral ? EqualAreaSphereToSquare(w)
                                                              : EquirectSphereToSquare(w);
}

Float ImageInfiniteLight::SolidAnglePerUnitST(Vector3f w) const {
    if (mapping == EnvironmentMapping::EqualAreaOctahedral) return 4 * Pi;
    // sin theta from x and y: accurate near the poles, where 1 - z^2 cancels
    return 2 * Pi * Pi * std::min<Float>(1, std::sqrt(Sqr(w.x) + Sqr(w.y)));
}

// Radiance
SampledSpectrum ImageInfiniteLight::ImageLe(Point2f st, const SampledWavelengths& lambda) const {
    Point2i res = image.Resolution();
    Point2i p(int(std::floor(st.x * res.x)), int(std::floor(st.y * res.y)));
    if (!RemapPixelCoords(&p, res, wrapMode)) return SampledSpectrum(0);
    RGB rgb = PixelRGB(image, p);
    return scale * RGBIlluminantSpectrum(*colorSpace, rgb).Sample(lambda);
}

SampledSpectrum ImageInfiniteLight::Le(const Ray& ray, const SampledWavelengths& lambda) const {
    Vector3f wLight = Normalize(renderFromLight.ApplyInverse(ray.d));
    return ImageLe(STFromDirection(wLight), lambda);
}

// Sampling
std::optional<LightLiSample> ImageInfiniteLight::SampleLi(const LightSampleContext& ctx, Point2f u,
                                                          const SampledWavelengths& lambda,
                                                          bool allowIncompletePDF) const {
    Float mapPDF = 0;
    Point2f st = allowIncompletePDF ? compensatedDistribution.Sample(u, &mapPDF)
                                    : distribution.Sample(u, &mapPDF);
    if (mapPDF == 0) return {};

    // Direction and its density per steradian
    Vector3f wLight = DirectionFromST(st);
    Float dOmega = SolidAnglePerUnitST(wLight);
    if (dOmega == 0) return {};
    // pbrt-v4 hands the integrator renderFromLight(wLight) unnormalised, so that under a
    // transform that does not preserve lengths (a scale, or a projective ConcatTransform whose
    // upper 3x3 in render space is no rotation) its light samples weigh the BSDF's cosine by
    // the vector's length; kiln renders such scenes as pbrt-v4 does by scaling L by it.
    Vector3f wRender = renderFromLight(wLight);
    Float length = Length(wRender);
    if (!(length > 0) || !std::isfinite(length)) return {};
    Vector3f wi = wRender / length;
    Float pdf = mapPDF / dOmega;

    Point3f pOutside = ctx.p + wi * (2 * sceneRadius);
    LightLiSample ls{ImageLe(st, lambda), wi, pdf, Interaction(pOutside, Normal3f(), Point2f())};
    ls.wiLength = length;
    return ls;
}

Float ImageInfiniteLight::PDF_Li(const LightSampleContext&, Vector3f w,
                                 bool allowIncompletePDF) const {
    // pbrt-v4 maps the transformed direction to its equal-area square without normalising it
    // (the same direction where the transform preserves lengths); kiln does the same
    Vector3f wLight = renderFromLight.ApplyInverse(w);
    if (mapping != EnvironmentMapping::EqualAreaOctahedral) wLight = Normalize(wLight);
    Float dOmega = SolidAnglePerUnitST(wLight);
    if (dOmega == 0) return 0;
    Point2f st = STFromDirection(wLight);
    Float pdf = allowIncompletePDF ? compensatedDistribution.PDF(st) : distribution.PDF(st);
    return pdf / dOmega;
}

std::optional<LightLeSample> ImageInfiniteLight::SampleLe(Point2f u1, Point2f u2,
                                                          const SampledWavelengths& lambda) const {
    if (!(sceneRadius > 0)) return {};
    Float mapPDF = 0;
    Point2f st = distribution.Sample(u1, &mapPDF);
    if (mapPDF == 0) return {};
    Vector3f wLight = DirectionFromST(st);
    Float dOmega = SolidAnglePerUnitST(wLight);
    if (dOmega == 0) return {};
    Vector3f w = -Normalize(renderFromLight(wLight));
    Frame frame = Frame::FromZ(-w);
    Point2f cd = SampleUniformDiskConcentric(u2);
    Point3f pDisk = sceneCenter + sceneRadius * frame.FromLocal(Vector3f(cd.x, cd.y, 0));
    SampledSpectrum L = ImageLe(st, lambda);
    if (!L) return {};
    return LightLeSample{L, Ray(pDisk - sceneRadius * w, w), std::nullopt,
                         1 / (Pi * Sqr(sceneRadius)), mapPDF / dOmega};
}

LightLePDF ImageInfiniteLight::PDF_Le(const Ray& ray) const {
    Vector3f wLight = -Normalize(renderFromLight.ApplyInverse(ray.d));
    Float dOmega = SolidAnglePerUnitST(wLight);
    if (dOmega == 0) return {};
    return {1 / (Pi * Sqr(sceneRadius)), distribution.PDF(STFromDirection(wLight)) / dOmega};
}

// Power: pi r^2 times the integral of L over the sphere (sum of L times each pixel's exact
// solid angle)
SampledSpectrum ImageInfiniteLight::Phi(const SampledWavelengths& lambda) const {
    Point2i res = image.Resolution();
    SampledSpectrum sum(0);
    for (int y = 0; y < res.y; ++y) {
        Float pixelSolidAngle;
        if (mapping == EnvironmentMapping::EqualAreaOctahedral)
            pixelSolidAngle = 4 * Pi / (Float(res.x) * res.y);
        else
            pixelSolidAngle =
                2 * Pi / res.x * (std::cos(Pi * y / res.y) - std::cos(Pi * (y + 1) / res.y));
        SampledSpectrum rowSum(0);
        for (int x = 0; x < res.x; ++x)
            rowSum += RGBIlluminantSpectrum(*colorSpace, PixelRGB(image, {x, y})).Sample(lambda);
        sum += pixelSolidAngle * rowSum;
    }
    return Pi * Sqr(sceneRadius) * scale * sum;
}

void ImageInfiniteLight::Preprocess(const Bounds3f& sceneBounds) const {
    sceneBounds.BoundingSphere(&sceneCenter, &sceneRadius);
}

}  // namespace kiln
