// Henyey-Greenstein phase function, used for the medium between the layers of a LayeredBxDF.
//
// Convention (pbrt-v4): wo and wi both point away from the scattering point, so forward
// scattering (g > 0) favours wi = -wo. p is per steradian.
// Reference: Henyey & Greenstein 1941, ApJ 93:70-83.
#pragma once

#include <optional>

#include "base/vecmath.h"

namespace kiln {

// Phase function value (sr^-1) for the cosine between wo and wi and asymmetry g in (-1, 1).
inline Float HenyeyGreenstein(Float cosTheta, Float g) {
    Float denom = 1 + Sqr(g) + 2 * g * cosTheta;
    return Inv4Pi * (1 - Sqr(g)) / (denom * SafeSqrt(denom));
}

// Samples wi from p(wo, .); *pdf is its density (equal to the phase function value).
inline Vector3f SampleHenyeyGreenstein(Vector3f wo, Float g, Point2f u, Float* pdf) {
    Float cosTheta;
    if (std::abs(g) < 1e-3f)
        cosTheta = 1 - 2 * u.x;
    else
        cosTheta = -1 / (2 * g) * (1 + Sqr(g) - Sqr((1 - Sqr(g)) / (1 + g - 2 * g * u.x)));
    cosTheta = Clamp(cosTheta, -1, 1);
    Float sinTheta = SafeSqrt(1 - Sqr(cosTheta));
    Vector3f wi = Frame::FromZ(wo).FromLocal(SphericalDirection(sinTheta, cosTheta, 2 * Pi * u.y));
    if (pdf) *pdf = HenyeyGreenstein(cosTheta, g);
    return wi;
}

struct PhaseFunctionSample {
    Float p;
    Vector3f wi;
    Float pdf;
};

class HGPhaseFunction {
  public:
    explicit HGPhaseFunction(Float g) : g(g) {}
    Float p(Vector3f wo, Vector3f wi) const { return HenyeyGreenstein(Dot(wo, wi), g); }
    std::optional<PhaseFunctionSample> Sample_p(Vector3f wo, Point2f u) const {
        Float pdf;
        Vector3f wi = SampleHenyeyGreenstein(wo, g, u, &pdf);
        return PhaseFunctionSample{pdf, wi, pdf};
    }
    Float PDF(Vector3f wo, Vector3f wi) const { return p(wo, wi); }

  private:
    Float g;
};

}  // namespace kiln
