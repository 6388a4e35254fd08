#include "core/camera/spherical_camera.h"

#include <utility>

#include "base/sphere_mappings.h"

namespace kiln {

SphericalCamera::SphericalCamera(const CameraTransform& cameraTransform, Float shutterOpen,
                                 Float shutterClose, Point2i fullResolution, Mapping mapping)
    : CameraBase(cameraTransform, shutterOpen, shutterClose),
      fullResolution(fullResolution),
      mapping(mapping) {
    FindMinimumDifferentials(*this, fullResolution);
}

std::optional<CameraRay> SphericalCamera::GenerateRay(const CameraSample& sample,
                                                      SampledWavelengths& lambda) const {
    (void)lambda;
    Point2f uv(sample.pFilm.x / fullResolution.x, sample.pFilm.y / fullResolution.y);
    Vector3f dir;
    if (mapping == Mapping::Equirectangular) {
        Float theta = Pi * uv.y, phi = 2 * Pi * uv.x;
        dir = SphericalDirection(std::sin(theta), std::cos(theta), phi);
    } else
        dir = EqualAreaSquareToSphere(WrapEqualAreaSquare(uv));
    std::swap(dir.y, dir.z);
    Ray ray(Point3f(0, 0, 0), Normalize(dir), SampleTime(sample.time));
    return CameraRay{cameraTransform.RenderFromCamera(ray)};
}

}  // namespace kiln
