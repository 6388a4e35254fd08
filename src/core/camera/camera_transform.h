// CameraTransform: the camera's placement and the choice of render space (pbrt-v4).
//
// kiln renders in pbrt-v4's default "cameraworld" space: world space translated so that the
// camera sits at the origin (for a moving camera, where it is halfway through its
// TransformTimes interval, as pbrt-v4). Axes keep their world orientation, so lights and
// geometry stay axis-aligned while coordinates near the camera keep full float precision.
// Lengths are in scene units.
#pragma once

#include "base/animated_transform.h"
#include "base/transform.h"

namespace kiln {

class CameraTransform {
  public:
    CameraTransform() = default;
    // worldFromCamera: the inverse of the CTM at the Camera directive (its start and end
    // transforms for a moving camera). Camera space is pbrt's: the camera at the origin
    // looking down +z, +y up, +x towards the image's right.
    explicit CameraTransform(const Transform& worldFromCamera)
        : CameraTransform(AnimatedTransform(worldFromCamera)) {}
    explicit CameraTransform(const AnimatedTransform& worldFromCamera);

    // The camera at the start of its motion (the only placement of a camera that does not move)
    const Transform& RenderFromCamera() const { return renderFromCamera; }
    const Transform& CameraFromRender() const { return cameraFromRender; }
    const Transform& RenderFromWorld() const { return renderFromWorld; }
    Transform WorldFromRender() const { return Inverse(renderFromWorld); }
    Transform CameraFromWorld() const { return cameraFromRender * renderFromWorld; }

    // The camera at scene time `time` (Ray::time)
    bool IsAnimated() const { return motion.IsAnimated(); }
    Transform RenderFromCamera(Float time) const {
        return motion.IsAnimated() ? motion.Interpolate(time) : renderFromCamera;
    }
    Transform CameraFromRender(Float time) const {
        return motion.IsAnimated() ? Inverse(motion.Interpolate(time)) : cameraFromRender;
    }
    // A camera-space ray to render space at the ray's time
    Ray RenderFromCamera(const Ray& r) const {
        return motion.IsAnimated() ? motion(r) : renderFromCamera(r);
    }

  private:
    Transform renderFromCamera, cameraFromRender, renderFromWorld;
    AnimatedTransform motion;  // renderFromCamera over time
};

inline CameraTransform::CameraTransform(const AnimatedTransform& worldFromCamera) {
    Float tMid = (worldFromCamera.StartTime() + worldFromCamera.EndTime()) / 2;
    Point3f pCamera = worldFromCamera.Interpolate(tMid)(Point3f(0, 0, 0));
    renderFromWorld = Translate(-Vector3f(pCamera));
    renderFromCamera = renderFromWorld * worldFromCamera.Start();
    cameraFromRender = Inverse(renderFromCamera);
    motion = AnimatedTransform(renderFromCamera, worldFromCamera.StartTime(),
                               renderFromWorld * worldFromCamera.End(), worldFromCamera.EndTime());
}

}  // namespace kiln
