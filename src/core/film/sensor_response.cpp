#include "core/film/sensor_response.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "spectral/planck.h"

namespace kiln {

namespace {

constexpr int kTemperatures = 2048;
constexpr double kLowestT = 1, kHighestT = 1e6;

// ln B(lambda, T), B in W m^-2 sr^-1 nm^-1, for T > 0 (no underflow: the exponential stays in
// logarithms)
double LogPlanck(double lambdaNm, double T) {
    const double lambda = lambdaNm * 1e-9;
    const double x = kSecondRadiationConstant / (lambda * T);
    // ln(e^x - 1)
    const double logExpm1 = x > 30 ? x + std::log1p(-std::exp(-x)) : std::log(std::expm1(x));
    return std::log(kFirstRadiationConstantL * 1e-9) - 5 * std::log(lambda) - logExpm1;
}

std::string Nm(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", v);
    return text;
}

}  // namespace

SensorResponse::SensorResponse(std::span<const float> l, std::span<const float> v)
    : lambdas(l.begin(), l.end()), values(v.begin(), v.end()) {
    const size_t n = lambdas.size();
    if (n != values.size() || n < 2)
        throw std::invalid_argument("a response needs at least two (wavelength, value) points");
    for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(lambdas[i]) || (i > 0 && !(lambdas[i] > lambdas[i - 1])))
            throw std::invalid_argument("the response's wavelengths must increase");
        if (!(values[i] >= 0) || !std::isfinite(values[i]))
            throw std::invalid_argument("the response's values must be finite and >= 0 (" +
                                        Nm(values[i]) + " at " + Nm(lambdas[i]) + " nm)");
    }
    if (!(lambdas.front() >= kSpectralRangeMin && lambdas.back() <= kSpectralRangeMax))
        throw std::invalid_argument("the response must lie within 300 nm - 20 um (it spans " +
                                    Nm(lambdas.front()) + " - " + Nm(lambdas.back()) + " nm)");
    auto first = std::find_if(values.begin(), values.end(), [](float r) { return r > 0; });
    if (first == values.end()) throw std::invalid_argument("the response is 0 everywhere");
    auto last = std::find_if(values.rbegin(), values.rend(), [](float r) { return r > 0; });
    const size_t a = size_t(std::max<std::ptrdiff_t>(first - values.begin() - 1, 0));
    const size_t b = std::min(n - 1, size_t(values.rend() - last));
    support = SpectralRange{lambdas[a], lambdas[b]};

    // Quadrature points: the points of the table from a to b, each interval divided into steps
    // of at most 0.2 % of its start
    for (size_t i = a; i < b; ++i) {
        const double x0 = lambdas[i], x1 = lambdas[i + 1];
        const int m = std::max(1, int(std::ceil((x1 - x0) / (0.002 * x0))));
        for (int j = 0; j < m; ++j) nodeLambda.push_back(x0 + (x1 - x0) * j / m);
    }
    nodeLambda.push_back(lambdas[b]);
    for (double l : nodeLambda) nodeR.push_back((*this)(float(l)));

    // The inversion table
    logT.resize(kTemperatures);
    logL.resize(kTemperatures);
    for (int i = 0; i < kTemperatures; ++i) {
        logT[size_t(i)] = std::log(kLowestT) +
                          (std::log(kHighestT) - std::log(kLowestT)) * i / (kTemperatures - 1);
        logL[size_t(i)] = LogBandRadiance(std::exp(logT[size_t(i)]));
    }
}

float SensorResponse::operator()(float lambda) const {
    if (!(lambda >= lambdas.front() && lambda <= lambdas.back())) return 0;
    size_t i = size_t(std::upper_bound(lambdas.begin(), lambdas.end(), lambda) - lambdas.begin());
    if (i >= lambdas.size()) return values.back();
    const float t = (lambda - lambdas[i - 1]) / (lambdas[i] - lambdas[i - 1]);
    return (1 - t) * values[i - 1] + t * values[i];
}

double SensorResponse::Integral(double a, double b) const {
    double sum = 0;
    for (size_t i = 0; i + 1 < lambdas.size(); ++i) {
        const double c = std::max(a, double(lambdas[i])), d = std::min(b, double(lambdas[i + 1]));
        if (!(d > c)) continue;
        sum += (d - c) * ((*this)(float(c)) + (*this)(float(d))) / 2;
    }
    return sum;
}

double SensorResponse::LogBandRadiance(double T) const {
    // Over each step R is linear and B the exponential through its ends, integrated exactly:
    // from the end where B is larger (its value B_b, R_b there, R_o at the other end, u = ln of
    // the other end's B over B_b <= 0), h B_b (R_b E(u) + (R_o - R_b) F(u)) with
    // E(u) = integral_0^1 e^(u t) dt and F(u) = integral_0^1 t e^(u t) dt. Exact where Planck's
    // law is Wien's exponential (B falls by orders of magnitude across a step when cold); in
    // logarithms, so that no temperature underflows.
    const size_t n = nodeLambda.size();
    std::vector<double> lnB(n), terms;
    for (size_t k = 0; k < n; ++k) lnB[k] = LogPlanck(nodeLambda[k], T);
    double largest = -INFINITY;
    for (size_t k = 0; k + 1 < n; ++k) {
        const bool first = lnB[k] >= lnB[k + 1];
        const double lnBase = first ? lnB[k] : lnB[k + 1];
        const double u = (first ? lnB[k + 1] : lnB[k]) - lnBase;
        const double rb = first ? nodeR[k] : nodeR[k + 1], ro = first ? nodeR[k + 1] : nodeR[k];
        double E, F;
        if (u > -1e-3) {
            E = 1 + u / 2 + u * u / 6;
            F = 0.5 + u / 3 + u * u / 8;
        } else {
            E = std::expm1(u) / u;
            F = (std::exp(u) * (u - 1) + 1) / (u * u);
        }
        const double bracket = rb * E + (ro - rb) * F;
        if (!(bracket > 0)) continue;
        const double t = std::log(nodeLambda[k + 1] - nodeLambda[k]) + lnBase + std::log(bracket);
        terms.push_back(t);
        largest = std::max(largest, t);
    }
    if (terms.empty()) return -INFINITY;
    double sum = 0;
    for (double t : terms) sum += std::exp(t - largest);
    return largest + std::log(sum);
}

double SensorResponse::BandRadiance(double T) const {
    return T > 0 ? std::exp(LogBandRadiance(T)) : 0;
}

double SensorResponse::Temperature(double L) const {
    if (!(L > 0)) return 0;
    const double lnL = std::log(L);
    if (lnL < logL.front()) return 0;
    if (lnL >= logL.back()) return kHighestT;
    size_t i = size_t(std::upper_bound(logL.begin(), logL.end(), lnL) - logL.begin());
    const double t = (lnL - logL[i - 1]) / (logL[i] - logL[i - 1]);
    return std::exp(logT[i - 1] + t * (logT[i] - logT[i - 1]));
}

}  // namespace kiln
