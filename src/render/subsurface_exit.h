// Where a path that enters a "subsurface" material leaves it: pbrt-v4's BSSRDF sampling (a
// probe segment from TabulatedBSSRDF::SampleSp intersected with the scene, one of its hits on
// the same material chosen uniformly), with the estimator's factors for volpath.
#pragma once

#include <optional>

#include "base/interaction.h"
#include "core/camera/sampler.h"
#include "materials/subsurface_material.h"
#include "render/scene.h"

namespace kiln {

// An exit point and its factors: weight = Sp / (p_choice pdf_hero) and r_u's factor
// pdf / pdf_hero (spectral MIS over the wavelengths' exit densities, pbrt-v4)
struct SubsurfaceExit {
    SurfaceInteraction intr;  // wo: the shading normal (the exit BxDF's outside)
    SampledSpectrum weight, r_uFactor;
};

// The probe's hits on material (isect's) are candidates, chosen uniformly by weighted
// reservoir sampling with unit weights; a probe through more than kMaxProbeCrossings surfaces
// stops there. nullopt where the probe finds none or Sp or its density is zero.
std::optional<SubsurfaceExit> SampleSubsurfaceExit(const Scene& scene,
                                                   const SubsurfaceMaterial& material,
                                                   const SurfaceInteraction& isect, Float time,
                                                   const SampledWavelengths& lambda,
                                                   Sampler& sampler);
inline constexpr int kMaxProbeCrossings = 1024;

}  // namespace kiln
