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

    CameraTransform cameraTransform;
    Float shutterOpen = 0, shutterClose = 1;
    // Camera-space minimum position and direction differentials (per pixel).
    Vector3f minPosDifferentialX, minPosDifferentialY;
    Vector3f minDirDifferentialX, minDirDifferentialY;
};

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
    // position it reaches.
    SampledSpectrum We(const Ray& ray, Bounds2f sampleBounds, Point2f* pRaster = nullptr) const;
    // Densities with which GenerateRay (film position uniform over the image, lens uniform)
    // produces ray: pos 1 / lensArea, dir 1 / (A cos^3 theta); zero outside sampleBounds.
    CameraPDF PDF_We(const Ray& ray, Bounds2f sampleBounds) const;
    // A point on the lens (uniform, from u) seen from pRef, with its importance towards pRef.
    std::optional<CameraWiSample> SampleWi(Point3f pRef, Point2f u, Bounds2f sampleBounds) const;
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
