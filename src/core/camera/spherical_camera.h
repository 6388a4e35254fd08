// SphericalCamera (pbrt-v4): the whole sphere of directions around the camera's origin laid on
// the film, by the equal-area octahedral mapping (pbrt-v4's default, the layout of its
// environment maps) or the equirectangular one.
#pragma once

#include <optional>

#include "core/camera/camera_sample.h"
#include "core/camera/projective_cameras.h"

namespace kiln {

class SphericalCamera : public CameraBase {
  public:
    enum class Mapping { EqualArea, Equirectangular };

    SphericalCamera(const CameraTransform& cameraTransform, Float shutterOpen, Float shutterClose,
                    Point2i fullResolution, Mapping mapping);

    // With uv the film position over the full resolution ([0,1]^2, v down the image):
    // equirectangular: theta = pi v from camera +y, phi = 2 pi u from camera +x towards +z;
    // equal area: EqualAreaSquareToSphere of WrapEqualAreaSquare(uv) with the mapping's z axis
    // along camera +y (pbrt-v4 swaps y and z). Rays start at the camera's origin.
    std::optional<CameraRay> GenerateRay(const CameraSample& sample,
                                         SampledWavelengths& lambda) const;
    Mapping GetMapping() const { return mapping; }

  private:
    Point2i fullResolution;
    Mapping mapping;
};

}  // namespace kiln
