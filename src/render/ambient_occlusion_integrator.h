// Ambient occlusion (pbrt-v4's AOIntegrator, Integrator "ambientocclusion"): at a camera ray's
// first surface (interface surfaces are passed through) one direction of the hemisphere about
// the geometric normal facing the ray, cosine-weighted ("cossample", default) or uniform; if no
// surface lies within "maxdistance" along it, the film's white: its colour space's illuminant
// (as pbrt-v4: the film's, not the Integrator directive's) at unit luminance, weighted by cos theta
// / (pi pdf), so that an unoccluded point renders luminance 1 and an occluded fraction of the
// hemisphere darkens it. Media, lights and thermal emission play no part (as in pbrt-v4).
#pragma once

#include "base/sampling.h"
#include "core/camera/sampler.h"
#include "render/radiance.h"
#include "render/scene.h"
#include "spectral/color.h"

namespace kiln {

class AmbientOcclusionIntegrator {
  public:
    using Radiance = UnpolarizedRadiance;

    AmbientOcclusionIntegrator(const Scene& scene, const PathIntegratorSettings& settings)
        : scene(scene),
          settings(*settings.ambientOcclusion),
          illuminant(scene.job->film->ColorSpace()->Illuminant()),
          illuminantScale(1 / EmissionLuminance(Spectrum(illuminant))) {}

    SampledSpectrum Li(Ray ray, SampledWavelengths& lambda, Sampler& sampler,
                       VisibleSurface* visibleSurface) const {
        while (true) {
            std::optional<ShapeIntersection> si = scene.aggregate->Intersect(ray, Infinity);
            if (!si) return SampledSpectrum(0.f);
            SurfaceInteraction& isect = si->intr;
            BSDF bsdf = scene.GetBSDF(isect, lambda);
            if (!bsdf) {
                ray = isect.SpawnRay(ray.d);
                continue;
            }
            if (visibleSurface) *visibleSurface = scene.MakeVisibleSurface(isect, bsdf, lambda);
            // A direction about the normal facing the ray
            Normal3f n = FaceForward(isect.n, -ray.d);
            Point2f u = sampler.Get2D();
            Vector3f wi =
                settings.cosSample ? SampleCosineHemisphere(u) : SampleUniformHemisphere(u);
            Float pdf =
                settings.cosSample ? CosineHemispherePDF(std::abs(wi.z)) : UniformHemispherePDF();
            if (pdf == 0) return SampledSpectrum(0.f);
            wi = Frame::FromZ(Vector3f(n)).FromLocal(wi);
            if (scene.aggregate->IntersectP(isect.SpawnRay(wi), settings.maxDistance))
                return SampledSpectrum(0.f);
            return illuminantScale * illuminant.Sample(lambda) *
                   (Dot(wi, Vector3f(n)) / (Pi * pdf));
        }
    }

  private:
    const Scene& scene;
    PathIntegratorSettings::AmbientOcclusion settings;
    const DenselySampledSpectrum& illuminant;
    Float illuminantScale;
};

}  // namespace kiln
