// Projective cameras (pbrt-v4): perspective and orthographic, both with an optional thin lens.
//
// Raster space: pixels of the full image, (0,0) at the top-left corner, y down. Screen space:
// the image plane window ("screenwindow"), y up. Camera space: the camera at the origin
// looking down +z. Rays leave GenerateRay in render space with unit directions; times are
// mapped from [0,1) into [shutteropen, shutterclose].
#pragma once

#include <optional>

#include "base/sampling.h"
#include "base/transform.h"
#include "core/camera/camera_sample.h"
#include "core/camera/camera_transform.h"

namespace kiln {

// CameraBase: what every camera shares, and pbrt-v4's Approximate_dp_dxy.
class CameraBase {
  public:
    const CameraTransform& GetCameraTransform() const { return cameraTransform; }
    Float ShutterOpen() const { return shutterOpen; }
    Float ShutterClose() const { return shutterClose; }
    Float SampleTime(Float u) const { return Lerp(u, shutterOpen, shutterClose); }

    // Estimates dp/dx and dp/dy (render space, scene units per pixel) at the point p with
    // normal n, from the smallest ray differentials the camera produces anywhere on the film,
    // scaled by max(1/8, 1/sqrt(spp)) as in pbrt-v4.
    void Approximate_dp_dxy(Point3f p, Normal3f n, Float time, int samplesPerPixel, Vector3f* dpdx,
                            Vector3f* dpdy) const;

  protected:
    CameraBase(const CameraTransform& cameraTransform, Float shutterOpen, Float shutterClose)
        : cameraTransform(cameraTransform), shutterOpen(shutterOpen), shutterClose(shutterClose) {}

    // pbrt-v4's FindMinimumDifferentials for cameras whose differentials have no closed form:
    // at 512 film points along the diagonal (lens sample at the centre, time 1/2), finite
    // differences of camera.GenerateRay over a twentieth of a pixel in x and in y (the other
    // direction when that ray fails), per pixel; the shortest camera-space origin and
    // direction differentials found (directions as offsets in the frame of each ray).
    template <typename C>
    void FindMinimumDifferentials(const C& camera, Point2i fullResolution);

    CameraTransform cameraTransform;
    Float shutterOpen = 0, shutterClose = 1;
    // Camera-space minimum position and direction differentials (per pixel).
    Vector3f minPosDifferentialX, minPosDifferentialY;
    Vector3f minDirDifferentialX, minDirDifferentialY;
};

template <typename C>
void CameraBase::FindMinimumDifferentials(const C& camera, Point2i fullResolution) {
    const Vector3f inf(Infinity, Infinity, Infinity);
    minPosDifferentialX = minPosDifferentialY = minDirDifferentialX = minDirDifferentialY = inf;
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    const int n = 512;
    for (int i = 0; i < n; ++i) {
        CameraSample s;
        s.pFilm =
            Point2f(Float(i) / (n - 1) * fullResolution.x, Float(i) / (n - 1) * fullResolution.y);
        s.pLens = Point2f(0.5f, 0.5f);
        s.time = 0.5f;
        std::optional<CameraRay> cr = camera.GenerateRay(s, lambda);
        if (!cr) continue;
        const Ray& r = cr->ray;
        // Per-pixel origin and direction differentials along axis `axis` of the film
        auto shifted = [&](int axis, Vector3f* dO, Vector3f* dD) {
            for (Float eps : {0.05f, -0.05f}) {
                CameraSample sh = s;
                (axis == 0 ? sh.pFilm.x : sh.pFilm.y) += eps;
                if (std::optional<CameraRay> c = camera.GenerateRay(sh, lambda)) {
                    *dO = (c->ray.o - r.o) / eps;
                    *dD = (c->ray.d - r.d) / eps;
                    return true;
                }
            }
            return false;
        };
        Vector3f dOx, dDx, dOy, dDy;
        if (!shifted(0, &dOx, &dDx) || !shifted(1, &dOy, &dDy)) continue;
        const Transform cameraFromRender = cameraTransform.CameraFromRender(r.time);
        Vector3f dox = cameraFromRender(dOx), doy = cameraFromRender(dOy);
        if (Length(dox) < Length(minPosDifferentialX)) minPosDifferentialX = dox;
        if (Length(doy) < Length(minPosDifferentialY)) minPosDifferentialY = doy;
        Vector3f d = Normalize(r.d);
        Frame f = Frame::FromZ(d);
        Vector3f df = f.ToLocal(d);
        Vector3f dxf = Normalize(f.ToLocal(Normalize(r.d + dDx)));
        Vector3f dyf = Normalize(f.ToLocal(Normalize(r.d + dDy)));
        if (Length(dxf - df) < Length(minDirDifferentialX)) minDirDifferentialX = dxf - df;
        if (Length(dyf - df) < Length(minDirDifferentialY)) minDirDifferentialY = dyf - df;
    }
    // No ray at all: no footprint (Approximate_dp_dxy then gives zero derivatives)
    for (Vector3f* v :
         {&minPosDifferentialX, &minPosDifferentialY, &minDirDifferentialX, &minDirDifferentialY})
        if (*v == inf) *v = Vector3f(0, 0, 0);
}

// ProjectiveCamera: raster <-> screen <-> camera transformations and thin-lens parameters.
class ProjectiveCamera : public CameraBase {
  public:
    // screenWindow: image-plane extent in screen space; lensRadius and focalDistance in scene
    // units (lensRadius 0 is a pinhole).
    ProjectiveCamera(const CameraTransform& cameraTransform, Float shutterOpen, Float shutterClose,
                     const Transform& screenFromCamera, Bounds2f screenWindow,
                     Point2i fullResolution, Float lensRadius, Float focalDistance);

