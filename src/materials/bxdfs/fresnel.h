// Fresnel reflectance of smooth interfaces and the laws of specular reflection and refraction.
//
// Angles are given by cosines measured from the surface normal; eta is the relative index of
// refraction (transmitted side over incident side, dimensionless); k is the extinction
// coefficient of an absorbing medium (imaginary part of its complex IOR, eta = n + i k).
// Reflectances are fractions of incident power in [0, 1]. The Fresnel equations are
// evaluated in double precision so that reflectance near grazing incidence, where
// emissivity = 1 - R is small and matters most for Kirchhoff emission, keeps full accuracy.
// Reference: Born & Wolf, Principles of Optics (7th ed.), Sec. 1.5.2 and 14.2;
// pbrt-v4 Sec. 9.3 and 9.4.
#pragma once

#include <complex>

#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// Reflection and refraction
//
// Mirror reflection of wo about n (both pointing away from the surface).
inline Vector3f Reflect(Vector3f wo, Vector3f n) { return -wo + 2 * Dot(wo, n) * n; }

// Refracts wi (pointing away from the surface) through the interface with normal n, eta being
// the IOR below n over the IOR above n. Handles wi on either side of n; on success *etap is
// the relative IOR actually crossed and *wt the (unit) transmitted direction. Returns false on
// total internal reflection.
bool Refract(Vector3f wi, Normal3f n, Float eta, Float* etap, Vector3f* wt);

// Dielectric interfaces
//
// Unpolarised reflectance. cosTheta_i < 0 means incidence from the other side (eta is then
// inverted); returns 1 under total internal reflection.
Float FrDielectric(Float cosTheta_i, Float eta);

// Reflectances for light polarised perpendicular (s) and parallel (p) to the plane of
// incidence; their average is the unpolarised reflectance.
struct FresnelRsRp {
    Float Rs, Rp;
};
FresnelRsRp FrDielectricPolarized(Float cosTheta_i, Float eta);

// Conductors (absorbing media)
//
// Per-polarisation reflectances for complex relative IOR eta = n + i k. cosTheta_i is clamped
// to [0, 1] (conductors are opaque: light arrives only from outside).
FresnelRsRp FrComplexPolarized(Float cosTheta_i, std::complex<Float> eta);

// Complex amplitude reflection coefficients r_s, r_p (Born & Wolf sign convention as in
// pbrt-v4: r_p = (eta cos_i - cos_t) / (eta cos_i + cos_t)); |r|^2 are the reflectances. For
// Mueller-matrix (polarised) transport; valid for real eta (including TIR) and complex eta.
struct FresnelAmplitudes {
    std::complex<double> rs, rp;
};
FresnelAmplitudes FrComplexAmplitudes(Float cosTheta_i, std::complex<Float> eta);

// Unpolarised reflectance of a conductor; scalar and per sampled wavelength.
Float FrComplex(Float cosTheta_i, std::complex<Float> eta);
SampledSpectrum FrComplex(Float cosTheta_i, SampledSpectrum eta, SampledSpectrum k);

// Absorbing dielectrics (glass through the infrared)
//
// The interface into a dielectric of complex index eta + i k (inside over outside, k >= 0),
// seen from either side. From outside (cosTheta_i >= 0): the complex Fresnel reflectances.
// From inside: those of the outside direction that refracts into this one by Snell's law with
// the real eta, and total reflection beyond the critical angle. So the interface is reciprocal
// (R inside at theta_t = R outside at theta_i), as the closed-cavity equilibrium needs; the
// inhomogeneous waves of an absorbing medium are left out (where k is large enough for them to
// matter, light entering the glass is absorbed within micrometres). k = 0 gives FrDielectric.
//
// The cosine of that outside direction (cosTheta_i itself from outside; 0 beyond the
// critical angle).
Float AbsorbingDielectricOutsideCosine(Float cosTheta_i, Float eta);
FresnelRsRp FrAbsorbingDielectricPolarized(Float cosTheta_i, Float eta, Float k);
Float FrAbsorbingDielectric(Float cosTheta_i, Float eta, Float k);

}  // namespace kiln
