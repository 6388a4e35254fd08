// pbrt-v4's "hair" material: HairBxDF (bxdfs/hair_bxdf.h) on curves.
#pragma once

#include <optional>

#include "materials/bxdfs/hair_bxdf.h"
#include "materials/material_base.h"
#include "textures/texture.h"

namespace kiln {

class TextureParameterDictionary;

// The fibre's absorption comes from "sigma_a" (per unit diameter), else "reflectance" (the
// colour after multiple scattering), else "eumelanin" / "pheomelanin" concentrations; with none
// of them, eumelanin 1.3 (brown hair). "eta" (1.55), "beta_m" and "beta_n" (0.3, raised to at
// least 0.01) and "alpha" (2 degrees) as pbrt-v4. The offset across the fibre is h = 2 v - 1,
// v the curve's coordinate across its width.
class HairMaterial : public MaterialBase {
  public:
    struct Params {
        std::optional<SpectrumTexture> sigma_a, reflectance;
        std::optional<FloatTexture> eumelanin, pheomelanin;
        FloatTexture eta, beta_m, beta_n, alpha;
    };
    explicit HairMaterial(Params p) : p(std::move(p)) {}
    HairBxDF GetBxDF(const MaterialEvalContext& ctx, const SampledWavelengths& lambda) const;
    const Params& Parameters() const { return p; }

    // Reads the parameters above (warning when more than one source of absorption is given).
    static HairMaterial* Create(const TextureParameterDictionary& params, ObjectArena& arena,
                                Diagnostics& diag);

  private:
    Params p;
};

}  // namespace kiln
