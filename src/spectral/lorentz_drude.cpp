#include "spectral/lorentz_drude.h"

#include <array>
#include <cmath>

namespace kiln {

namespace {

// One metal of Rakic et al. (1998), Table 1: plasma energy wp (eV); oscillator j = 0 is the
// Drude term (w_0 = 0); f_j, G_j (eV), w_j (eV). Unused oscillators have f = 0.
struct Oscillator {
    double f, gamma, omega;
};
struct Metal {
    std::string_view symbol;
    double omegaP;
    std::array<Oscillator, 6> terms;
};

constexpr Metal kMetals[] = {
    {"Ag",
     9.01,
     {{{0.845, 0.048, 0},
       {0.065, 3.886, 0.816},
       {0.124, 0.452, 4.481},
       {0.011, 0.065, 8.185},
       {0.840, 0.916, 9.083},
       {5.646, 2.419, 20.29}}}},
    {"Au",
     9.03,
     {{{0.760, 0.053, 0},
       {0.024, 0.241, 0.415},
       {0.010, 0.345, 0.830},
       {0.071, 0.870, 2.969},
       {0.601, 2.494, 4.304},
       {4.384, 2.214, 13.32}}}},
    {"Cu",
     10.83,
     {{{0.575, 0.030, 0},
       {0.061, 0.378, 0.291},
       {0.104, 1.056, 2.957},
       {0.723, 3.213, 5.300},
       {0.638, 4.305, 11.18},
       {0, 0, 0}}}},
    {"Al",
     14.98,
     {{{0.523, 0.047, 0},
       {0.227, 0.333, 0.162},
       {0.050, 0.312, 1.544},
       {0.166, 1.351, 1.808},
       {0.030, 3.382, 3.473},
       {0, 0, 0}}}},
    {"Be",
     18.51,
     {{{0.084, 0.035, 0},
       {0.031, 1.664, 0.100},
       {0.140, 3.395, 1.032},
       {0.530, 4.454, 3.183},
       {0.130, 1.802, 4.604},
       {0, 0, 0}}}},
    {"Cr",
     10.75,
     {{{0.168, 0.047, 0},
       {0.151, 3.175, 0.121},
       {0.150, 1.305, 0.543},
       {1.149, 2.676, 1.970},
       {0.825, 1.335, 8.775},
       {0, 0, 0}}}},
    {"Ni",
     15.92,
     {{{0.096, 0.048, 0},
       {0.100, 4.511, 0.174},
       {0.135, 1.334, 0.582},
       {0.106, 2.178, 1.597},
       {0.729, 6.292, 6.089},
       {0, 0, 0}}}},
    {"Pd",
     9.72,
     {{{0.330, 0.008, 0},
       {0.649, 2.950, 0.336},
       {0.121, 0.555, 0.501},
       {0.638, 4.621, 1.659},
       {0.453, 3.236, 5.715},
       {0, 0, 0}}}},
    {"Pt",
     9.59,
     {{{0.333, 0.080, 0},
       {0.191, 0.517, 0.780},
       {0.659, 1.838, 1.314},
       {0.547, 3.668, 3.141},
       {3.576, 8.517, 9.249},
       {0, 0, 0}}}},
    {"Ti",
     7.29,
     {{{0.148, 0.082, 0},
       {0.899, 2.276, 0.777},
       {0.393, 2.518, 1.545},
       {0.187, 1.663, 2.509},
       {0.001, 1.762, 19.43},
       {0, 0, 0}}}},
    {"W",
     13.22,
     {{{0.206, 0.064, 0},
       {0.054, 0.530, 1.004},
       {0.166, 1.281, 1.917},
       {0.706, 3.332, 3.580},
       {2.590, 5.836, 7.498},
       {0, 0, 0}}}},
};

}  // namespace

std::optional<std::complex<double>> LorentzDrudePermittivity(std::string_view metal,
                                                             double lambda_nm,
                                                             const LorentzDrudeScaling& s) {
    for (const Metal& m : kMetals) {
        if (m.symbol != metal) continue;
        using C = std::complex<double>;
        const double E = 1239.841984 / lambda_nm, wp2 = m.omegaP * m.omegaP;
        const Oscillator& drude = m.terms[0];
        C eps = 1.0 - drude.f * s.drudeStrength * wp2 / (E * C(E, drude.gamma * s.drudeDamping));
        for (size_t j = 1; j < m.terms.size(); ++j) {
            const Oscillator& o = m.terms[j];
            if (o.f == 0) continue;
            eps += o.f * s.lorentzStrength * wp2 /
                   C(o.omega * o.omega - E * E, -E * o.gamma * s.lorentzDamping);
        }
        return eps;
    }
    return std::nullopt;
}

std::optional<std::complex<double>> LorentzDrudeIndex(std::string_view metal, double lambda_nm) {
    std::optional<std::complex<double>> eps = LorentzDrudePermittivity(metal, lambda_nm);
    if (!eps) return std::nullopt;
    return std::sqrt(*eps);  // principal root: n > 0, k >= 0 where Im eps >= 0
}

}  // namespace kiln
