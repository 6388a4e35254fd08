// Projective cameras: raster transforms, ray generation and minimum ray differentials.
#include "core/camera/projective_cameras.h"

namespace kiln {

// Rotation between unit vectors, by composing two reflections (Hughes & Moeller 1999).
Transform RotateFromTo(Vector3f from, Vector3f to) {
    Vector3f refl;
    if (std::abs(from.x) < 0.72f && std::abs(to.x) < 0.72f)
        refl = Vector3f(1, 0, 0);
    else if (std::abs(from.y) < 0.72f && std::abs(to.y) < 0.72f)
        refl = Vector3f(0, 1, 0);
    else
        refl = Vector3f(0, 0, 1);
    Vector3f u = refl - from, v = refl - to;
    Float uu = Dot(u, u), vv = Dot(v, v), uv = Dot(u, v);
    SquareMatrix4 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = ((i == j) ? 1 : 0) - 2 / uu * u[i] * u[j] - 2 / vv * v[i] * v[j] +
                        4 * uv / (uu * vv) * v[i] * u[j];
    return Transform(r, r.Transposed());
}

// CameraBase
void CameraBase::Approximate_dp_dxy(Point3f p, Normal3f n, Float time, int samplesPerPixel,
                                    Vector3f* dpdx, Vector3f* dpdy) const {
    // Tangent plane of p in a camera space rotated so that p lies on +z.
    const Transform cameraFromRender = cameraTransform.CameraFromRender(time);
    Point3f pCamera = cameraFromRender(p);
    Vector3f toP = Vector3f(pCamera);
    if (LengthSquared(toP) == 0) {
        *dpdx = *dpdy = Vector3f(0, 0, 0);
        return;
    }
    Transform downZFromCamera = RotateFromTo(Normalize(toP), Vector3f(0, 0, 1));
    Point3f pDownZ = downZFromCamera(pCamera);
    Normal3f nDownZ = downZFromCamera(cameraFromRender(n));
    Float d = nDownZ.z * pDownZ.z;

    // Intersect the smallest differential rays with that plane.
    auto hit = [&](Vector3f dPos, Vector3f dDir) {
        Ray r(Point3f(0, 0, 0) + dPos, Vector3f(0, 0, 1) + dDir);
        Float denom = Dot(nDownZ, r.d);
        Float t = denom != 0 ? -(Dot(nDownZ, Vector3f(r.o)) - d) / denom : 0;
        return r(t);
    };
    Point3f px = hit(minPosDifferentialX, minDirDifferentialX);
    Point3f py = hit(minPosDifferentialY, minDirDifferentialY);

    Float sppScale = std::max<Float>(0.125f, 1 / std::sqrt(Float(std::max(1, samplesPerPixel))));
    const Transform renderFromCamera = cameraTransform.RenderFromCamera(time);
    *dpdx = sppScale * renderFromCamera(downZFromCamera.ApplyInverse(px - pDownZ));
    *dpdy = sppScale * renderFromCamera(downZFromCamera.ApplyInverse(py - pDownZ));
}

// ProjectiveCamera
ProjectiveCamera::ProjectiveCamera(const CameraTransform& cameraTransform, Float shutterOpen,
                                   Float shutterClose, const Transform& screenFromCamera,
                                   Bounds2f screenWindow, Point2i fullResolution, Float lensRadius,
                                   Float focalDistance)
    : CameraBase(cameraTransform, shutterOpen, shutterClose),
      screenFromCamera(screenFromCamera),
      lensRadius(lensRadius),
      focalDistance(focalDistance) {
    // Screen window -> NDC [0,1]^2 (y flipped) -> raster pixels.
    Transform ndcFromScreen = Scale(1 / (screenWindow.pMax.x - screenWindow.pMin.x),
                                    1 / (screenWindow.pMax.y - screenWindow.pMin.y), 1) *
                              Translate(Vector3f(-screenWindow.pMin.x, -screenWindow.pMax.y, 0));
    Transform rasterFromNDC = Scale(Float(fullResolution.x), -Float(fullResolution.y), 1);
    rasterFromScreen = rasterFromNDC * ndcFromScreen;
    screenFromRaster = Inverse(rasterFromScreen);
    cameraFromRaster = Inverse(screenFromCamera) * screenFromRaster;
}

void ProjectiveCamera::ApplyThinLens(Point2f uLens, Ray* ray) const {
    if (lensRadius <= 0) return;
    Point2f pLens = lensRadius * SampleUniformDiskConcentric(uLens);
    // The ray through the lens centre defines the in-focus point on the plane z = focal.
    Float ft = focalDistance / ray->d.z;
    Point3f pFocus = (*ray)(ft);
    ray->o = Point3f(pLens.x, pLens.y, 0);
    ray->d = Normalize(pFocus - ray->o);
}

// PerspectiveCamera
PerspectiveCamera::PerspectiveCamera(const CameraTransform& cameraTransform, Float shutterOpen,
                                     Float shutterClose, Float fov, Bounds2f screenWindow,
                                     Point2i fullResolution, Float lensRadius, Float focalDistance)
    : ProjectiveCamera(cameraTransform, shutterOpen, shutterClose, Perspective(fov, 1e-2f, 1000.f),
                       screenWindow, fullResolution, lensRadius, focalDistance) {
    dxCamera = cameraFromRaster(Point3f(1, 0, 0)) - cameraFromRaster(Point3f(0, 0, 0));
    dyCamera = cameraFromRaster(Point3f(0, 1, 0)) - cameraFromRaster(Point3f(0, 0, 0));

    // Area of the full image on the plane z = 1
    Point3f pMin = cameraFromRaster(Point3f(0, 0, 0));
    Point3f pMax = cameraFromRaster(Point3f(fullResolution.x, fullResolution.y, 0));
    pMin = Point3f(pMin.x / pMin.z, pMin.y / pMin.z, 1);
    pMax = Point3f(pMax.x / pMax.z, pMax.y / pMax.z, 1);
    imagePlaneArea = std::abs((pMax.x - pMin.x) * (pMax.y - pMin.y));

    // Minimum differentials along the film diagonal (pbrt-v4 FindMinimumDifferentials); all
    // rays through the lens centre start at the origin, so position differentials vanish.
    minPosDifferentialX = minPosDifferentialY = Vector3f(0, 0, 0);
    minDirDifferentialX = minDirDifferentialY = Vector3f(Infinity, Infinity, Infinity);
    const int n = 512;
    for (int i = 0; i < n; ++i) {
        Point3f pFilm(Float(i) / (n - 1) * fullResolution.x, Float(i) / (n - 1) * fullResolution.y,
                      0);
        Point3f pCamera = cameraFromRaster(pFilm);
        Vector3f d = Normalize(Vector3f(pCamera));
        Frame f = Frame::FromZ(d);
        Vector3f df = f.ToLocal(d);
        Vector3f dxf = Normalize(f.ToLocal(Normalize(Vector3f(pCamera) + dxCamera)));
        Vector3f dyf = Normalize(f.ToLocal(Normalize(Vector3f(pCamera) + dyCamera)));
        if (Length(dxf - df) < Length(minDirDifferentialX)) minDirDifferentialX = dxf - df;
        if (Length(dyf - df) < Length(minDirDifferentialY)) minDirDifferentialY = dyf - df;
    }
}

std::optional<CameraRay> PerspectiveCamera::GenerateRay(const CameraSample& sample,
                                                        SampledWavelengths& lambda) const {
    (void)lambda;
    Point3f pCamera = cameraFromRaster(Point3f(sample.pFilm.x, sample.pFilm.y, 0));
    Ray ray(Point3f(0, 0, 0), Normalize(Vector3f(pCamera)), SampleTime(sample.time));
    ApplyThinLens(sample.pLens, &ray);
    return CameraRay{cameraTransform.RenderFromCamera(ray)};
}

namespace {
// Whether p lies in b, edges included (pbrt-v4's Inside)
bool Inside(Point2f p, const Bounds2f& b) {
    return p.x >= b.pMin.x && p.x <= b.pMax.x && p.y >= b.pMin.y && p.y <= b.pMax.y;
}
}  // namespace

bool PerspectiveCamera::RasterPosition(const Ray& ray, Float* cosTheta, Point2f* pRaster) const {
    const Transform cameraFromRender = cameraTransform.CameraFromRender(ray.time);
    Vector3f dCamera = cameraFromRender(ray.d);
    Float len = Length(dCamera);
    if (!(len > 0)) return false;
    *cosTheta = dCamera.z / len;
    if (!(*cosTheta > 0)) return false;
    // The ray's point on the plane of focus (z = 1 for a pinhole): its film position
    Point3f oCamera = cameraFromRender(ray.o);
    Float zFocus = lensRadius > 0 ? focalDistance : 1;
    Point3f pFocus = oCamera + dCamera * ((zFocus - oCamera.z) / dCamera.z);
    Point3f pRaster3 = (rasterFromScreen * screenFromCamera)(pFocus);
    *pRaster = Point2f(pRaster3.x, pRaster3.y);
    return true;
}

SampledSpectrum PerspectiveCamera::We(const Ray& ray, Bounds2f sampleBounds,
                                      Point2f* pRasterOut) const {
    Float cosTheta;
    Point2f pRaster;
    if (!RasterPosition(ray, &cosTheta, &pRaster)) return SampledSpectrum(0);
    if (pRasterOut) *pRasterOut = pRaster;
    if (!Inside(pRaster, sampleBounds)) return SampledSpectrum(0);
    return SampledSpectrum(1 / (imagePlaneArea * LensArea() * Sqr(Sqr(cosTheta))));
}

CameraPDF PerspectiveCamera::PDF_We(const Ray& ray, Bounds2f sampleBounds) const {
    Float cosTheta;
    Point2f pRaster;
    if (!RasterPosition(ray, &cosTheta, &pRaster) || !Inside(pRaster, sampleBounds)) return {};
    return {1 / LensArea(), 1 / (imagePlaneArea * cosTheta * cosTheta * cosTheta)};
}

std::optional<CameraWiSample> PerspectiveCamera::SampleWi(Point3f pRef, Float time, Point2f u,
                                                          Bounds2f sampleBounds) const {
    Point2f pLens = lensRadius * SampleUniformDiskConcentric(u);
    const Transform renderFromCamera = cameraTransform.RenderFromCamera(time);
    Point3f pLensRender = renderFromCamera(Point3f(pLens.x, pLens.y, 0));
    Normal3f nLens = Normalize(renderFromCamera(Normal3f(0, 0, 1)));
    Vector3f wi = pLensRender - pRef;
    Float dist = Length(wi);
    if (!(dist > 0)) return {};
    wi = wi / dist;
    Float cosLens = AbsDot(nLens, wi);
    if (cosLens == 0) return {};
    Float pdf = dist * dist / (cosLens * LensArea());
    Point2f pRaster;
    SampledSpectrum Wi = We(Ray(pLensRender, -wi, time), sampleBounds, &pRaster);
    if (!Wi) return {};
    return CameraWiSample{Wi, wi, pdf, pRaster, pRef, pLensRender, nLens};
}

// OrthographicCamera
OrthographicCamera::OrthographicCamera(const CameraTransform& cameraTransform, Float shutterOpen,
                                       Float shutterClose, Bounds2f screenWindow,
                                       Point2i fullResolution, Float lensRadius,
                                       Float focalDistance)
    : ProjectiveCamera(cameraTransform, shutterOpen, shutterClose, Orthographic(0, 1), screenWindow,
                       fullResolution, lensRadius, focalDistance) {
    dxCamera = cameraFromRaster(Vector3f(1, 0, 0));
    dyCamera = cameraFromRaster(Vector3f(0, 1, 0));
    minDirDifferentialX = minDirDifferentialY = Vector3f(0, 0, 0);
    minPosDifferentialX = dxCamera;
    minPosDifferentialY = dyCamera;
}

std::optional<CameraRay> OrthographicCamera::GenerateRay(const CameraSample& sample,
                                                         SampledWavelengths& lambda) const {
    (void)lambda;
    Point3f pCamera = cameraFromRaster(Point3f(sample.pFilm.x, sample.pFilm.y, 0));
    Ray ray(pCamera, Vector3f(0, 0, 1), SampleTime(sample.time));
    if (lensRadius > 0) {
        // As pbrt-v4: the lens is centred on the camera axis, focusing this film point.
        ApplyThinLens(sample.pLens, &ray);
    }
    return CameraRay{cameraTransform.RenderFromCamera(ray)};
}

}  // namespace kiln
