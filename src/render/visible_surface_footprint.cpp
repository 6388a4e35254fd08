#include "render/visible_surface_footprint.h"

#include <array>
#include <cmath>
#include <optional>

namespace kiln {

void SetCameraDifferentials(const Camera& camera, const CameraSample& sample, const Ray& ray,
                            const SampledWavelengths& lambda, Float scale, int samplesPerPixel,
                            VisibleSurface* vs) {
    const Vector3f n(vs->n);
    // The differential ray of a film direction (1, 0) or (0, 1): pbrt-v4's perspective and
    // orthographic cameras take the ray one pixel over; its other cameras the finite difference
    // over 0.05 pixel (or -0.05 where that gives no ray), extrapolated to one pixel
    const bool projective = camera.Is<PerspectiveCamera>() || camera.Is<OrthographicCamera>();
    auto differential = [&](Vector2f dir, Point3f* o, Vector3f* d) {
        const std::array<Float, 2> steps =
            projective ? std::array<Float, 2>{1, 0} : std::array<Float, 2>{0.05f, -0.05f};
        for (Float eps : steps) {
            if (eps == 0) break;
            CameraSample s = sample;
            s.pFilm = Point2f(s.pFilm.x + eps * dir.x, s.pFilm.y + eps * dir.y);
            SampledWavelengths l = lambda;
            if (std::optional<CameraRay> r = camera.GenerateRay(s, l)) {
                *o = ray.o + (r->ray.o - ray.o) / eps;
                *d = ray.d + (r->ray.d - ray.d) / eps;
                return true;
            }
        }
        return false;
    };
    // Where the differential ray, scaled, meets the tangent plane (nullopt: no ray, or one
    // parallel to the plane)
    auto offset = [&](Vector2f dir) -> std::optional<Vector3f> {
        Point3f rxo;
        Vector3f rxd;
        if (!differential(dir, &rxo, &rxd)) return std::nullopt;
        Point3f o = ray.o + scale * (rxo - ray.o);
        Vector3f d = ray.d + scale * (rxd - ray.d);
        Float denom = Dot(n, d);
        if (denom == 0) return std::nullopt;
        Float t = Dot(n, vs->p - o) / denom;
        Vector3f dp = (o + t * d) - vs->p;
        if (!(std::isfinite(dp.x) && std::isfinite(dp.y) && std::isfinite(dp.z)))
            return std::nullopt;
        return dp;
    };
    std::optional<Vector3f> dx = offset(Vector2f(1, 0)), dy = offset(Vector2f(0, 1));
    if (dx && dy) {
        vs->dpdx = *dx;
        vs->dpdy = *dy;
    } else {
        camera.Approximate_dp_dxy(vs->p, vs->n, sample.time, samplesPerPixel, &vs->dpdx, &vs->dpdy);
    }
}

}  // namespace kiln
