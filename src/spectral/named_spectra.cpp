// Named spectra built from the tables of named_spectra_*_data.cpp.
#include "spectral/named_spectra.h"

#include <map>
#include <string>

#include "spectral/named_spectra_data.h"

namespace kiln {

namespace {

struct NamedSpectra {
    std::vector<std::string_view> names;
    std::map<std::string_view, Spectrum> spectra;
};

const NamedSpectra& AllNamedSpectra() {
    static const NamedSpectra all = [] {
        NamedSpectra n;
        for (auto tables : {PbrtNamedSpectrumTables(), CameraNamedSpectrumTables(),
                            MeasuredNamedSpectrumTables()})
            for (const NamedSpectrumTable& t : tables) {
                n.names.push_back(t.name);
                PiecewiseLinearSpectrum s =
                    PiecewiseLinearSpectrum::FromInterleaved(t.interleaved, t.normalize);
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
