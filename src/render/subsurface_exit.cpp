#include "render/subsurface_exit.h"

#include "base/rng.h"

namespace kiln {

std::optional<SubsurfaceExit> SampleSubsurfaceExit(const Scene& scene,
                                                   const SubsurfaceMaterial& material,
                                                   const SurfaceInteraction& isect, Float time,
                                                   const SampledWavelengths& lambda,
                                                   Sampler& sampler) {
    TabulatedBSSRDF bssrdf = material.GetBSSRDF(MaterialEvalContext(isect), lambda);
    Float uc = sampler.Get1D();
    Point2f up = sampler.Get2D();
    std::optional<BSSRDFProbeSegment> probe = bssrdf.SampleSp(uc, up);
    if (!probe) return std::nullopt;
    RNG rng(Hash(sampler.Get1D()));
    std::optional<SurfaceInteraction> chosen;
    int hits = 0;
    Interaction base(probe->p0, Normal3f(), Point2f(), Vector3f(), time);
    for (int crossings = 0; crossings < kMaxProbeCrossings; ++crossings) {
        Ray r = base.SpawnRayTo(probe->p1);
        if (r.d == Vector3f(0, 0, 0)) break;
        std::optional<ShapeIntersection> si = scene.aggregate->Intersect(r, 1);
        if (!si) break;
        base = si->intr;
        if (si->intr.material != isect.material) continue;
        if (rng.UniformFloat() * Float(++hits) < 1) chosen = si->intr;
    }
    if (!chosen) return std::nullopt;
    SampledSpectrum Sp = bssrdf.Sp(chosen->p), pdf = bssrdf.PDF_Sp(chosen->p, chosen->n);
    if (!Sp || !pdf || pdf[0] == 0) return std::nullopt;
    SubsurfaceExit exit{*chosen, Sp * (Float(hits) / pdf[0]), pdf / pdf[0]};
    exit.intr.wo = Vector3f(exit.intr.shading.n);
    return exit;
}

}  // namespace kiln
