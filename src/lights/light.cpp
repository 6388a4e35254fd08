#include "lights/light.h"

#include "spectral/cie.h"

namespace kiln {

SampledSpectrum Light::L(Point3f p, Normal3f n, Point2f uv, Vector3f w,
                         const SampledWavelengths& lambda) const {
    if (auto area = GetIf<DiffuseAreaLight>()) return area->L(p, n, uv, w, lambda);
#if KILN_THERMAL_EMISSION
    if (auto thermal = GetIf<ThermalAreaLight>()) return thermal->L(p, n, uv, w, lambda);
#endif
    return SampledSpectrum(0);
}

SampledSpectrum Light::Le(const Ray& ray, const SampledWavelengths& lambda) const {
    if (auto uniform = GetIf<UniformInfiniteLight>()) return uniform->Le(ray, lambda);
    if (auto image = GetIf<ImageInfiniteLight>()) return image->Le(ray, lambda);
    return SampledSpectrum(0);
}

Float EmissionLuminance(const Spectrum& s) { return SpectrumToPhotometric(s) / CIE_Y_integral; }

}  // namespace kiln
