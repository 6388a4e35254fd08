// "homogeneous" (pbrt-v4's HomogeneousMedium): the same coefficients everywhere.
#pragma once

#include <optional>

#include "base/object_arena.h"
#include "core/parser/diagnostics.h"
#include "media/majorant_grid.h"
#include "media/medium_emission.h"
#include "media/medium_parameters.h"

namespace kiln {

class HomogeneousMedium {
  public:
    HomogeneousMedium(const MediumCoefficients& c, MediumEmission emission)
        : sigma_a(c.sigma_a),
          sigma_s(c.sigma_s),
          scale(c.scale),
          g(c.g),
          emission(std::move(emission)) {}
    // "preset", "sigma_a", "sigma_s", "scale", "g", "Le", "Lescale"; kiln's "temperature"
    // and "emission".
    static HomogeneousMedium* Create(const TextureParameterDictionary& params,
                                     std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                                     ObjectArena& arena, Diagnostics& diag);

    bool IsEmissive() const { return emission.IsEmissive(); }
    bool IsUniform() const { return emission.IsUniform(); }
    MediumEmission& Emission() { return emission; }
    MediumProperties SamplePoint(Point3f p, const SampledWavelengths& lambda) const {
        MediumProperties mp{sigma_a.Sample(lambda) * scale, sigma_s.Sample(lambda) * scale, g, {}};
        emission.Apply(mp, p, p, lambda);
        return mp;
    }
    // ray: render space, unit direction.
    MajorantIterator SampleRay(const Ray&, Float tMax, const SampledWavelengths& lambda) const {
        return MajorantIterator(0, tMax, (sigma_a.Sample(lambda) + sigma_s.Sample(lambda)) * scale);
    }
    // Everywhere: where it is depends on the shapes bounding it.
    std::optional<Bounds3f> RenderBounds() const { return std::nullopt; }

  private:
    Spectrum sigma_a, sigma_s;
    Float scale, g;
    MediumEmission emission;
};

}  // namespace kiln
