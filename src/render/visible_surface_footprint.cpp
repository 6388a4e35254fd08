#include "render/visible_surface_footprint.h"

#include <cmath>
#include <optional>

namespace kiln {

void SetCameraDifferentials(const Camera& camera, const CameraSample& sample, const Ray& ray,
                            const SampledWavelengths& lambda, Float scale, int samplesPerPixel,
                            VisibleSurface* vs) {
    const Vector3f n(vs->n);
    // Where the differential ray for a film offset meets the tangent plane (nullopt: no ray,
    // or one parallel to the plane)
    auto offset = [&](Vector2f dFilm) -> std::optional<Vector3f> {
        CameraSample s = sample;
        s.pFilm = Point2f(s.pFilm.x + dFilm.x, s.pFilm.y + dFilm.y);
        SampledWavelengths l = lambda;
        std::optional<CameraRay> r = camera.GenerateRay(s, l);
        if (!r) return std::nullopt;
        Point3f o = ray.o + scale * (r->ray.o - ray.o);
        Vector3f d = ray.d + scale * (r->ray.d - ray.d);
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
