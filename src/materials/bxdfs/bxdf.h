// BxDF: the closed set of scattering functions, held by value and dispatched with std::visit.
//
// All directions are in the local shading frame (normal = +z) and point away from the surface.
#pragma once

#include <optional>
#include <span>
#include <type_traits>
#include <variant>

#include "materials/bxdfs/bxdf_types.h"
#include "materials/bxdfs/conductor_bxdf.h"
#include "materials/bxdfs/dielectric_bxdf.h"
#include "materials/bxdfs/diffuse_bxdf.h"
#include "materials/bxdfs/layered_bxdf.h"
#include "materials/bxdfs/thin_dielectric_bxdf.h"

namespace kiln {

class BxDF {
  public:
    using Variant = std::variant<DiffuseBxDF, ConductorBxDF, DielectricBxDF, ThinDielectricBxDF,
                                 CoatedDiffuseBxDF, CoatedConductorBxDF>;

    BxDF() = default;  // a black DiffuseBxDF
    template <typename T>
    requires std::is_constructible_v<Variant, T> BxDF(T bxdf) : v(std::move(bxdf)) {}

    // BSDF value (sr^-1) per wavelength; includes no cosine factor.
    SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode mode) const {
        return std::visit([&](const auto& b) { return b.f(wo, wi, mode); }, v);
    }
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const {
        return std::visit([&](const auto& b) { return b.Sample_f(wo, uc, u, mode, sampleFlags); },
                          v);
    }
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const {
        return std::visit([&](const auto& b) { return b.PDF(wo, wi, mode, sampleFlags); }, v);
    }
    BxDFFlags Flags() const {
        return std::visit([](const auto& b) { return b.Flags(); }, v);
    }
    void Regularize() {
        std::visit([](auto& b) { b.Regularize(); }, v);
    }

    // Monte Carlo estimate of the directional albedo (reflection plus transmission) from wo,
    // using one Sample_f call per (uc[i], u2[i]) pair (pbrt-v4's BxDF::rho).
    SampledSpectrum rho(Vector3f wo, std::span<const Float> uc, std::span<const Point2f> u2) const;

    template <typename T>
    const T* Cast() const {
        return std::get_if<T>(&v);
    }
    template <typename T>
    bool Is() const {
        return std::holds_alternative<T>(v);
    }
    const Variant& Get() const { return v; }

  private:
    Variant v;
};

}  // namespace kiln
