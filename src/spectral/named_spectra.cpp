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
        for (auto tables : {PbrtNamedSpectrumTables(), MeasuredNamedSpectrumTables()})
            for (const NamedSpectrumTable& t : tables) {
                n.names.push_back(t.name);
                n.spectra.emplace(
                    t.name, PiecewiseLinearSpectrum::FromInterleaved(t.interleaved, t.normalize));
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

std::vector<std::string_view> NamedSpectrumNames() { return AllNamedSpectra().names; }

}  // namespace kiln
