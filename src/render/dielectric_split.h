// Camera rays split at their first smooth dielectric (Integrator "bool splitdielectrics"): where
// a camera ray first meets a surface with specular reflection and specular transmission only,
// path and volpath trace the reflection as a branch of its own and the transmission on the
// path, each weighted by its Fresnel factor, rather than one of them chosen with probability
// R / (R + T) as pbrt-v4 does. A glow seen through glass is otherwise, sample by sample, the
// glow or the reflected surroundings. The branch splits no further.
#pragma once

#include <optional>

#include "materials/bxdfs/bsdf.h"
#include "render/scene.h"

namespace kiln {

// Whether a path at its vertex number depth (1: the camera ray's first surface) that may still
// branch splits at bsdf.
inline bool SplitsAt(const PathIntegratorSettings& settings, bool mayBranch, int depth,
                     const BSDF& bsdf) {
    return mayBranch && depth == 1 && settings.splitDielectrics && IsSmoothDielectric(bsdf.Flags());
}

// The two ways out of a smooth dielectric, each sampled alone (probability 1) with the same
// uniform samples: f / pdf is the Fresnel reflectance or transmittance of each.
template <typename Throughput>
struct DielectricSplit {
    std::optional<BSDFSampleOf<Throughput>> reflection, transmission;
};
template <typename Throughput>
DielectricSplit<Throughput> SplitDielectric(const BSDF& bsdf, Vector3f wo, Float u, Point2f u2) {
    DielectricSplit<Throughput> split;
    split.reflection = bsdf.Sample_f<Throughput>(wo, u, u2, TransportMode::Radiance,
                                                 BxDFReflTransFlags::Reflection);
    if (split.reflection && (split.reflection->pdf == 0 || !split.reflection->f))
        split.reflection.reset();
    split.transmission = bsdf.Sample_f<Throughput>(wo, u, u2, TransportMode::Radiance,
                                                   BxDFReflTransFlags::Transmission);
    return split;
}

}  // namespace kiln
