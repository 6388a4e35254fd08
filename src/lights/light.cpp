#include "lights/light.h"

#include "core/geometry/shape.h"
#include "spectral/cie.h"

namespace kiln {

std::optional<LightBounds> Light::Bounds(const SpectralRange& range) const {
    // The emitter's extent and normal cone; phi is filled in below
    std::optional<LightBounds> lb = Dispatch([&](auto l) -> std::optional<LightBounds> {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
        if constexpr (std::is_same_v<T, PointLight>) {
            return LightBounds(Bounds3f(l->Position()), Vector3f(0, 0, 1), 0, -1, 0, false);
        } else if constexpr (std::is_same_v<T, SpotLight> || std::is_same_v<T, GoniometricLight> ||
                             std::is_same_v<T, ProjectionLight>) {
            return l->Bounds();
        } else if constexpr (T::kType == LightType::Area) {
            auto [w, cosTheta] = l->GetShape().NormalBounds();
            return LightBounds(l->GetShape().Bounds(), w, 0, cosTheta, 0, l->TwoSided());
        } else {
            return std::nullopt;  // at infinity
        }
    });
    if (lb) lb->phi = Power(range);
    return lb;
}

std::optional<Light::ThermalOutput> Light::Thermal() const {
    return Dispatch([](auto l) -> std::optional<ThermalOutput> {
#if KILN_THERMAL_EMISSION
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
        if constexpr (std::is_same_v<T, ThermalAreaLight>) {
            if (l->MeanTemperature() > 0 && l->BandPower() > 0)
                return ThermalOutput{l->MeanTemperature(), l->BandPower()};
        }
#endif
        (void)l;
        return std::nullopt;
    });
}

Float Light::Power(const SpectralRange& range) const {
    SampledWavelengths lambda = range.Spread(0.5f);
    Float p = SafeDiv(Phi(lambda), lambda.PDF()).Average();
    return std::isfinite(p) && p > 0 ? p : 0;
}

Float EmissionLuminance(const Spectrum& s) { return SpectrumToPhotometric(s) / CIE_Y_integral; }

}  // namespace kiln
