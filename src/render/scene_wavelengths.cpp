#include "render/scene_wavelengths.h"

#include <cmath>
#include <map>
#include <vector>

#include "render/scene.h"
#include "render/scene_description.h"
#include "spectral/planck.h"

namespace kiln {

WavelengthDistribution CreateWavelengthDistribution(const Scene& scene, Float* visibleShare) {
    *visibleShare = 1;
    // A sensor's spectral response: in proportion to it, over 4096 bins of its band
    if (const ThermalSensor* sensor = scene.job->film->Thermal(); sensor && sensor->Response()) {
        constexpr int kResponseBins = 4096;
        const SpectralRange band = scene.spectralRange;
        const double width = (double(band.max) - band.min) / kResponseBins;
        std::vector<Float> means(kResponseBins);
        for (int i = 0; i < kResponseBins; ++i)
            means[size_t(i)] = Float(
                sensor->Response()->Integral(band.min + i * width, band.min + (i + 1) * width) /
                width);
        return WavelengthDistribution::Tabulated(means, band.min, band.max);
    }
    if (!scene.spectralRange.IsVisible())
        return WavelengthDistribution::Band(scene.spectralRange.min, scene.spectralRange.max);
    if (!scene.integrator.emissionWavelengths) return {};
    // Temperatures in bins 1 % wide, with their power over 360-830 nm (W), so that a mesh of a
    // million hot triangles costs one pass over its lights
    std::map<int, double> binPower;
    auto binOf = [](double T) { return int(std::lround(std::log(T) / std::log(1.01))); };
    // What a hostile scene can make of a temperature or power (0, negative, Inf, NaN): skipped
    auto usable = [](double T, double power) {
        return T > 0 && T < 1e30 && power > 0 && std::isfinite(power);
    };
    double lightPower = 0;
    bool others = false;
    for (const Light& light : scene.lights) {
        if (std::optional<Light::ThermalOutput> t = light.Thermal()) {
            if (!usable(t->temperature, t->bandPower)) continue;
            binPower[binOf(t->temperature)] += t->bandPower;
            lightPower += t->bandPower;
        } else {
            others = true;
        }
    }
    if (scene.features.volumetric) {
        std::vector<Float> mediumTemperatures;
        for (const Medium& m : scene.media) {
            if (!m.IsEmissive()) continue;
            if (std::optional<Float> T = m.EmissionTemperature()) {
                if (usable(*T, 1)) mediumTemperatures.push_back(*T);
            } else {
                others = true;
            }
        }
        double each = mediumTemperatures.empty()
                          ? 0
                          : (lightPower > 0 ? lightPower : double(mediumTemperatures.size())) /
                                double(mediumTemperatures.size());
        for (Float T : mediumTemperatures) binPower[binOf(T)] += each;
    }
    if (binPower.empty()) return {};
    // Each bin's spectrum scaled to its power over 360-830 nm
    std::vector<Float> emitted(WavelengthDistribution::kBins, 0.f);
    for (const auto& [bin, power] : binPower) {
        double T = std::pow(1.01, bin), visible = planck_band_radiance(Lambda_min, Lambda_max, T);
        if (!(power > 0) || !(visible > 0)) continue;
        for (int i = 0; i < WavelengthDistribution::kBins; ++i)
            emitted[size_t(i)] += Float(power * planck_radiance(Lambda_min + i + 0.5, T) / visible);
    }
    Float share = others ? 0.75f : 0.5f;
    WavelengthDistribution d(emitted, share);
    if (!d.IsVisible()) *visibleShare = share;
    return d;
}

void WarnOfColoursBeyondTheVisible(const SceneDescription& desc, const SpectralRange& range,
                                   Diagnostics& diag) {
    if (range.IsVisible()) return;
    FileLoc firstLoc;
    std::string firstWhat;
    int count = 0;
    auto found = [&](const FileLoc& loc, const std::string& what) {
        if (count++ == 0) firstLoc = loc, firstWhat = what;
    };
    auto look = [&](const ParameterDictionary& params) {
        for (const ParsedParameter& p : params.Parameters())
            if (p.type == "rgb") found(p.loc, "'rgb " + p.name + "'");
    };
    for (const SceneEntity& m : desc.materials) look(m.parameters);
    for (const auto& [name, m] : desc.namedMaterials) look(m.parameters);
    for (const auto& [name, t] : desc.spectrumTextures) {
        look(t.parameters);
        if (t.texName == "imagemap") found(t.loc, "the image map \"" + name + "\"");
    }
    if (count == 0) return;
    diag.Warn(firstLoc, "RGB colours say nothing beyond the visible: in this render of " +
                            std::to_string(int(range.min)) + "-" + std::to_string(int(range.max)) +
                            " nm, " + firstWhat +
                            (count > 1 ? " and " + std::to_string(count - 1) + " other RGB colours"
                                       : std::string()) +
                            " of materials and textures hold their values at 360 or 830 nm "
                            "(give spectra for infrared properties)");
}

}  // namespace kiln