    const Transform& CameraFromRaster() const { return cameraFromRaster; }
    Float LensRadius() const { return lensRadius; }
    Float FocalDistance() const { return focalDistance; }

  protected:
    // Refocuses a camera-space ray through the lens point sampled from uLens (thin lens).
    void ApplyThinLens(Point2f uLens, Ray* ray) const;

    Transform screenFromCamera, cameraFromRaster, rasterFromScreen, screenFromRaster;
    Float lensRadius, focalDistance;
};

// PerspectiveCamera: fov (degrees) spans the shorter axis of the screen window.
class PerspectiveCamera : public ProjectiveCamera {
  public:
    PerspectiveCamera(const CameraTransform& cameraTransform, Float shutterOpen, Float shutterClose,
                      Float fov, Bounds2f screenWindow, Point2i fullResolution, Float lensRadius,
                      Float focalDistance);
    std::optional<CameraRay> GenerateRay(const CameraSample& sample,
                                         SampledWavelengths& lambda) const;

    // Light tracing (pbrt-v4's PerspectiveCamera::We, PDF_We, SampleWi). sampleBounds: the
    // raster area the film takes samples from (RGBFilm::SampleBounds); rays reaching the film
    // outside it carry no importance. Importance is normalised so that its integral over the
    // image plane at distance 1 (area A, the full image) and the lens (area pi r^2, 1 for a
    // pinhole) is 1: We = 1 / (A lensArea cos^4 theta), theta from the viewing direction.
    // We of a render-space ray leaving the lens (unit direction); *pRaster gets the film
    // position it reaches. The camera is placed where it is at ray.time.
    SampledSpectrum We(const Ray& ray, Bounds2f sampleBounds, Point2f* pRaster = nullptr) const;
    // Densities with which GenerateRay (film position uniform over the image, lens uniform)
    // produces ray: pos 1 / lensArea, dir 1 / (A cos^3 theta); zero outside sampleBounds.
    CameraPDF PDF_We(const Ray& ray, Bounds2f sampleBounds) const;
    // A point on the lens (uniform, from u) seen from pRef at `time`, with its importance
    // towards pRef.
    std::optional<CameraWiSample> SampleWi(Point3f pRef, Float time, Point2f u,
                                           Bounds2f sampleBounds) const;
    // The image plane's area at distance 1 in camera space (A above).
    Float ImagePlaneArea() const { return imagePlaneArea; }

  private:
    // cos theta of a render-space direction and the raster position it reaches; false if it
    // points away from the film's side
    bool RasterPosition(const Ray& ray, Float* cosTheta, Point2f* pRaster) const;
    Float LensArea() const { return lensRadius > 0 ? Pi * Sqr(lensRadius) : 1; }

    Vector3f dxCamera, dyCamera;  // camera-space film offsets of one pixel
    Float imagePlaneArea = 0;
};

// OrthographicCamera: parallel rays along +z; the screen window is in scene units.
class OrthographicCamera : public ProjectiveCamera {
  public:
    OrthographicCamera(const CameraTransform& cameraTransform, Float shutterOpen,
                       Float shutterClose, Bounds2f screenWindow, Point2i fullResolution,
                       Float lensRadius, Float focalDistance);
    std::optional<CameraRay> GenerateRay(const CameraSample& sample,
                                         SampledWavelengths& lambda) const;

  private:
    Vector3f dxCamera, dyCamera;
};

// Rotation taking unit vector `from` to unit vector `to` (Hughes & Moeller 1999).
Transform RotateFromTo(Vector3f from, Vector3f to);

}  // namespace kiln
