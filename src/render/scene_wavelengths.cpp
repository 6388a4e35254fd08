#include "render/scene_wavelengths.h"

#include <cmath>
#include <map>
#include <vector>

#include "render/scene.h"
#include "render/scene_description.h"
#include "spectral/planck.h"

namespace kiln {

namespace {

// The temperatures of the scene's hot matter in bins 1 % wide, with their power over the
// scene's band (W), so that a mesh of a million hot triangles costs one pass over its lights;
// *others: whether anything else emits or an emissive medium's temperature varies
std::map<int, double> HotPowerByTemperature(const Scene& scene, bool* others) {
    std::map<int, double> binPower;
    auto binOf = [](double T) { return int(std::lround(std::log(T) / std::log(1.01))); };
    // What a hostile scene can make of a temperature or power (0, negative, Inf, NaN): skipped
    auto usable = [](double T, double power) {
        return T > 0 && T < 1e30 && power > 0 && std::isfinite(power);
    };
    double lightPower = 0;
    *others = false;
    for (const Light& light : scene.lights) {
        if (std::optional<Light::ThermalOutput> t = light.Thermal()) {
            if (!usable(t->temperature, t->bandPower)) continue;
            binPower[binOf(t->temperature)] += t->bandPower;
            lightPower += t->bandPower;
        } else {
            *others = true;
        }
    }
    if (scene.features.volumetric) {
        std::vector<Float> mediumTemperatures;
        for (const Medium& m : scene.media) {
            if (!m.IsEmissive()) continue;
            if (std::optional<Float> T = m.EmissionTemperature()) {
                if (usable(*T, 1)) mediumTemperatures.push_back(*T);
            } else {
                *others = true;
            }
        }
        double each = mediumTemperatures.empty()
                          ? 0
                          : (lightPower > 0 ? lightPower : double(mediumTemperatures.size())) /
                                double(mediumTemperatures.size());
        for (Float T : mediumTemperatures) binPower[binOf(T)] += each;
    }
    return binPower;
}

double BinTemperature(int bin) { return std::pow(1.01, bin); }

// A thermal film's band: share of the sensor's response (flat, or "response") plus the rest in
// proportion to the response times the spectrum the hot matter radiates, each temperature's
// part normalised to its power; over 4096 equal bins of the band
WavelengthDistribution ThermalBandDistribution(const Scene& scene, Float* visibleShare) {
    constexpr int kBins = 4096;
    const SpectralRange band = scene.spectralRange;
    const SensorResponse* response = scene.job->film->Thermal()->Response();
    const double width = (double(band.max) - band.min) / kBins;
    std::vector<double> R(kBins), centre(kBins);
    double sumR = 0;
    for (int i = 0; i < kBins; ++i) {
        const double a = band.min + i * width;
        centre[size_t(i)] = a + width / 2;
        R[size_t(i)] = response ? response->Integral(a, a + width) / width : 1;
        sumR += R[size_t(i)];
    }
    bool others = false;
    std::map<int, double> binPower;
    if (scene.integrator.emissionWavelengths) binPower = HotPowerByTemperature(scene, &others);
    std::vector<double> hot(kBins, 0.0);
    double hotSum = 0;
    for (const auto& [bin, power] : binPower) {
        std::vector<double> part(kBins);
        double partSum = 0;
        for (int i = 0; i < kBins; ++i) {
            part[size_t(i)] =
                R[size_t(i)] * planck_radiance(centre[size_t(i)], BinTemperature(bin));
            partSum += part[size_t(i)];
        }
        if (!(partSum > 0) || !std::isfinite(partSum)) continue;
        for (int i = 0; i < kBins; ++i) hot[size_t(i)] += power * part[size_t(i)] / partSum;
        hotSum += power;
    }
    const double share = hotSum > 0 ? (others ? 0.75 : 0.5) : 1;
    std::vector<Float> f(kBins);
    for (int i = 0; i < kBins; ++i)
        f[size_t(i)] = Float(share * R[size_t(i)] / sumR +
                             (hotSum > 0 ? (1 - share) * hot[size_t(i)] / hotSum : 0));
    *visibleShare = Float(share);
    return WavelengthDistribution::Tabulated(f, band.min, band.max);
}

}  // namespace

WavelengthDistribution CreateWavelengthDistribution(const Scene& scene, Float* visibleShare) {
    *visibleShare = 1;
    if (scene.job->film->Thermal()) return ThermalBandDistribution(scene, visibleShare);
    if (!scene.spectralRange.IsVisible())
        return WavelengthDistribution::Band(scene.spectralRange.min, scene.spectralRange.max);
    if (!scene.integrator.emissionWavelengths) return {};
    bool others = false;
    std::map<int, double> binPower = HotPowerByTemperature(scene, &others);
    if (binPower.empty()) return {};
    // Each bin's spectrum scaled to its power over 360-830 nm
    std::vector<Float> emitted(WavelengthDistribution::kBins, 0.f);
    for (const auto& [bin, power] : binPower) {
        double T = BinTemperature(bin), visible = planck_band_radiance(Lambda_min, Lambda_max, T);
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
