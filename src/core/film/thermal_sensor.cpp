#include "core/film/thermal_sensor.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/parser/diagnostics.h"
#include "core/parser/parameter_dictionary.h"
#include "spectral/planck.h"
#include "spectral/spectrum.h"

namespace kiln {

namespace {

std::string Nm(Float v) {
    std::string s = std::to_string(v);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

}  // namespace

ThermalSensor ThermalSensor::Create(const ParameterDictionary& params, const FileLoc& loc) {
    ThermalSensor s;
    s.name = params.GetOneString("sensor", "lwir");
    const FileLoc sensorLoc = params.Loc("sensor", loc);
    // The named bands (nm)
    struct Named {
        const char* name;
        Float min, max;
    };
    static constexpr Named kBands[] = {
        {"lwir", 8000, 14000}, {"mwir", 3000, 5000}, {"swir", 900, 1700}, {"nir", 750, 1100}};
    bool named = false;
    for (const Named& b : kBands)
        if (s.name == b.name) {
            s.band = SpectralRange{b.min, b.max};
            named = true;
        }
    if (s.name == "pyrometer") {
        if (!params.Has("wavelength"))
            throw SceneError(sensorLoc, "the pyrometer needs its \"float wavelength\" (nm)",
                             s.name);
        Float centre = params.GetOneFloat("wavelength", 0);
        Float width = params.GetOneFloat("bandwidth", 10);
        if (!(width > 0 && width <= 1000))
            throw SceneError(params.Loc("bandwidth", loc),
                             "the pyrometer's \"bandwidth\" must be more than 0 and at most "
                             "1000 nm",
                             Nm(width));
        s.band = SpectralRange{centre - width / 2, centre + width / 2};
        if (!(s.band.min >= kSpectralRangeMin && s.band.max <= kSpectralRangeMax))
            throw SceneError(params.Loc("wavelength", loc),
                             "the pyrometer's band must lie within 300 nm - 20 um", Nm(centre));
    } else if (s.name == "band") {
        s.band =
            SpectralRange{params.GetOneFloat("lambdamin", 0), params.GetOneFloat("lambdamax", 0)};
        if (!(s.band.min >= kSpectralRangeMin && s.band.max <= kSpectralRangeMax &&
              s.band.min < s.band.max))
            throw SceneError(params.Loc("lambdamin", params.Loc("lambdamax", sensorLoc)),
                             "the thermal film's band must satisfy 300 <= \"lambdamin\" < "
                             "\"lambdamax\" <= 20000 (nm)",
                             "lambdamin");
    } else if (s.name == "response") {
        std::optional<Spectrum> r =
            params.GetOneSpectrum("response", std::nullopt, SpectrumType::Illuminant);
        if (!r)
            throw SceneError(sensorLoc,
                             "the \"response\" sensor needs its \"spectrum response\" "
                             "(wavelength-value pairs in nm, or a spectrum file)",
                             s.name);
        const PiecewiseLinearSpectrum* table = r->GetIf<PiecewiseLinearSpectrum>();
        if (!table)
            throw SceneError(params.Loc("response", loc),
                             "the sensor's \"response\" must be wavelength-value pairs (nm) or a "
                             "spectrum file",
                             "response");
        try {
            s.response.emplace(table->Lambdas(), table->Values());
        } catch (const std::invalid_argument& e) {
            throw SceneError(params.Loc("response", loc), e.what(), "response");
        }
        s.band = s.response->Support();
    } else if (!named) {
        throw SceneError(sensorLoc,
                         "unknown thermal sensor \"" + s.name +
                             "\" (expected \"lwir\", \"mwir\", \"swir\", \"nir\", \"pyrometer\", "
                             "\"band\" or \"response\")",
                         s.name);
    }
    s.emissivity = params.GetOneFloat("emissivity", 1);
    if (!(s.emissivity > 0 && s.emissivity <= 1))
        throw SceneError(params.Loc("emissivity", loc),
                         "the thermal film's \"emissivity\" setting must be more than 0 and at "
                         "most 1",
                         Nm(s.emissivity));
    s.reflectedTemperature = params.GetOneFloat("reflectedtemperature", 0);
    if (!(s.reflectedTemperature >= 0 && s.reflectedTemperature <= 1e6f))
        throw SceneError(params.Loc("reflectedtemperature", loc),
                         "the thermal film's \"reflectedtemperature\" must be 0 to 1e6 K",
                         Nm(s.reflectedTemperature));
    if (params.Has("scalemin") || params.Has("scalemax")) {
        const char* which = params.Has("scalemin") ? "scalemin" : "scalemax";
        if (!params.Has("scalemin") || !params.Has("scalemax"))
            throw SceneError(params.Loc(which, loc),
                             "the thermal film's picture scale needs both \"scalemin\" and "
                             "\"scalemax\" (kelvin)",
                             which);
        TemperatureScale t{params.GetOneFloat("scalemin", 0), params.GetOneFloat("scalemax", 0)};
        if (!(t.lo >= 0 && t.hi > t.lo && t.hi <= 1e6f))
            throw SceneError(params.Loc("scalemax", loc),
                             "the thermal film's \"scalemin\" and \"scalemax\" must be kelvin "
                             "with 0 <= scalemin < scalemax <= 1e6",
                             Nm(t.lo) + " " + Nm(t.hi));
        s.pictureScale = t;
    }
    return s;
}

std::string ThermalSensor::ScaleSettings(const TemperatureScale& t) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.9g %.9g", double(t.lo), double(t.hi));
    return text;
}

std::optional<TemperatureScale> ThermalSensor::ScaleFromSettings(std::string_view settings) {
    std::istringstream in{std::string(settings)};
    double lo, hi;
    std::string rest;
    if (!(in >> lo >> hi) || (in >> rest)) return std::nullopt;
    if (!(lo >= 0 && hi > lo && hi <= 1e6)) return std::nullopt;
    return TemperatureScale{Float(lo), Float(hi)};
}

double ThermalSensor::BlackbodyRadiance(double T) const {
    return response ? response->BandRadiance(T) : planck_band_radiance(band.min, band.max, T);
}

double ThermalSensor::ApparentTemperature(double L) const {
    double reflected = emissivity < 1 && reflectedTemperature > 0
                           ? (1 - double(emissivity)) * BlackbodyRadiance(reflectedTemperature)
                           : 0;
    double own = (L - reflected) / double(emissivity);
    if (!(own > 0)) return 0;
    return response ? response->Temperature(own)
                    : band_radiance_temperature(band.min, band.max, own);
}

std::string ThermalSensor::Settings() const {
    char text[128];
    std::snprintf(text, sizeof(text), "%.9g %.9g %.9g %.9g", double(band.min), double(band.max),
                  double(emissivity), double(reflectedTemperature));
    std::string s = text;
    if (response) {
        s += " response";
        for (size_t i = 0; i < response->Lambdas().size(); ++i) {
            std::snprintf(text, sizeof(text), " %.9g %.9g", double(response->Lambdas()[i]),
                          double(response->Values()[i]));
            s += text;
        }
    }
    return s;
}

std::optional<ThermalSensor> ThermalSensor::FromSettings(std::string_view settings) {
    std::istringstream in{std::string(settings)};
    ThermalSensor s;
    if (!(in >> s.band.min >> s.band.max >> s.emissivity >> s.reflectedTemperature))
        return std::nullopt;
    if (!(s.band.min >= kSpectralRangeMin && s.band.max <= kSpectralRangeMax &&
          s.band.min < s.band.max && s.emissivity > 0 && s.emissivity <= 1 &&
          s.reflectedTemperature >= 0 && s.reflectedTemperature <= 1e6f))
        return std::nullopt;
    s.name = "band";
    std::string word;
    if (in >> word) {
        if (word != "response") return std::nullopt;
        std::vector<float> numbers, lambdas, values;
        float x;
        while (in >> x) numbers.push_back(x);
        if (!in.eof() || numbers.size() % 2 != 0) return std::nullopt;
        for (size_t i = 0; i < numbers.size(); i += 2)
            lambdas.push_back(numbers[i]), values.push_back(numbers[i + 1]);
        try {
            s.response.emplace(lambdas, values);
        } catch (const std::invalid_argument&) {
            return std::nullopt;
        }
        if (!(s.response->Support() == s.band)) return std::nullopt;
        s.name = "response";
    }
    return s;
}

}  // namespace kiln
