#include "media/medium_emission.h"

#include <algorithm>
#include <cmath>

#include "spectral/cie.h"
#include "spectral/planck.h"
#include "textures/texture_eval_context.h"
#include "thermal/volume_emission.h"

namespace kiln {

MediumEmission MediumEmission::Radiance(Spectrum Le, SampledGrid<Float> LeScale) {
    MediumEmission e;
    e.kind = Kind::Radiance;
    e.Le = Le;
    e.LeScale = std::move(LeScale);
    return e;
}

MediumEmission MediumEmission::NormalizedBlackbody(SampledGrid<Float> temperature, Float offset,
                                                   Float scale, SampledGrid<Float> LeScale,
                                                   Float LeFactor) {
    MediumEmission e;
    e.kind = Kind::NormalizedBlackbody;
    e.temperatureGrid = std::move(temperature);
    e.temperatureOffset = offset;
    e.temperatureScale = scale;
    e.LeScale = std::move(LeScale);
    e.LeFactor = LeFactor;
    return e;
}

MediumEmission MediumEmission::Thermal(FloatTexture temperature, EmissionModel model) {
    MediumEmission e;
    e.kind = model == EmissionModel::None ? Kind::None : Kind::Thermal;
    e.temperatureTexture = temperature;
    e.model = model;
    return e;
}

MediumEmission MediumEmission::Thermal(SampledGrid<Float> temperature, Float offset, Float scale,
                                       EmissionModel model) {
    MediumEmission e;
    e.kind = model == EmissionModel::None ? Kind::None : Kind::Thermal;
    e.temperatureGrid = std::move(temperature);
    e.temperatureOffset = offset;
    e.temperatureScale = scale;
    e.model = model;
    return e;
}

bool MediumEmission::IsUniform() const {
    switch (kind) {
        case Kind::None:
            return true;
        case Kind::Radiance:
            return LeScale.Empty();
        case Kind::NormalizedBlackbody:
            return false;
        case Kind::Thermal:
            return temperatureTexture && temperatureTexture->ConstantValue().has_value();
    }
    return false;
}

std::optional<Float> MediumEmission::RepresentativeTemperature() const {
    if (kind != Kind::Thermal) return std::nullopt;
    if (temperatureTexture) {
        std::optional<Float> T = temperatureTexture->ConstantValue();
        return T && *T > 0 ? T : std::nullopt;
    }
    // At most 32 voxels per axis, evenly strided
    auto stride = [](int n) { return std::max(1, n / 32); };
    int sx = stride(temperatureGrid.XSize()), sy = stride(temperatureGrid.YSize()),
        sz = stride(temperatureGrid.ZSize());
    double weighted = 0, weights = 0;
    for (int z = 0; z < temperatureGrid.ZSize(); z += sz)
        for (int y = 0; y < temperatureGrid.YSize(); y += sy)
            for (int x = 0; x < temperatureGrid.XSize(); x += sx) {
                double T =
                    (double(temperatureGrid.At(x, y, z)) - temperatureOffset) * temperatureScale;
                if (!(T > 0) || !std::isfinite(T)) continue;
                double w = planck_band_radiance(Lambda_min, Lambda_max, T);
                if (!std::isfinite(w * T)) continue;  // hostile grid values
                weighted += w * T;
                weights += w;
            }
    Float T = Float(weighted / weights);
    if (!(T > 0) || !std::isfinite(T)) return std::nullopt;
    return T;
}

void MediumEmission::Apply(MediumProperties& mp, Point3f pRender, Point3f pUnit,
                           const SampledWavelengths& lambda) const {
    switch (kind) {
        case Kind::None:
            return;
        case Kind::Radiance: {
            Float scale = LeScale.Empty() ? 1 : LeScale.Lookup(pUnit);
            if (scale > 0) mp.emission = mp.sigma_a * (scale * Le->Sample(lambda));
            return;
        }
        case Kind::NormalizedBlackbody: {
            Float scale = LeFactor * (LeScale.Empty() ? 1 : LeScale.Lookup(pUnit));
            Float T = (temperatureGrid.Lookup(pUnit) - temperatureOffset) * temperatureScale;
            if (scale <= 0 || !(T > 100)) return;
            SampledSpectrum B = planck_radiance_normalized(lambda, T) * CIE_Y_integral;
            mp.emission = mp.sigma_a * (scale * B);
            return;
        }
        case Kind::Thermal:
            break;
    }
    Float T;
    if (temperatureTexture) {
        TextureEvalContext ctx;
        ctx.p = pRender;
        T = temperatureTexture->Evaluate(ctx);
    } else {
        T = (temperatureGrid.Lookup(pUnit) - temperatureOffset) * temperatureScale;
    }
    if (!(T > 0)) return;  // 0 K, and NaN from a hostile texture, emit nothing
    std::optional<SampledSpectrum> n;
    if (eta) n = eta->Sample(lambda);
    mp.emission = VolumeEmission(model, T, n ? &*n : nullptr, mp.sigma_a, mp.sigma_s, lambda);
}

}  // namespace kiln
