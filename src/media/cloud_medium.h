// "cloud" (pbrt-v4's CloudMedium): a procedural cloud of Perlin-noise density over the box
// [p0, p1] of the medium's space, thinning with height; "density", "wispiness", "frequency".
// One majorant, sigma_t, over the whole box (the density is at most 1).
#pragma once

#include "base/object_arena.h"
#include "base/transform.h"
#include "core/parser/diagnostics.h"
#include "media/majorant_grid.h"
#include "media/medium_emission.h"
#include "media/medium_parameters.h"

namespace kiln {

class CloudMedium {
  public:
    CloudMedium(const Bounds3f& bounds, const Transform& renderFromMedium,
                const MediumCoefficients& c, Float density, Float wispiness, Float frequency,
                MediumEmission thermal)
        : bounds(bounds),
          renderFromMedium(renderFromMedium),
          sigma_a(c.sigma_a),
          sigma_s(c.sigma_s),
          scale(c.scale),
          g(c.g),
          density(density),
          wispiness(wispiness),
          frequency(frequency),
          thermal(std::move(thermal)) {}
    static CloudMedium* Create(const TextureParameterDictionary& params,
                               const Transform& renderFromMedium,
                               std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                               ObjectArena& arena, Diagnostics& diag);

    bool IsEmissive() const { return thermal.IsEmissive(); }
    bool IsUniform() const { return false; }
    MediumEmission& Emission() { return thermal; }
    MediumProperties SamplePoint(Point3f p, const SampledWavelengths& lambda) const;
    MajorantIterator SampleRay(const Ray& ray, Float tMax, const SampledWavelengths& lambda) const;
    // The render-space box holding the medium (nothing is outside it).
    Bounds3f RenderBounds() const { return renderFromMedium(bounds); }

    // The density in [0, 1] at a point of the medium's space.
    Float Density(Point3f p) const;

  private:
    Bounds3f bounds;
    Transform renderFromMedium;
    Spectrum sigma_a, sigma_s;
    Float scale, g, density, wispiness, frequency;
    MediumEmission thermal;
};

}  // namespace kiln
