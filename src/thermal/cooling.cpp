#include "thermal/cooling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "spectral/planck.h"

namespace kiln {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Dormand-Prince 5(4) coefficients (J. R. Dormand and P. J. Prince, "A family of embedded
// Runge-Kutta formulae", J. Comput. Appl. Math. 6 (1980) 19-26). The ODE is autonomous, so
// the nodes c_i are not needed.
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
// Fifth-order weights (also the seventh stage's row: first same as last).
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                 b6 = 11.0 / 84;
// Fifth minus fourth order weights: the error estimate.
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;

}  // namespace

// CoolingModel Method Definitions
CoolingModel::CoolingModel(const CoolingParameters& p, double relTol)
    : params(p), relTol(relTol), k(p.area / (p.mass * p.specificHeat)) {}

double CoolingModel::dTdt(double T) const { return dudt(T - params.Tambient); }

double CoolingModel::dudt(double u) const {
    double Ta = params.Tambient, T = Ta + u;
    // T^4 - Ta^4 = u (T + Ta) (T^2 + Ta^2): accurate near T = Ta
    double rad = params.emissivity * kStefanBoltzmannConstant * u * (T + Ta) * (T * T + Ta * Ta);
    return -k * (rad + params.h * u);
}

double CoolingModel::RadiativeTimeConstant() const {
    double d = params.emissivity * kStefanBoltzmannConstant * std::pow(params.T0, 3) * k;
    return d > 0 ? 1 / d : kInfinity;
}

double CoolingModel::ConvectiveTimeConstant() const {
    double d = params.h * k;
    return d > 0 ? 1 / d : kInfinity;
}

double CoolingModel::Temperature(double t) const {
    if (t <= 0) return params.T0;
    if (params.h == 0 && params.Tambient == 0)
        return RadiativeCoolingTemperature(params.T0, params.emissivity, params.area, params.mass,
                                           params.specificHeat, t);
    return IntegrateTemperature(t);
}

double CoolingModel::IntegrateTemperature(double t) const {
    return IntegrateTemperatures(std::span<const double>(&t, 1))[0];
}

std::vector<double> CoolingModel::IntegrateTemperatures(std::span<const double> times) const {
    std::vector<double> result(times.size(), params.T0);
    std::vector<size_t> order(times.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return times[a] < times[b]; });

    // The integrated quantity is u = T - Ta, with error control relative to |u|: T - Ta
    // decays monotonically and keeps its relative accuracy as T approaches Ta.
    double Ta = params.Tambient, u = params.T0 - Ta;
    // Stiffness scale |df/du| at the start picks the first step.
    double rate = k * (4 * params.emissivity * kStefanBoltzmannConstant *
                           std::pow(std::max(params.T0, Ta), 3) +
                       params.h);
    if (!(rate > 0) || u == 0) return result;  // no heat exchange: T stays T0
    double step = 1e-3 / rate;
    // Absolute tolerance floor (K), far below any temperature that matters.
    double absTol = relTol * 1e-30 * std::abs(u);

    double t = 0;
    double k1 = dudt(u);
    for (size_t idx : order) {
        double tEnd = times[idx];
        while (t < tEnd) {
            bool last = t + step >= tEnd;
            double hStep = last ? tEnd - t : step;
            double k2 = dudt(u + hStep * a21 * k1);
            double k3 = dudt(u + hStep * (a31 * k1 + a32 * k2));
            double k4 = dudt(u + hStep * (a41 * k1 + a42 * k2 + a43 * k3));
            double k5 = dudt(u + hStep * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4));
            double k6 = dudt(u + hStep * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5));
            double uNew = u + hStep * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
            double k7 = dudt(uNew);
            double err =
                hStep * std::abs(e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
            double scale = absTol + relTol * std::max(std::abs(u), std::abs(uNew));
            double ratio = err / scale;
            // Step-size controller (Hairer, Norsett & Wanner, "Solving ODEs I", II.4)
            double factor = ratio == 0 ? 5 : std::clamp(0.9 * std::pow(ratio, -0.2), 0.2, 5.0);
            // T - Ta never changes sign in the exact solution
            bool accept = ratio <= 1 && std::isfinite(uNew) && uNew * u >= 0;
            if (accept) {
                t = last ? tEnd : t + hStep;
                u = uNew;
                k1 = k7;
                // A clipped final step says nothing about the step size that works.
                if (!last || factor < 1) step = hStep * factor;
            } else {
                step = hStep * std::min(factor, 0.5);
            }
        }
        result[idx] = Ta + u;
    }
    return result;
}

// Closed forms
double RadiativeCoolingTemperature(double T0, double emissivity, double area, double mass,
                                   double specificHeat, double t) {
    if (t <= 0) return T0;
    double invT3 = 1 / (T0 * T0 * T0) +
                   3 * emissivity * kStefanBoltzmannConstant * area * t / (mass * specificHeat);
    return 1 / std::cbrt(invT3);
}

double RadiativeCoolingTime(double T0, double T, double Ta, double emissivity, double area,
                            double mass, double specificHeat) {
    if (T >= T0) return 0;
    if (T <= Ta) return kInfinity;
    // I = integral_T^T0 dT' / (T'^4 - Ta^4); t = I m c / (eps sigma A)
    double I;
    double r = Ta / T;
    if (r < 0.05) {
        // Series 1 / (T^4 - a^4) = sum_n a^(4n) T^-(4n+4), integrated term by term (avoids the
        // cancellation of the closed form below when Ta << T).
        I = 0;
        double a4n = 1;  // Ta^(4n)
        for (int n = 0; n < 20; ++n) {
            int p = 4 * n + 3;
            double term = a4n * (std::pow(T, -p) - std::pow(T0, -p)) / p;
            I += term;
            if (std::abs(term) <= 1e-17 * I) break;
            a4n *= Ta * Ta * Ta * Ta;
        }
    } else {
        // Differences of the antiderivative written without cancellation between terms:
        // ln((T0-a)/(T0+a)) - ln((T-a)/(T+a)) = log1p(2a (T0 - T) / ((T0 + a)(T - a)))
        // atan(T0/a) - atan(T/a) = atan(a (T0 - T) / (a^2 + T0 T))
        double a = Ta;
        double L = std::log1p(2 * a * (T0 - T) / ((T0 + a) * (T - a)));
        double At = std::atan(a * (T0 - T) / (a * a + T0 * T));
        I = (0.25 * L - 0.5 * At) / (a * a * a);
    }
    return I * mass * specificHeat / (emissivity * kStefanBoltzmannConstant * area);
}

}  // namespace kiln
