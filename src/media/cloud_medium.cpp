#include "media/cloud_medium.h"

#include <cmath>

#include "textures/noise.h"

namespace kiln {

Float CloudMedium::Density(Point3f p) const {
    // Domain warping by the noise gradient (wisps), then five octaves of noise
    Point3f pp = frequency * p;
    if (wispiness > 0) {
        Float vomega = 0.05f * wispiness, vlambda = 10;
        for (int i = 0; i < 2; ++i) {
            pp += vomega * DNoise(vlambda * pp);
            vomega *= 0.5f;
            vlambda *= 1.99f;
        }
    }
    Float d = 0, omega = 0.5f, lambda = 1;
    for (int i = 0; i < 5; ++i) {
        d += omega * Noise(lambda * pp);
        omega *= 0.5f;
        lambda *= 1.99f;
    }
    // Thinning with height, and a dense base below y = 0.5
    d = Clamp((1 - p.y) * 4.5f * density * d, 0, 1);
    d += 2 * std::max<Float>(0, 0.5f - p.y);
    return Clamp(d, 0, 1);
}

MediumProperties CloudMedium::SamplePoint(Point3f p, const SampledWavelengths& lambda) const {
    Point3f pm = renderFromMedium.ApplyInverse(p);
    Float d = scale * Density(pm);
    MediumProperties mp{sigma_a.Sample(lambda) * d, sigma_s.Sample(lambda) * d, g, {}};
    thermal.Apply(mp, p, pm, lambda);
    return mp;
}

MajorantIterator CloudMedium::SampleRay(const Ray& ray, Float tMax,
                                        const SampledWavelengths& lambda) const {
    std::optional<MediumRaySegment> r = RayInMedium(renderFromMedium, bounds, ray, tMax);
    if (!r) return {};
    return MajorantIterator(r->tMin, r->tMax,
                            (sigma_a.Sample(lambda) + sigma_s.Sample(lambda)) * scale);
}

CloudMedium* CloudMedium::Create(const TextureParameterDictionary& params,
                                 const Transform& renderFromMedium,
                                 std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                                 ObjectArena& arena, Diagnostics& diag) {
    MediumCoefficients c = ReadMediumCoefficients(params, loc, diag);
    CheckExtinction(c, 1, params, loc);  // (its density is at most 1)
    Float density = params.GetOneFloat("density", 1);
    Float wispiness = params.GetOneFloat("wispiness", 1);
    Float frequency = params.GetOneFloat("frequency", 5);
    for (auto [name, v] : {std::pair{"density", density}, std::pair{"wispiness", wispiness},
                           std::pair{"frequency", frequency}})
        if (!std::isfinite(v))
            throw SceneError(params.Loc(name), std::string("cloud \"") + name + "\" must be finite",
                             std::to_string(v));
    std::optional<MediumEmission> thermal = ReadMediumThermalEmission(params, modelOverride, arena);
    return arena.New<CloudMedium>(ReadGridBounds(params, loc), renderFromMedium, c, density,
                                  wispiness, frequency,
                                  thermal ? std::move(*thermal) : MediumEmission());
}

}  // namespace kiln
