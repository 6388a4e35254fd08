// Bidirectional path tracing (pbrt-v4's BDPTIntegrator), surfaces only, unpolarised.
//
// Per pixel sample: a camera subpath (up to maxdepth + 2 vertices, the camera's included) and
// a light subpath (up to maxdepth + 1, from a light chosen by power, PowerLightSampler, as
// pbrt-v4 does whatever "lightsampler" says) are traced as random walks without Russian
// roulette; every strategy (s light vertices, t camera vertices) with path length
// s + t - 2 <= maxdepth is evaluated: s = 0 (the camera path found emission), s = 1 (a light
// sampled from the camera path's end, SampleLi), t = 1 (the light path's end connected to a
// point sampled on the lens, splatted to the film where it lands) and the general
// connections. Each is weighted by pbrt-v4's MISWeight: the balance heuristic over all
// strategies that could have produced the path, in the rescaled form 1 / (1 + sum r_i), with
// the correction for cropped films of pbrt-v4's issue 347 (light tracing from a crop has fewer
// paths per pixel: its splats are scaled by the full image's area over the area sampled, the
// crop's and, with spread reconstruction, its margin, and its density in the heuristic by the
// inverse; pbrt-v4 gets the latter wrong for t = 1, see MISWeight).
//
// kiln specifics: emission found by the camera path is the scene's SurfaceLe (thermal emission
// from the hit's own BSDF, as PathIntegrator); hot shapes are lights (ThermalAreaLight) whose
// light subpaths start with their Kirchhoff emission at the sampled point
// (Light::SampleLe with the job's shader). A surface that emits but is no light (only the s = 0
// strategy can find it) keeps all of its emission. Only the perspective camera can be
// sampled (as pbrt-v4); scene creation falls back to volpath otherwise, for media and for
// polarised renders (scene_create.cpp).
#pragma once

#include <vector>

#include "core/camera/sampler.h"
#include "lights/light_sampler.h"
#include "render/bdpt_vertex.h"
#include "render/radiance.h"
#include "render/scene.h"

namespace kiln {

class BDPTIntegrator {
  public:
    using Radiance = UnpolarizedRadiance;

    // scene.camera must be a PerspectiveCamera and the film must have splats enabled.
    BDPTIntegrator(const Scene& scene, PathIntegratorSettings settings);

    // The sum of the strategies with t >= 2 for the camera ray `ray`; the t = 1 strategies are
    // splatted to the job's film (RGBFilm::AddSplat, scaled by 1 / spp on output).
    SampledSpectrum Li(Ray ray, SampledWavelengths& lambda, Sampler& sampler,
                       VisibleSurface* visibleSurface) const;

  private:
    int CameraSubpath(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler,
                      BDPTVertex* path, VisibleSurface* visibleSurface) const;
    // The light subpath at the camera ray's time.
    int LightSubpath(SampledWavelengths& lambda, Sampler& sampler, BDPTVertex* path,
                     Float time) const;
    int RandomWalk(SampledWavelengths& lambda, Ray ray, Sampler& sampler, SampledSpectrum beta,
                   Float pdf, int maxDepth, TransportMode mode, BDPTVertex* path,
                   VisibleSurface* visibleSurface) const;
    SampledSpectrum Connect(SampledWavelengths& lambda, BDPTVertex* lightVertices,
                            BDPTVertex* cameraVertices, int s, int t, Sampler& sampler,
                            Point2f* pRaster) const;
    Float MISWeight(BDPTVertex* lightVertices, BDPTVertex* cameraVertices, BDPTVertex& sampled,
                    int s, int t) const;

    // Vertex densities (pbrt-v4's Vertex::PDF, PDFLight, PDFLightOrigin)
    Float PDF(const BDPTVertex& v, const BDPTVertex* prev, const BDPTVertex& next) const;
    Float PDFLight(const BDPTVertex& v, const BDPTVertex& next) const;
    Float PDFLightOrigin(const BDPTVertex& v, const BDPTVertex& next) const;
    Float InfiniteLightDensity(Vector3f w) const;
    // Emission of a light vertex towards v
    SampledSpectrum Le(const BDPTVertex& light, const BDPTVertex& v,
                       const SampledWavelengths& lambda) const;
    // 1 if nothing blocks the segment between the two points, else 0
    bool Unoccluded(const Interaction& a, const Interaction& b) const;
    // The light of a light vertex or of a surface-light vertex
    const Light& LightOf(const BDPTVertex& v) const {
        return scene.lights[size_t(v.type == BDPTVertexType::Light ? v.light : v.si.lightIndex)];
    }
    int LightIndexOf(const BDPTVertex& v) const {
        return v.type == BDPTVertexType::Light ? v.light : v.si.lightIndex;
    }

    const Scene& scene;
    PathIntegratorSettings settings;
    const PerspectiveCamera* camera;
    RGBFilm* film;
    Bounds2f sampleBounds;
    // full image area / area of the pixels sampled (RGBFilm::SpreadPixelBounds; pbrt-v4 issue
    // 347)
    Float splatScale;
    Float sceneRadius = 0;
    PowerLightSampler lightSampler;
};

}  // namespace kiln
