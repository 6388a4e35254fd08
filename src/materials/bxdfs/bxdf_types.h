// What every BxDF shares: transport mode, lobe flags and the sample a BxDF returns (pbrt-v4's
// TransportMode, BxDFFlags, BxDFReflTransFlags and BSDFSample).
#pragma once

#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// Radiance: paths traced from the camera; Importance: from lights (non-symmetric scattering
// at refraction is handled accordingly).
enum class TransportMode { Radiance, Importance };

enum BxDFFlags : unsigned {
    Unset = 0,
    Reflection = 1 << 0,
    Transmission = 1 << 1,
    Diffuse = 1 << 2,
    Glossy = 1 << 3,
    Specular = 1 << 4,
    // Transmission that leaves the direction unchanged (a thin sheet: thindielectric). Light
    // sampling looks through such a surface (the integrators' shadow rays cross it).
    StraightThrough = 1 << 5,
    DiffuseReflection = Diffuse | Reflection,
    DiffuseTransmission = Diffuse | Transmission,
    GlossyReflection = Glossy | Reflection,
    GlossyTransmission = Glossy | Transmission,
    SpecularReflection = Specular | Reflection,
    SpecularTransmission = Specular | Transmission,
    All = Diffuse | Glossy | Specular | Reflection | Transmission
};
inline BxDFFlags operator|(BxDFFlags a, BxDFFlags b) {
    return BxDFFlags(unsigned(a) | unsigned(b));
}
inline bool IsReflective(BxDFFlags f) { return f & BxDFFlags::Reflection; }
inline bool IsTransmissive(BxDFFlags f) { return f & BxDFFlags::Transmission; }
inline bool IsDiffuse(BxDFFlags f) { return f & BxDFFlags::Diffuse; }
inline bool IsGlossy(BxDFFlags f) { return f & BxDFFlags::Glossy; }
inline bool IsSpecular(BxDFFlags f) { return f & BxDFFlags::Specular; }
inline bool IsNonSpecular(BxDFFlags f) { return f & (BxDFFlags::Diffuse | BxDFFlags::Glossy); }
inline bool IsStraightThrough(BxDFFlags f) { return f & BxDFFlags::StraightThrough; }
// Specular reflection and specular transmission and nothing else: a smooth dielectric interface
inline bool IsSmoothDielectric(BxDFFlags f) {
    return f == (BxDFFlags::SpecularReflection | BxDFFlags::SpecularTransmission);
}

// Which hemispheres a sampling call may choose from.
enum class BxDFReflTransFlags : unsigned {
    Unset = 0,
    Reflection = 1 << 0,
    Transmission = 1 << 1,
    All = Reflection | Transmission
};
inline bool operator&(BxDFReflTransFlags a, BxDFReflTransFlags b) {
    return (unsigned(a) & unsigned(b)) != 0;
}

// A sampled direction wi with BSDF value f (sr^-1; per wavelength, or a Mueller matrix per
// wavelength in polarised transport), its pdf (sr^-1; for specular lobes the discrete
// probability), the lobe flags, the relative IOR crossed on transmission (1 otherwise) and
// whether pdf is only proportional to the true density (layered BxDFs).
template <typename Value>
struct BSDFSampleOf {
    Value f;
    Vector3f wi;
    Float pdf = 0;
    BxDFFlags flags = BxDFFlags::Unset;
    Float eta = 1;
    bool pdfIsProportional = false;

    BSDFSampleOf() = default;
    BSDFSampleOf(Value f, Vector3f wi, Float pdf, BxDFFlags flags, Float eta = 1,
                 bool pdfIsProportional = false)
        : f(f), wi(wi), pdf(pdf), flags(flags), eta(eta), pdfIsProportional(pdfIsProportional) {}
    // The same sample with another value (its polarised counterpart).
    template <typename Other>
    BSDFSampleOf(const BSDFSampleOf<Other>& bs, Value f)
        : BSDFSampleOf(f, bs.wi, bs.pdf, bs.flags, bs.eta, bs.pdfIsProportional) {}

    bool IsReflection() const { return kiln::IsReflective(flags); }
    bool IsTransmission() const { return kiln::IsTransmissive(flags); }
    bool IsSpecular() const { return kiln::IsSpecular(flags); }
    bool IsStraightThrough() const { return kiln::IsStraightThrough(flags); }
};
using BSDFSample = BSDFSampleOf<SampledSpectrum>;

}  // namespace kiln
