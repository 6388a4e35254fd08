// CameraTransform: the camera's placement and the choice of render space (pbrt-v4).
//
// kiln renders in pbrt-v4's default "cameraworld" space: world space translated so that the
// camera (at time 0) sits at the origin. Axes keep their world orientation, so lights and
// geometry stay axis-aligned while coordinates near the camera keep full float precision.
// Lengths are in scene units.
#pragma once

#include "base/transform.h"

namespace kiln {

class CameraTransform {
  public:
    CameraTransform() = default;
    // worldFromCamera: the inverse of the CTM at the Camera directive. Camera space is
    // pbrt's: the camera at the origin looking down +z, +y up, +x towards the image's right.
    explicit CameraTransform(const Transform& worldFromCamera);

    const Transform& RenderFromCamera() const { return renderFromCamera; }
    const Transform& CameraFromRender() const { return cameraFromRender; }
    const Transform& RenderFromWorld() const { return renderFromWorld; }
    Transform WorldFromRender() const { return Inverse(renderFromWorld); }
    Transform CameraFromWorld() const { return cameraFromRender * renderFromWorld; }

  private:
    Transform renderFromCamera, cameraFromRender, renderFromWorld;
};

inline CameraTransform::CameraTransform(const Transform& worldFromCamera) {
    Point3f pCamera = worldFromCamera(Point3f(0, 0, 0));
    renderFromWorld = Translate(-Vector3f(pCamera));
    renderFromCamera = renderFromWorld * worldFromCamera;
    cameraFromRender = Inverse(renderFromCamera);
}

}  // namespace kiln
