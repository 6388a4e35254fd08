// Named spectra built from the tables of named_spectra_*_data.cpp.
#include "spectral/named_spectra.h"

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "spectral/infrared_metal_data.h"
#include "spectral/lorentz_drude.h"
#include "spectral/named_spectra_data.h"
#include "spectral/spectral_range.h"

namespace kiln {

namespace {

// A metal's table (metal-X-eta or metal-X-k) extended to 300 nm - 20 um with the Lorentz-Drude
// model of Rakic et al. 1998 (lorentz_drude.h), where it has X, else with measured infrared
// constants (infrared_metal_data.h: iron, brass, magnesia): beyond each end of the table the values
// go over linearly from the table's end value to the model's (within 15 % of the end's wavelength
// below the table, 50 % above it), then follow the model; where the model has no value below the
// table, the table holds its first value. Tables of other names, and metals with neither, come
// back unchanged (nullopt).
std::optional<std::vector<float>> ExtendedMetalTable(std::string_view name,
                                                     std::span<const float> interleaved) {
    if (!name.starts_with("metal-") || interleaved.size() < 4) return std::nullopt;
    std::string_view rest = name.substr(6);
    size_t dash = rest.find('-');
    if (dash == std::string_view::npos) return std::nullopt;
    std::string_view symbol = rest.substr(0, dash), part = rest.substr(dash + 1);
    if (part != "eta" && part != "k") return std::nullopt;
    auto model = [&](double lambda) -> std::optional<double> {
        std::optional<std::complex<double>> nk = LorentzDrudeIndex(symbol, lambda);
        if (!nk) nk = MeasuredInfraredIndex(symbol, lambda);
        if (!nk) return std::nullopt;
        return part == "eta" ? nk->real() : nk->imag();
    };
    if (!model(1000)) return std::nullopt;
    const double start = interleaved[0], end = interleaved[interleaved.size() - 2];
    const double vStart = interleaved[1], vEnd = interleaved.back();
    std::vector<float> out;
    // Below the table: 300 nm up to it, in steps of at most 5 nm
    if (start > kSpectralRangeMin && model(kSpectralRangeMin)) {
        const double blend = start / 1.15;
        int n = int(std::ceil((start - kSpectralRangeMin) / 5));
        for (int i = 0; i < n; ++i) {
            double l = kSpectralRangeMin + (start - kSpectralRangeMin) * i / n;
            double w = l <= blend ? 1 : (start - l) / (start - blend);
            out.push_back(float(l));
            out.push_back(float((1 - w) * vStart + w * *model(l)));
        }
    }
    out.insert(out.end(), interleaved.begin(), interleaved.end());
    // Above it: to 20 um in 120 geometric steps
    if (end < kSpectralRangeMax) {
        const double blend = 1.5 * end;
        constexpr int n = 120;
        for (int i = 1; i <= n; ++i) {
            double l = end * std::pow(kSpectralRangeMax / end, double(i) / n);
            double w = l >= blend ? 1 : (l - end) / (blend - end);
            out.push_back(float(l));
            out.push_back(float((1 - w) * vEnd + w * *model(l)));
        }
    }
    return out;
}

struct NamedSpectra {
    std::vector<std::string_view> names;
    std::map<std::string_view, Spectrum> spectra;
};

const NamedSpectra& AllNamedSpectra() {
    static const NamedSpectra all = [] {
        NamedSpectra n;
        for (auto tables : {PbrtNamedSpectrumTables(), CameraNamedSpectrumTables(),
                            MeasuredNamedSpectrumTables(), GlassNamedSpectrumTables()})
            for (const NamedSpectrumTable& t : tables) {
                n.names.push_back(t.name);
                std::optional<std::vector<float>> extended =
                    ExtendedMetalTable(t.name, t.interleaved);
                PiecewiseLinearSpectrum s = PiecewiseLinearSpectrum::FromInterleaved(
                    extended ? std::span<const float>(*extended) : t.interleaved, t.normalize);
                // Optical constants hold their ends beyond the visible
                std::string_view name = t.name;
                if (name.starts_with("metal-") || name.starts_with("glass-"))
                    s.HoldEndsBeyondVisible();
                n.spectra.emplace(t.name, std::move(s));
            }
        return n;
    }();
    return all;
}

}  // namespace

const Spectrum* GetNamedSpectrum(std::string_view name) {
    const auto& s = AllNamedSpectra().spectra;
    auto it = s.find(name);
    return it != s.end() ? &it->second : nullptr;
}

bool IsPbrtSensorWithoutData(std::string_view name) {
    for (std::string_view n :
         {"canon_eos_100d", "canon_eos_1dx_mkii", "canon_eos_200d", "canon_eos_200d_mkii",
          "canon_eos_5d", "canon_eos_5d_mkiii", "canon_eos_5d_mkiv", "canon_eos_5ds", "canon_eos_m",
          "hasselblad_l1d_20c", "nikon_d810", "nikon_d850", "sony_ilce_6400", "sony_ilce_7m3",
          "sony_ilce_7rm3", "sony_ilce_9"})
        if (name == n) return true;
    return false;
}

std::vector<std::string_view> NamedSpectrumNames() { return AllNamedSpectra().names; }

}  // namespace kiln
