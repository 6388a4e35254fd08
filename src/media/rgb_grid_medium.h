// "rgbgrid" (pbrt-v4's RGBGridMedium): sigma_a, sigma_s and Le given per voxel as RGB over the
// box [p0, p1] of the medium's space. Majorants per voxel of a 16^3 grid.
#pragma once

#include "base/object_arena.h"
#include "base/transform.h"
#include "core/parser/diagnostics.h"
#include "media/majorant_grid.h"
#include "media/medium_emission.h"
#include "media/medium_parameters.h"
#include "media/sampled_grid.h"

namespace kiln {

class RGBGridMedium {
  public:
    // Absent coefficient grids are 1 everywhere (as pbrt-v4).
    RGBGridMedium(const Bounds3f& bounds, const Transform& renderFromMedium, Float g,
                  SampledGrid<Spectrum> sigma_a, SampledGrid<Spectrum> sigma_s, Float scale,
                  SampledGrid<Spectrum> Le, Float LeScale, MediumEmission thermal);
    // "rgb sigma_a", "rgb sigma_s", "rgb Le" (nx * ny * nz values each), "nx", "ny", "nz",
    // "p0", "p1", "scale", "Lescale", "g"; kiln's "temperature" and "emission".
    static RGBGridMedium* Create(const TextureParameterDictionary& params,
                                 const Transform& renderFromMedium,
                                 std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                                 ObjectArena& arena, Diagnostics& diag);

    bool IsEmissive() const { return (!Le.Empty() && LeScale > 0) || thermal.IsEmissive(); }
    bool IsUniform() const { return false; }
    MediumEmission& Emission() { return thermal; }
    MediumProperties SamplePoint(Point3f p, const SampledWavelengths& lambda) const;
    MajorantIterator SampleRay(const Ray& ray, Float tMax, const SampledWavelengths& lambda) const;
    // The render-space box holding the medium (nothing is outside it).
    Bounds3f RenderBounds() const { return renderFromMedium(bounds); }

  private:
    Bounds3f bounds;
    Transform renderFromMedium;
    Float g;
    SampledGrid<Spectrum> sigma_a, sigma_s, Le;
    Float scale, LeScale;
    MediumEmission thermal;
    MajorantGrid majorants;
};

}  // namespace kiln
