// Thin sheets in the integrators. A surface whose BSDF flags its transmission StraightThrough
// (a non-dispersive thindielectric: a bulb, a window pane) passes light without turning it, so
// the integrators' shadow rays cross it, attenuated by its transmittance (SheetTransmittance),
// and a path that goes straight through one keeps the vertex before it for MIS and counts no
// bounce (SampleSheet is drawn before the vertex counts): light sampling and BSDF sampling
// then cover the same paths.
#pragma once

#include <optional>

#include "core/camera/sampler.h"
#include "render/scene.h"

namespace kiln {

// What a thin sheet at intr (hit by a shadow ray travelling towards -intr.wo) lets through, or
// nothing when the surface there is not a sheet and blocks the ray.
template <typename Throughput>
std::optional<Throughput> SheetTransmittance(const Scene& scene, SurfaceInteraction& intr,
                                             const SampledWavelengths& lambda) {
    if (!intr.material || !intr.material->MayPassLightStraightThrough()) return std::nullopt;
    SampledWavelengths sheetLambda = lambda;  // a sheet terminates no wavelength
    BSDF sheet = scene.GetBSDF(intr, sheetLambda);
    if (!sheet || !IsStraightThrough(sheet.Flags())) return std::nullopt;
    std::optional<BSDFSampleOf<Throughput>> bs =
        sheet.Sample_f<Throughput>(intr.wo, 0.5f, Point2f(0.5f, 0.5f), TransportMode::Radiance,
                                   BxDFReflTransFlags::Transmission);
    if (!bs || !bs->IsStraightThrough() || bs->pdf == 0) return std::nullopt;
    return bs->f * (AbsDot(bs->wi, intr.shading.n) / bs->pdf);
}

// The BSDF sample of a path at a sheet: straight through (the caller multiplies the throughput
// by CrossingWeight and goes on from the same MIS vertex and depth) or a reflection (the
// vertex's bounce). Nothing: the path ends.
template <typename Throughput>
std::optional<BSDFSampleOf<Throughput>> SampleSheet(const BSDF& bsdf, Vector3f wo,
                                                    Sampler& sampler) {
    Float u = sampler.Get1D();
    std::optional<BSDFSampleOf<Throughput>> bs = bsdf.Sample_f<Throughput>(wo, u, sampler.Get2D());
    if (!bs || bs->pdf == 0 || !bs->f) return std::nullopt;
    return bs;
}

template <typename Throughput>
Throughput CrossingWeight(const BSDFSampleOf<Throughput>& bs, Normal3f ns) {
    return bs.f * (AbsDot(bs.wi, ns) / bs.pdf);
}

// A path or shadow ray through thousands of sheets is treated as blocked
constexpr int kMaxSheetCrossings = 1024;

}  // namespace kiln
