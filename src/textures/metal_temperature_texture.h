// A named metal's eta or k at the surface's temperature (spectral/metal_temperature.h):
// "spectrum eta" "metal-W-eta" (and k) of a conductor become these textures for the metals with
// a temperature model. The temperature is the context's (TextureEvalContext::temperature,
// which the scene's shader sets for materials that use it; without one the named table), or
// one fixed by the material ("float opticaltemperature").
#pragma once

#include "spectral/metal_temperature.h"
#include "spectral/spectrum.h"
#include "textures/texture_eval_context.h"

namespace kiln {

class SpectrumMetalTemperatureTexture {
  public:
    enum class Part { Eta, K };
    // fixedTemperature: kelvin; 0 to follow the surface's
    SpectrumMetalTemperatureTexture(const MetalTemperatureTable* table, Part part,
                                    Float fixedTemperature = 0)
        : table(table), part(part), fixedTemperature(fixedTemperature) {}

    bool UsesFootprint() const { return false; }
    const MetalTemperatureTable& Table() const { return *table; }
    // Whether the value follows the surface's temperature (else it is fixed)
    bool FollowsSurface() const { return fixedTemperature == 0; }
    SampledSpectrum Evaluate(const TextureEvalContext& ctx,
                             const SampledWavelengths& lambda) const {
        const Float T = Temperature(ctx);
        if (!(T > table->RoomTemperature()))
            return (part == Part::Eta ? table->NamedEta() : table->NamedK()).Sample(lambda);
        SampledSpectrum eta, k;
        table->Evaluate(lambda, T, &eta, &k);
        return part == Part::Eta ? eta : k;
    }
    // eta and k at once (the eta and k textures of one material share table and temperature)
    void EvaluateBoth(const TextureEvalContext& ctx, const SampledWavelengths& lambda,
                      SampledSpectrum* eta, SampledSpectrum* k) const {
        table->Evaluate(lambda, Temperature(ctx), eta, k);
    }

  private:
    Float Temperature(const TextureEvalContext& ctx) const {
        return FollowsSurface() ? ctx.temperature : fixedTemperature;
    }

    const MetalTemperatureTable* table;
    Part part;
    Float fixedTemperature;
};

}  // namespace kiln
