// Optical constants of metals from the Lorentz-Drude model fitted by Rakic et al. (1998), for
// the infrared beyond kiln's tabulated metals (named_spectra.cpp extends metal-X-eta and
// metal-X-k with it up to 20 um).
//
// A. D. Rakic, A. B. Djurisic, J. M. Elazar, M. L. Majewski, "Optical properties of metallic
// films for vertical-cavity optoelectronic devices", Appl. Opt. 37(22), 5271-5283 (1998),
// doi:10.1364/AO.37.005271, Table 1. With photon energy E = 1239.841984 / lambda_nm (eV) and the
// time dependence exp(-i omega t):
//   eps(E) = 1 - f_0 wp^2 / (E (E + i G_0)) + sum_{j >= 1} f_j wp^2 / (w_j^2 - E^2 - i E G_j),
//   n + i k = sqrt(eps).
// The paper fits 0.1-5 eV (248 nm - 12.4 um); beyond 12.4 um the free-electron (Drude) term
// dominates and the model is extrapolated.
#pragma once

#include <complex>
#include <optional>
#include <string_view>

namespace kiln {

// n + i k of the metal with chemical symbol `metal` (Ag, Au, Cu, Al, Be, Cr, Ni, Pd, Pt, Ti,
// W) at lambda_nm; nullopt for other metals.
std::optional<std::complex<double>> LorentzDrudeIndex(std::string_view metal, double lambda_nm);

// Factors on the model's parameters (spectral/metal_temperature.h varies them with temperature):
// the Drude term's damping G_0 and strength f_0, the Lorentz dampings G_j and strengths f_j
// (j >= 1).
struct LorentzDrudeScaling {
    double drudeDamping = 1, drudeStrength = 1, lorentzDamping = 1, lorentzStrength = 1;
};

// The permittivity eps (= (n + i k)^2) of `metal` at lambda_nm with the scaled parameters;
// nullopt for metals the model lacks.
std::optional<std::complex<double>> LorentzDrudePermittivity(std::string_view metal,
                                                             double lambda_nm,
                                                             const LorentzDrudeScaling& s = {});

}  // namespace kiln
