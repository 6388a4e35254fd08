#include "spectral/metal_temperature.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spectral/lorentz_drude.h"
#include "spectral/metal_temperature_data.h"
#include "spectral/named_spectra.h"
#include "spectral/spectral_range.h"
#include "spectral/spectrum.h"

namespace kiln {

namespace {

using Complex = std::complex<double>;

// Tungsten
// Electrical resistivity, micro-ohm cm, at 293, 500, 1000, 2000, 3000 and 3500 K, as tabulated
// by the International Tungsten Industry Association's supplier page tungsten.com ("Tungsten",
// material properties: 5.5, 10.5, 24.3, 55.7, 90.4, 108.5 at 20, 227, 727, 1727, 2727 and
// 3227 degC); linear between the points and beyond the last two.
constexpr double kTungstenRho[][2] = {{293, 5.5},   {500, 10.5},  {1000, 24.3},
                                      {2000, 55.7}, {3000, 90.4}, {3500, 108.5}};
constexpr double kTungstenRoom = 293, kTungstenHot = 1600, kTungstenMelting = 3695;
// The Lorentz terms' factors per kelvin above 293 K (gen/hot_tungsten_fit.py)
constexpr double kTungstenLorentzDamping = 3.0e-4, kTungstenLorentzStrength = 2.96e-4;

Complex TungstenModel(double lambda, double T) {
    const double dT = T - kTungstenRoom;
    LorentzDrudeScaling s;
    s.drudeDamping = TungstenResistivityRatio(T);
    s.lorentzDamping = 1 + kTungstenLorentzDamping * dT;
    s.lorentzStrength = 1 + kTungstenLorentzStrength * dT;
    return *LorentzDrudePermittivity("W", lambda, s);
}

// Weight of the named table's difference from the model (1 at room temperature, 0 from 1600 K)
double TungstenTableWeight(double T) {
    return std::clamp((kTungstenHot - T) / (kTungstenHot - kTungstenRoom), 0.0, 1.0);
}

// Gold and silver: the measured tables (metal_temperature_data.cpp)
struct MeasuredChange {
    const MeasuredMetalTemperatures* table = nullptr;
    double melting = 0;
    int nT = 0, nRows = 0;
    std::vector<double> lambdas;
    // Permittivity change from room temperature, [row][temperature]
    std::vector<Complex> change;
    // Least-squares slope of the change in T through all temperatures, per row (per kelvin)
    std::vector<Complex> slope;
    // The Drude model's damping and strength factors (DrudeFactors) at room temperature, each
    // measured temperature and the melting point; linear in T between them
    std::vector<double> factorTemperatures;
    std::vector<std::pair<double, double>> factors;

