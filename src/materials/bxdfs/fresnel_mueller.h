// Mueller matrices of smooth interfaces, and the frames they are given in.
//
// A BxDF's Mueller matrix M(wo, wi) (local shading frame, z = normal) maps the Stokes vector of
// light arriving from wi (travelling along -wi) to that of light leaving towards wo. kiln's
// BxDFs give it with reference axes perpendicular to the planes that contain the normal:
// PlaneAxis(z, wi) for the incident light and PlaneAxis(z, wo) for the outgoing light, so
// smooth-interface matrices have Fresnel's s (perpendicular) component along x and p along y.
// BSDF rotates them to the implicit frames of render-space directions (spectral/polarization.h).
//
// Fresnel amplitudes follow fresnel.h (Born & Wolf signs, as pbrt-v4): with reference axes s
// for both incident and reflected light, a perfect mirror at normal incidence has
// M = diag(1, 1, -1, -1) (the y axis turns over with the direction of travel).
// Reference: Collett, Field Guide to Polarization (2005), sec. 5.5; Wilkie & Weidlich (2016).
#pragma once

#include "base/vecmath.h"
#include "spectral/polarization.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// Reflection from a smooth interface with complex relative IOR eta + i k (per wavelength) at
// incidence cosTheta_i (clamped to [0, 1]), reference axes s: M00 = (Rs + Rp) / 2, the
// unpolarised reflectance, M01 = (Rs - Rp) / 2, the phase difference between the s and p waves
// in the lower block: M22 = M33 = Re(rs conj(rp)), M23 = -M32 = Im(rs conj(rp)).
MuellerMatrix FresnelReflectionMueller(Float cosTheta_i, const SampledSpectrum& eta,
                                       const SampledSpectrum& k);
// The same for a real relative IOR (dielectrics), incidence from either side (cosTheta_i < 0:
// from below, eta inverted, as FrDielectric); total internal reflection has |rs| = |rp| = 1
// and a phase difference.
MuellerMatrix FresnelReflectionMueller(Float cosTheta_i, Float eta);
// Transmission through a smooth dielectric interface (power transmittances Ts = 1 - Rs,
// Tp = 1 - Rp, no phase difference: M22 = M33 = sqrt(Ts Tp)), without the 1/eta^2 radiance
// scaling; zero under total internal reflection.
MuellerMatrix FresnelTransmissionMueller(Float cosTheta_i, Float eta);
// An absorbing dielectric of index eta + i k (fresnel.h's FrAbsorbingDielectric; k = 0: the two
// above). Reflection from inside takes the matrix of the outside direction that refracts into
// cosTheta_i (total internal reflection: the dielectric's, with its phase difference);
// transmission has Ts = 1 - Rs, Tp = 1 - Rp and no phase difference, as above.
MuellerMatrix AbsorbingDielectricReflectionMueller(Float cosTheta_i, Float eta, Float k);
MuellerMatrix AbsorbingDielectricTransmissionMueller(Float cosTheta_i, Float eta, Float k);

// A Mueller matrix of an interface with normal m (local frame), given with reference axes s
// about m (PlaneAxis(m, wi), PlaneAxis(m, wo)), re-expressed with the macro-surface axes
// PlaneAxis(z, wi), PlaneAxis(z, wo): for microfacets.
MuellerMatrix MicrofacetToSurfaceFrame(const MuellerMatrix& M, Vector3f wo, Vector3f wi,
                                       Vector3f wm);

}  // namespace kiln
