// pbrt-v4's MeasuredBxDF: reflection from an RGL measured BRDF (measured_bxdf_data.h), Dupuy and
// Jakob 2018. With u_wo, u_wm the unit-square coordinates of wo and of the half vector wm
// (theta2u, phi2u; for an isotropic BRDF the azimuth of wm relative to wo's):
//   f(wo, wi) = max(0, spectra(R^-1(u_wm), phi_o, theta_o, lambda)) D(u_wm)
//               / (4 sigma(u_wo) cos theta_i)
// where R^-1 is the inverse of the visible-normal warp (vndf.Invert). Sampling draws a point of
// the unit square from the luminance table, warps it through the vndf to a normal and reflects
// wo about it; its pdf is vndf pdf x luminance pdf / (4 (wo . wm) 2 pi^2 u_wm.x sin theta_m),
// the Jacobians from the square to the normal's and then wi's solid angle (the second factor
// kept above 1e-6, as pbrt-v4). Two-sided: directions below the surface are mirrored through it
// (wo, wi -> -wo, -wi). Spectral values at the path's wavelengths are interpolated linearly
// between the file's wavelengths (held at the end values outside them).
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"
#include "materials/bxdfs/measured_bxdf_data.h"

namespace kiln {

class MeasuredBxDF {
  public:
    // Measured reflectance is taken as unpolarised (the files hold no polarisation).
    static constexpr bool kDepolarizes = true;

    MeasuredBxDF() = default;
    MeasuredBxDF(const MeasuredBxDFData* data, const SampledWavelengths& lambda);

    SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode mode) const;
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    BxDFFlags Flags() const { return BxDFFlags::GlossyReflection; }
    void Regularize() {}

    // What Sample_f draws from wo (wo.z > 0) with u, apart from the spectral values: f at the
    // wavelengths lambda is max(0, spectra(p, phi_o, theta_o, lambda)) * scale.
    struct Draw {
        Vector3f wi;
        Float pdf;
        Point2f p;
        Float scale, phi_o, theta_o;
    };
    static std::optional<Draw> SampleGeometry(const MeasuredBxDFData& data, Vector3f wo, Point2f u);
    // The same for f(wo, wi) (both with z > 0); pdf is not set.
    static std::optional<Draw> EvaluateGeometry(const MeasuredBxDFData& data, Vector3f wo,
                                                Vector3f wi);

    const MeasuredBxDFData* Data() const { return data; }
    // The wavelengths (nm) the values are given at.
    Float Lambda(int i) const { return lambda[i]; }

  private:
    // Spectral values at the point p of the vndf's unit square, clamped to >= 0.
    SampledSpectrum Spectra(Point2f p, Float phi_o, Float theta_o) const;

    const MeasuredBxDFData* data = nullptr;
    Float lambda[NSpectrumSamples] = {};
};

}  // namespace kiln