    double Lambda(int r) const { return lambdas[size_t(r)]; }
    double LastTemperature() const { return table->temperatures[size_t(nT - 1)]; }
    // The change at row r and temperature T (room temperature <= T <= melting)
    Complex At(int r, double T) const {
        const std::span<const float> Ts = table->temperatures;
        const Complex* c = &change[size_t(r * nT)];
        if (T >= Ts[size_t(nT - 1)]) return c[nT - 1] + slope[size_t(r)] * (T - Ts[size_t(nT - 1)]);
        int i = 0;
        while (i < nT - 2 && Ts[size_t(i + 1)] <= T) ++i;
        double t = (T - Ts[size_t(i)]) / (Ts[size_t(i + 1)] - Ts[size_t(i)]);
        return (1 - t) * c[i] + t * c[i + 1];
    }
    // Start of the last 15 % of the wavelengths
    double BlendStart() const { return lambdas.back() / 1.15; }
    std::pair<double, double> DrudeFactorsAt(double T) const {
        size_t i = 0;
        while (i + 2 < factorTemperatures.size() && factorTemperatures[i + 1] <= T) ++i;
        double t = std::clamp(
            (T - factorTemperatures[i]) / (factorTemperatures[i + 1] - factorTemperatures[i]), 0.0,
            1.0);
        return {(1 - t) * factors[i].first + t * factors[i + 1].first,
                (1 - t) * factors[i].second + t * factors[i + 1].second};
    }
};

std::pair<double, double> DrudeFactors(const MeasuredChange& m, std::string_view symbol, double T);

const MeasuredChange* FindMeasured(std::string_view symbol) {
    static const std::vector<MeasuredChange> all = [] {
        std::vector<MeasuredChange> v;
        for (const MeasuredMetalTemperatures& t : MeasuredMetalTemperatureTables()) {
            MeasuredChange m;
            m.table = &t;
            m.melting = t.symbol == "Au" ? 1337.33 : 1234.93;  // ITS-90 fixed points
            m.nT = int(t.temperatures.size());
            const int stride = 1 + 2 * m.nT;
            m.nRows = int(t.rows.size()) / stride;
            for (int r = 0; r < m.nRows; ++r) {
                const float* row = &t.rows[size_t(r * stride)];
                m.lambdas.push_back(row[0]);
                Complex room = Complex(row[1], row[2]) * Complex(row[1], row[2]);
                Complex num = 0;
                double den = 0;
                for (int i = 0; i < m.nT; ++i) {
                    Complex e = Complex(row[1 + 2 * i], row[2 + 2 * i]);
                    Complex d = e * e - room;
                    m.change.push_back(d);
                    double dT = t.temperatures[size_t(i)] - t.temperatures[0];
                    num += d * dT;
                    den += dT * dT;
                }
                m.slope.push_back(num / den);
            }
            m.factorTemperatures.assign(t.temperatures.begin(), t.temperatures.end());
            m.factorTemperatures.push_back(m.melting);
            m.factors.emplace_back(1, 1);
            for (size_t i = 1; i < m.factorTemperatures.size(); ++i)
                m.factors.push_back(DrudeFactors(m, t.symbol, m.factorTemperatures[i]));
            v.push_back(std::move(m));
        }
        return v;
    }();
    for (const MeasuredChange& m : all)
        if (m.table->symbol == symbol) return &m;
    return nullptr;
}

// The Lorentz-Drude model's change when its Drude term's damping and strength are scaled
Complex DrudeChange(std::string_view symbol, double lambda, double damping, double strength) {
    LorentzDrudeScaling s;
    s.drudeDamping = damping;
    s.drudeStrength = strength;
    return *LorentzDrudePermittivity(symbol, lambda, s) - *LorentzDrudePermittivity(symbol, lambda);
}

// The Drude damping and strength factors whose change matches the measured change at T averaged
// over the measurements' last 15 % of wavelength: Re eps of the Drude term is nearly
// proportional to its strength, Im eps rises with its damping (below the photon energy), so
// strength and damping are found in turns (three rounds; damping by bisection).
std::pair<double, double> DrudeFactors(const MeasuredChange& m, std::string_view symbol, double T) {
    std::vector<int> rows;
    for (int r = 0; r < m.nRows; ++r)
        if (m.Lambda(r) >= m.BlendStart()) rows.push_back(r);
    Complex target = 0;
    for (int r : rows) target += m.At(r, T);
    target /= double(rows.size());
    auto mean = [&](double damping, double strength) {
        Complex sum = 0;
        for (int r : rows) sum += DrudeChange(symbol, m.Lambda(r), damping, strength);
        return sum / double(rows.size());
    };
    // Mean over the rows of Re of the Drude term alone (its strength 1) at a damping factor
    auto drudeRe = [&](double damping) {
        double sum = 0;
        for (int r : rows) {
            LorentzDrudeScaling only;
            only.drudeDamping = damping;
            only.lorentzStrength = 0;
            sum += LorentzDrudePermittivity(symbol, m.Lambda(r), only)->real() - 1;
        }
        return sum / double(rows.size());
    };
    const double reRoom = drudeRe(1);
    double damping = 1, strength = 1;
    for (int round = 0; round < 3; ++round) {
        // Re change = strength Re D(damping) - Re D(1)
        strength = (target.real() + reRoom) / drudeRe(damping);
        double lo = 0.05, hi = 50;
        for (int i = 0; i < 40; ++i) {
            double mid = std::sqrt(lo * hi);
            (mean(mid, strength).imag() < target.imag() ? lo : hi) = mid;
        }
        damping = std::sqrt(lo * hi);
    }
    return {damping, strength};
}

// The measured metals' change at lambda and T, given the Drude factors at T
Complex MeasuredMetalChange(const MeasuredChange& m, std::string_view symbol, double lambda,
                            double T, std::pair<double, double> drude) {
    if (T <= m.table->temperatures[0]) return 0;
    T = std::min(T, m.melting);
    auto drudeChange = [&] { return DrudeChange(symbol, lambda, drude.first, drude.second); };
    if (lambda >= m.lambdas.back()) return drudeChange();
    // Linear between the measured wavelengths
    auto it = std::upper_bound(m.lambdas.begin(), m.lambdas.end(), lambda);
    int r = std::max(0, int(it - m.lambdas.begin()) - 1);
    int r1 = std::min(r + 1, m.nRows - 1);
    double t =
        r1 == r ? 0 : std::clamp((lambda - m.Lambda(r)) / (m.Lambda(r1) - m.Lambda(r)), 0.0, 1.0);
    Complex measured = (1 - t) * m.At(r, T) + t * m.At(r1, T);
    if (lambda <= m.BlendStart()) return measured;
    double u = (lambda - m.BlendStart()) / (m.lambdas.back() - m.BlendStart());
    return (1 - u) * measured + u * drudeChange();
}

}  // namespace

double TungstenResistivityRatio(double T) {
    constexpr int n = int(std::size(kTungstenRho));
    int i = 0;
    while (i < n - 2 && kTungstenRho[i + 1][0] <= T) ++i;
    const double* a = kTungstenRho[i];
    const double* b = kTungstenRho[i + 1];
    double rho = a[1] + (b[1] - a[1]) * (T - a[0]) / (b[0] - a[0]);
    return std::max(rho, 0.1 * kTungstenRho[0][1]) / kTungstenRho[0][1];
}

bool HasMetalTemperatureModel(std::string_view symbol) {
    return symbol == "W" || FindMeasured(symbol) != nullptr;
}

std::complex<double> MetalPermittivityAt(std::string_view symbol, double lambda, double T,
                                         std::complex<double> epsNamed) {
    if (symbol == "W") {
        if (T <= kTungstenRoom) return epsNamed;
        T = std::min(T, kTungstenMelting);
        double w = TungstenTableWeight(T);
        return TungstenModel(lambda, T) + w * (epsNamed - TungstenModel(lambda, kTungstenRoom));
    }
    const MeasuredChange* m = FindMeasured(symbol);
    if (!m || T <= m->table->temperatures[0]) return epsNamed;
    T = std::min(T, m->melting);
    return epsNamed + MeasuredMetalChange(*m, symbol, lambda, T, m->DrudeFactorsAt(T));
}

// MetalTemperatureTable Method Definitions
const MetalTemperatureTable* MetalTemperatureTable::Find(std::string_view symbol) {
    // Each built when first asked for
    auto get = [](const std::optional<MetalTemperatureTable>& t) { return t ? &*t : nullptr; };
    if (symbol == "W") {
        static const std::optional<MetalTemperatureTable> w = Create("W");
        return get(w);
    }
    if (symbol == "Au") {
        static const std::optional<MetalTemperatureTable> au = Create("Au");
        return get(au);
    }
    if (symbol == "Ag") {
        static const std::optional<MetalTemperatureTable> ag = Create("Ag");
        return get(ag);
    }
    return nullptr;
}

std::optional<MetalTemperatureTable> MetalTemperatureTable::Create(std::string_view symbol) {
    if (!HasMetalTemperatureModel(symbol)) return std::nullopt;
    std::string prefix = "metal-" + std::string(symbol);
    const Spectrum* eta = GetNamedSpectrum(prefix + "-eta");
    const Spectrum* k = GetNamedSpectrum(prefix + "-k");
    if (!eta || !k) return std::nullopt;
    MetalTemperatureTable table;
    table.symbol = symbol;
    table.namedEta = eta;
    table.namedK = k;
    // Wavelength nodes: 1 % geometric steps over 300 nm - 20 um
    const double lo = std::log(double(kSpectralRangeMin)), hi = std::log(double(kSpectralRangeMax));
    const int nLambda = int(std::ceil((hi - lo) / std::log(1.01))) + 1;
    std::vector<float> logLambdas(static_cast<size_t>(nLambda));
    for (int i = 0; i < nLambda; ++i)
        logLambdas[size_t(i)] = float(lo + (hi - lo) * i / (nLambda - 1));
    // Temperature nodes: room temperature to the melting point in 25 K steps
    const MeasuredChange* measured = FindMeasured(symbol);
    const double room = measured ? measured->table->temperatures[0] : kTungstenRoom;
    const double melting = measured ? measured->melting : kTungstenMelting;
    const int nT = int(std::ceil((melting - room) / 25)) + 1;
    std::vector<float> Ts(static_cast<size_t>(nT));
    for (int j = 0; j < nT; ++j) Ts[size_t(j)] = float(room + (melting - room) * j / (nT - 1));
    table.w.resize(size_t(nT));
    table.change.resize(size_t(nT * nLambda));
    for (int j = 0; j < nT; ++j) {
        const double T = Ts[size_t(j)];
        std::pair<double, double> drude{1, 1};
        if (measured) drude = measured->DrudeFactorsAt(T);
        const double w = measured ? 1 : (j == 0 ? 1 : TungstenTableWeight(T));
        table.w[size_t(j)] = float(w);
        for (int i = 0; i < nLambda; ++i) {
            const double lambda = std::exp(double(logLambdas[size_t(i)]));
            Complex c;
            if (j == 0)
                c = 0;
            else if (measured)
                c = MeasuredMetalChange(*measured, symbol, lambda, T, drude);
            else
                c = TungstenModel(lambda, T) - w * TungstenModel(lambda, kTungstenRoom);
            table.change[size_t(j * nLambda + i)] = std::complex<float>(c);
        }
    }
    table.logLambdas = TableAxis(std::move(logLambdas));
    table.temperatures = TableAxis(std::move(Ts));
    return table;
}

MetalTemperatureTable MetalTemperatureTable::FromMeasurements(
    const std::vector<std::pair<Float, NkTable>>& measurements) {
    // Each measurement's n and k as spectra holding their ends, and its permittivity
    std::vector<std::pair<PiecewiseLinearSpectrum, PiecewiseLinearSpectrum>> nk;
    for (const auto& [T, t] : measurements) {
        nk.emplace_back(PiecewiseLinearSpectrum(t.lambdas, t.n),
                        PiecewiseLinearSpectrum(t.lambdas, t.k));
        nk.back().first.HoldEndsBeyondVisible();
        nk.back().second.HoldEndsBeyondVisible();
    }
    auto eps = [&](size_t m, double lambda) {
        Complex n(nk[m].first(Float(lambda)), nk[m].second(Float(lambda)));
        return n * n;
    };
    MetalTemperatureTable table;
    table.symbol = "";
    table.ownEta = std::make_shared<const Spectrum>(nk[0].first);
    table.ownK = std::make_shared<const Spectrum>(nk[0].second);
    table.namedEta = table.ownEta.get();
    table.namedK = table.ownK.get();
    const double lo = std::log(double(kSpectralRangeMin)), hi = std::log(double(kSpectralRangeMax));
    const int nLambda = int(std::ceil((hi - lo) / std::log(1.01))) + 1;
    std::vector<float> logLambdas(static_cast<size_t>(nLambda));
    for (int i = 0; i < nLambda; ++i)
        logLambdas[size_t(i)] = float(lo + (hi - lo) * i / (nLambda - 1));
    const double first = measurements.front().first, last = measurements.back().first;
    const int nT = int(std::ceil((last - first) / 25)) + 1;
    std::vector<float> Ts(static_cast<size_t>(nT));
    for (int j = 0; j < nT; ++j) Ts[size_t(j)] = float(first + (last - first) * j / (nT - 1));
    Ts.back() = float(last);
    table.w.assign(size_t(nT), 1.f);
    table.change.resize(size_t(nT * nLambda));
    size_t m = 0;
    for (int j = 0; j < nT; ++j) {
        const double T = Ts[size_t(j)];
        while (m + 2 < measurements.size() && T > measurements[m + 1].first) ++m;
        const double T0 = measurements[m].first, T1 = measurements[m + 1].first;
        const double t = std::clamp((T - T0) / (T1 - T0), 0.0, 1.0);
        for (int i = 0; i < nLambda; ++i) {
            const double lambda = std::exp(double(logLambdas[size_t(i)]));
            Complex e = (1 - t) * eps(m, lambda) + t * eps(m + 1, lambda);
            table.change[size_t(j * nLambda + i)] = std::complex<float>(e - eps(0, lambda));
        }
    }
    table.logLambdas = TableAxis(std::move(logLambdas));
    table.temperatures = TableAxis(std::move(Ts));
    return table;
}

void MetalTemperatureTable::Evaluate(const SampledWavelengths& lambda, Float T,
                                     SampledSpectrum* eta, SampledSpectrum* k) const {
    *eta = namedEta->Sample(lambda);
    *k = namedK->Sample(lambda);
    if (!(T > temperatures.Node(0))) return;
    auto [j, tT] = temperatures.Locate(T);
    const int j1 = temperatures.Next(j);
    const int nLambda = logLambdas.Size();
    const float w = (1 - tT) * this->w[size_t(j)] + tT * this->w[size_t(j1)];
    for (int s = 0; s < NSpectrumSamples; ++s) {
        auto [i, tL] = logLambdas.Locate(std::log(lambda[s]));
        const int i1 = logLambdas.Next(i);
        auto at = [&](int jj, int ii) { return change[size_t(jj * nLambda + ii)]; };
        std::complex<float> c = (1 - tT) * ((1 - tL) * at(j, i) + tL * at(j, i1)) +
                                tT * ((1 - tL) * at(j1, i) + tL * at(j1, i1));
        std::complex<float> n((*eta)[s], (*k)[s]);
        std::complex<float> e = w * n * n + c;
        // n + i k = sqrt(e), the root with n >= 0, each part from the form that does not cancel
        const float re = e.real(), im = std::max(e.imag(), 0.f);
        const float r = std::sqrt(re * re + im * im);
        if (re >= 0) {
            (*eta)[s] = std::sqrt((r + re) / 2);
            (*k)[s] = (*eta)[s] > 0 ? im / (2 * (*eta)[s]) : 0;
        } else {
            (*k)[s] = std::sqrt((r - re) / 2);
            (*eta)[s] = im / (2 * (*k)[s]);
        }
    }
}

}  // namespace kiln
