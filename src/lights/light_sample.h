// What every light shares: its type, the context of a light sample (the receiving point) and
// the incident-radiance sample a light returns (pbrt-v4's LightType, LightSampleContext and
// LightLiSample).
//
// Units: radiance in W m^-2 sr^-1 nm^-1 at each sampled wavelength; pdfs per steradian of
// incident direction at the receiving point (the sample pdf of a delta light is 1, a formal
// value that cancels against the delta distribution).
#pragma once

#include <optional>

#include "base/interaction.h"
#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// How a light's emission is distributed (pbrt-v4): delta in position (point, spot), delta in
// direction (distant), over a surface (area) or over all directions at infinity (infinite).
enum class LightType { DeltaPosition, DeltaDirection, Area, Infinite };

inline bool IsDeltaLight(LightType type) {
    return type == LightType::DeltaPosition || type == LightType::DeltaDirection;
}

// The point receiving light: render-space position, geometric normal n and shading normal ns
// (both zero for points in a medium).
struct LightSampleContext {
    Point3f p;
    Normal3f n, ns;

    LightSampleContext() = default;
    LightSampleContext(Point3f p, Normal3f n, Normal3f ns) : p(p), n(n), ns(ns) {}
    LightSampleContext(const SurfaceInteraction& si) : p(si.p), n(si.n), ns(si.shading.n) {}
    // A point with no surface (pbrt-v4 keeps only the position of a plain Interaction).
    LightSampleContext(const Interaction& intr) : p(intr.p) {}
};

// Incident radiance L arriving from direction wi (unit, pointing away from the receiving point
// towards the light), drawn with solid-angle density pdf; pLight is the point on the light (a
// point beyond the scene's bounding sphere for infinite and distant lights) for shadow rays.
// A sample drawn with Light::SampleLi may leave L to be evaluated later
// (deferredL, Light::DeferredL): for lights whose radiance costs a surface evaluation.
struct LightLiSample {
    SampledSpectrum L;
    Vector3f wi;
    Float pdf = 0;
    Interaction pLight;
    bool deferredL = false;
    // pbrt-v4 compatibility: the length of the direction pbrt-v4 would hand its integrator
    // unnormalised (1 but for image infinite lights under transforms that do not preserve
    // lengths: ImageInfiniteLight::SampleLi). pbrt-v4 evaluates the cosine and the BSDF's pdf
    // with that vector, so kiln's integrators scale both by it.
    Float wiLength = 1;
};

// A ray leaving a light (pbrt-v4's LightLeSample): radiance L carried along `ray` (unit
// direction), drawn with density pdfPos per m^2 of its origin (per unit area of the disk
// presented to the scene for lights at infinity and distant lights; 1 for point and spot
// lights, a formal value cancelling the delta distribution) and pdfDir per sr of its direction
// (1 for distant lights). intr: the point of an area light's surface the ray leaves.
struct LightLeSample {
    SampledSpectrum L;
    Ray ray;
    std::optional<Interaction> intr;
    Float pdfPos = 0, pdfDir = 0;
    // |cos| between w and the surface normal at the origin (1 for lights without a surface)
    Float AbsCosTheta(Vector3f w) const { return intr ? AbsDot(w, intr->n) : 1; }
};

// The densities PDF_Le reports, as in LightLeSample.
struct LightLePDF {
    Float pos = 0, dir = 0;
};

// A light chosen by a light sampler, by its index in the scene's light list.
struct SampledLight {
    int index;
    Float p;  // probability of choosing this light
};

}  // namespace kiln
