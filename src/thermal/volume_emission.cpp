#include "thermal/volume_emission.h"

#include "spectral/planck.h"

namespace kiln {

SampledSpectrum VolumeEmission(EmissionModel model, Float T, const SampledSpectrum* n,
                               SampledSpectrum& sigma_a, SampledSpectrum& sigma_s,
                               const SampledWavelengths& lambda) {
    if (!(T > 0) || model == EmissionModel::None) return SampledSpectrum(0.f);
    SampledSpectrum B = planck_radiance(lambda, T);
    if (n) B *= *n * *n;
    switch (model) {
        case EmissionModel::Kirchhoff:
            return sigma_a * B;
        case EmissionModel::Additive:
            return (sigma_a + sigma_s) * B;
        case EmissionModel::Diffuse:
            sigma_a += sigma_s;
            sigma_s = SampledSpectrum(0.f);
            return sigma_a * B;
        case EmissionModel::None:
            break;
    }
    return SampledSpectrum(0.f);
}

}  // namespace kiln
