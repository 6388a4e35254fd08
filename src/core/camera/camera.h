// Camera: the closed set of cameras (pbrt-v4's Camera interface; light tracing (We, PDF_We,
// SampleWi) only for PerspectiveCamera, as in pbrt-v4).
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "base/closed_set.h"
#include "base/object_arena.h"
#include "core/camera/camera_sample.h"
#include "core/camera/camera_transform.h"
#include "core/camera/projective_cameras.h"
#include "core/camera/realistic_camera.h"
#include "core/camera/spherical_camera.h"
#include "core/parser/diagnostics.h"
#include "core/parser/file_loc.h"

namespace kiln {

class ParameterDictionary;

class Camera : public ClosedSet<const PerspectiveCamera*, const OrthographicCamera*,
                                const SphericalCamera*, const RealisticCamera*> {
  public:
    using ClosedSet::ClosedSet;
    // A render-space ray with unit direction for the film position, lens sample and time of
    // `sample`; nullopt if the camera cannot produce one.
    std::optional<CameraRay> GenerateRay(const CameraSample& sample,
                                         SampledWavelengths& lambda) const {
        return Dispatch([&](auto c) { return c->GenerateRay(sample, lambda); });
    }
    const CameraTransform& GetCameraTransform() const {
        return Dispatch([](auto c) -> const CameraTransform& { return c->GetCameraTransform(); });
    }
    // Shutter interval (pbrt-v4 "shutteropen" 0, "shutterclose" 1), in scene time units.
    Float ShutterOpen() const {
        return Dispatch([](auto c) { return c->ShutterOpen(); });
    }
    Float ShutterClose() const {
        return Dispatch([](auto c) { return c->ShutterClose(); });
    }
    // Screen-space derivatives (render space, per pixel) of a point p with normal n seen by
    // the camera, for texture filtering (pbrt-v4 Approximate_dp_dxy).
    void Approximate_dp_dxy(Point3f p, Normal3f n, Float time, int samplesPerPixel, Vector3f* dpdx,
                            Vector3f* dpdy) const {
        Dispatch([&](auto c) { c->Approximate_dp_dxy(p, n, time, samplesPerPixel, dpdx, dpdy); });
    }

    // "perspective" (fov 90, lensradius 0, focaldistance 1e6, frameaspectratio, screenwindow),
    // "orthographic" (lensradius, focaldistance, frameaspectratio, screenwindow), "spherical"
    // (mapping "equalarea" or "equirectangular"; lensradius, focaldistance, frameaspectratio
    // and screenwindow are read and ignored, as pbrt-v4) or "realistic" (lensfile, resolved
    // against the scene file's directory; aperturediameter 1 mm; focusdistance 10 m;
    // aperture: "gaussian", "square", "pentagon", "star" or an image file); common
    // "shutteropen" 0 and "shutterclose" 1. Other names and bad values: SceneError.
    // fullResolution is the film's full (uncropped) resolution in pixels, filmDiagonal the
    // film's "diagonal" in metres (the realistic camera's film size).
    static Camera Create(const std::string& name, const ParameterDictionary& params,
                         const CameraTransform& cameraTransform, Point2i fullResolution,
                         Float filmDiagonal, const FileLoc& loc, ObjectArena& arena,
                         Diagnostics& diag);
};

}  // namespace kiln
