// Planck's law evaluated without overflow, underflow to NaN, or cancellation.
#include "spectral/planck.h"

#include <cfloat>
#include <cmath>
#include <limits>

#include "base/quadrature.h"

namespace kiln {

namespace {

// c1L per nm of wavelength: 2 h c^2 * 1e-9 (the 1e-9 converts "per m" to "per nm").
constexpr double kC1LPerNm = kFirstRadiationConstantL * 1e-9;

double Pow5(double x) {
    double x2 = x * x;
    return x2 * x2 * x;
}

// log(e^x - 1) for x >= 0, accurate for tiny and huge x; -inf at x = 0.
double LogExpm1(double x) {
    if (x > 30) return x + std::log1p(-std::exp(-x));
    return std::log(std::expm1(x));
}

// exp(v) clamped to the largest finite double; 0 for v = -inf.
double SafeExp(double v) {
    if (v >= std::log(DBL_MAX)) return DBL_MAX;
    return std::exp(v);
}

}  // namespace

double planck_radiance(double lambda_nm, double T) {
    if (!(T > 0) || !(lambda_nm > 0) || std::isinf(lambda_nm)) return 0;
    if (std::isinf(T)) return DBL_MAX;
    const double lambda = lambda_nm * 1e-9;  // m

    // Direct form where every intermediate is a normal finite number
    const double lT = lambda * T;
    if (lT > 0 && std::isfinite(lT)) {
        const double x = kSecondRadiationConstant / lT;
        const double l5 = Pow5(lambda);
        if (x < 700 && l5 > DBL_MIN && std::isfinite(l5)) {
            const double em1 = std::expm1(x);
            if (em1 > DBL_MIN) {
                const double B = kC1LPerNm / (l5 * em1);
                if (std::isfinite(B)) return B;
            }
        }
    }

    // Logarithmic form for the extremes (Wien tail underflowing to 0, huge lambda T)
    const double logLambda = std::log(lambda), logT = std::log(T);
    const double logX = std::log(kSecondRadiationConstant) - logLambda - logT;
    const double x = std::exp(logX);
    const double logEm1 = (x < 1e-8) ? logX + std::log1p(0.5 * x) : LogExpm1(x);
    return SafeExp(std::log(kC1LPerNm) - 5 * logLambda - logEm1);
}

SampledSpectrum planck_radiance(const SampledWavelengths& lambda, double T) {
    SampledSpectrum s;
    const double maxFloat = double(std::numeric_limits<Float>::max());
    for (int i = 0; i < NSpectrumSamples; ++i) {
        double l = lambda[i];
        // The exponential in single precision where x = c2 / (lambda T) keeps it well inside
        // float's range (relative error below 1e-5, growing with x; the double function
        // keeps 1e-12); the double function for the tails and extremes
        double lT = l * 1e-9 * T;
        double x = lT > 0 ? kSecondRadiationConstant / lT : 0;
        if (x > 1e-3 && x < 80 && std::isfinite(T) && l < 1e6) {
            float e = std::exp(float(x));
            double B = kC1LPerNm / (Pow5(l * 1e-9) * (double(e) - 1));
            s[i] = Float(std::min(B, maxFloat));
        } else {
            s[i] = Float(std::min(planck_radiance(l, T), maxFloat));
        }
    }
    return s;
}

double planck_radiance_normalized(double lambda_nm, double T) {
    if (!(T > 0) || !(lambda_nm > 0) || std::isinf(lambda_nm) || std::isinf(T)) return 0;
    // B(l) / B(lp) = (lp / l)^5 (e^x5 - 1) / (e^x - 1), x = x5 lp / l, lp = b / T.
    const double logRatio = std::log(kWienDisplacementConstant) - std::log(T) -
                            std::log(lambda_nm * 1e-9);  // log(lp / l)
    const double x = kWienX5 * std::exp(logRatio);
    const double logEm1 =
        (x < 1e-8) ? std::log(kWienX5) + logRatio + std::log1p(0.5 * x) : LogExpm1(x);
    const double v = SafeExp(5 * logRatio + LogExpm1(kWienX5) - logEm1);
    return std::min(v, 1.0);
}

SampledSpectrum planck_radiance_normalized(const SampledWavelengths& lambda, double T) {
    SampledSpectrum s;
    if (!(T >= 1 && T <= 1e6)) {
        for (int i = 0; i < NSpectrumSamples; ++i)
            s[i] = Float(planck_radiance_normalized(lambda[i], T));
        return s;
    }
    // 1 / B(lambda_peak, T), lambda_peak = b / T: b^5 (e^x5 - 1) / (c1L T^5), per nm
    const double b = kWienDisplacementConstant, T2 = T * T;
    const double inversePeak = Pow5(b) * std::expm1(kWienX5) / (kC1LPerNm * T2 * T2 * T);
    s = planck_radiance(lambda, T);
    for (int i = 0; i < NSpectrumSamples; ++i)
        s[i] = Float(std::min(double(s[i]) * inversePeak, 1.0));
    return s;
}

double planck_peak_wavelength_nm(double T) {
    if (!(T > 0)) return std::numeric_limits<double>::infinity();
    return kWienDisplacementConstant / T * 1e9;
}

double stefan_boltzmann_radiance(double T) {
    if (!(T > 0)) return 0;
    const double T2 = T * T;
    return std::min(kStefanBoltzmannConstant * T2 * T2 / 3.14159265358979323846, DBL_MAX);
}

namespace {

// Integral of t^3 / (e^t - 1) from x >= 1 to infinity, by its series (terms fall by e^-x at
// least: 40 terms reach 1e-17 relative at x = 1).
double PlanckTail(double x) {
    double sum = 0;
    for (int n = 1; n <= 64; ++n) {
        double term = std::exp(-n * x) / n *
                      (x * x * x + 3 * x * x / n + 6 * x / (n * n) + 6.0 / (double(n) * n * n));
        sum += term;
        if (term < 1e-17 * sum) break;
    }
    return sum;
}

// Integral of t^3 / (e^t - 1) over [a, b] within [0, 1], where the integrand is smooth (t^2
// near 0): 8-point Gauss-Legendre, exact to about 1e-14.
double PlanckHead(double a, double b) {
    if (!(b > a)) return 0;
    QuadratureRule rule = GaussLegendre(8, a, b);
    double sum = 0;
    for (size_t i = 0; i < rule.x.size(); ++i) {
        double t = rule.x[i];
        sum += rule.weight[i] * (t > 0 ? t * t * t / std::expm1(t) : 0);
    }
    return sum;
}

}  // namespace

double planck_band_radiance(double lambda1_nm, double lambda2_nm, double T) {
    if (!(T > 0) || !(lambda2_nm > lambda1_nm) || !(lambda2_nm > 0)) return 0;
    lambda1_nm = std::max(lambda1_nm, 0.0);
    // Ends in x = c2 / (lambda T): xLow from the long wavelength, xHigh from the short one
    double xLow = kSecondRadiationConstant / (lambda2_nm * 1e-9 * T);
    double xHigh = lambda1_nm > 0 ? kSecondRadiationConstant / (lambda1_nm * 1e-9 * T)
                                  : std::numeric_limits<double>::infinity();
    if (xHigh < 1e-12) {
        // Rayleigh-Jeans (relative error below x / 2), also where T^4 would overflow:
        // integral of 2 c k T / lambda^4 over the band
        double l1 = lambda1_nm * 1e-9, l2 = lambda2_nm * 1e-9;
        double rj = 2 * kSpeedOfLight * kBoltzmannConstant * T / 3 *
                    (1 / (l1 * l1 * l1) - 1 / (l2 * l2 * l2));
        return std::min(rj, DBL_MAX);
    }
    double integral;
    if (xLow >= 1) {
        integral = PlanckTail(xLow) - (std::isinf(xHigh) ? 0 : PlanckTail(xHigh));
    } else {
        integral = PlanckHead(xLow, std::min(xHigh, 1.0));
        if (xHigh > 1) integral += PlanckTail(1) - (std::isinf(xHigh) ? 0 : PlanckTail(xHigh));
    }
    // 2 k^4 T^4 / (h^3 c^2) = (15 / pi^4) sigma T^4 / pi
    constexpr double pi = 3.14159265358979323846;
    double scale = 15 / (pi * pi * pi * pi) * kStefanBoltzmannConstant / pi;
    double T2 = T * T;
    return std::min(scale * T2 * T2 * std::max(integral, 0.0), DBL_MAX);
}

double radiance_temperature(double lambda_nm, double L) {
    if (!(L > 0) || !(lambda_nm > 0) || std::isinf(lambda_nm)) return 0;
    if (std::isinf(L)) return std::numeric_limits<double>::infinity();
    // ln(1 + a), a = c1L / (lambda^5 L) in logarithms (a over- or underflows at the extremes)
    const double lambda = lambda_nm * 1e-9;  // m
    const double logA = std::log(kC1LPerNm) - 5 * std::log(lambda) - std::log(L);
    const double ln1pA =
        logA > 30 ? logA + std::log1p(std::exp(-logA)) : std::log1p(std::exp(logA));
    if (!(ln1pA > 0)) return std::numeric_limits<double>::infinity();
    return kSecondRadiationConstant / (lambda * ln1pA);
}

double band_radiance_temperature(double lambda1_nm, double lambda2_nm, double L) {
    if (!(L > 0) || !(lambda2_nm > std::max(lambda1_nm, 0.0))) return 0;
    double logLo = std::log(1e-3), logHi = std::log(kMaxRenderTemperature);
    if (planck_band_radiance(lambda1_nm, lambda2_nm, kMaxRenderTemperature) <= L)
        return kMaxRenderTemperature;
    if (planck_band_radiance(lambda1_nm, lambda2_nm, 1e-3) >= L) return 1e-3;
    // Invariant: band radiance at exp(logLo) below L, at exp(logHi) at least L
    while (logHi - logLo > 1e-12) {
        double logMid = 0.5 * (logLo + logHi);
        if (planck_band_radiance(lambda1_nm, lambda2_nm, std::exp(logMid)) < L)
            logLo = logMid;
        else
            logHi = logMid;
    }
    return std::exp(0.5 * (logLo + logHi));
}

}  // namespace kiln
