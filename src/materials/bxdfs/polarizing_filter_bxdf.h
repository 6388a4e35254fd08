// Thin polarising filters: an ideal linear polariser or a linear retarder (wave plate) sheet.
// Light passes straight through (wi = -wo) and nothing is reflected. The element's axis lies in
// the surface at `angle` (radians) from the shading frame's x axis towards y; for light crossing
// the sheet obliquely the axis seen by the beam is its projection onto the plane perpendicular
// to the beam (the usual thin-sheet model).
//
// Unpolarised transport sees only the intensity: a polariser transmits half of unpolarised
// light, a retarder all of it. Polarised transport applies the element's Mueller matrix
// (spectral/polarization.h), so crossed polarisers block light.
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"
#include "spectral/polarization.h"

namespace kiln {

class PolarizingFilterBxDF {
  public:
    enum class Kind { LinearPolarizer, Retarder };

    PolarizingFilterBxDF() = default;
    // retardance: radians (retarders only; pi / 2 is a quarter-wave plate).
    PolarizingFilterBxDF(Kind kind, Float angle, Float retardance = 0)
        : kind(kind), angle(angle), retardance(retardance) {}

    SampledSpectrum f(Vector3f, Vector3f, TransportMode) const { return SampledSpectrum(0.f); }
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f, Vector3f, TransportMode,
              BxDFReflTransFlags = BxDFReflTransFlags::All) const {
        return 0;
    }
    BxDFFlags Flags() const { return BxDFFlags::SpecularTransmission; }
    void Regularize() {}

    // Polarised transport (frames of fresnel_mueller.h).
    MuellerMatrix MuellerF(Vector3f, Vector3f, TransportMode) const { return {}; }
    MuellerMatrix MuellerSample(Vector3f wo, const BSDFSample& bs, TransportMode mode) const;

    // The fraction of unpolarised light transmitted.
    Float UnpolarizedTransmittance() const { return kind == Kind::LinearPolarizer ? 0.5f : 1; }

  private:
    Kind kind = Kind::LinearPolarizer;
    Float angle = 0, retardance = 0;
};

}  // namespace kiln
