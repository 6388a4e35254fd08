// BxDF: the closed set of scattering functions, held by value and dispatched with std::visit.
//
// All directions are in the local shading frame (normal = +z) and point away from the surface.
//
// f and Sample_f take the type of value that transport carries (Mitsuba 3's variants):
// SampledSpectrum (unpolarised, the default) or MuellerMatrix (polarised: frames as in
// fresnel_mueller.h). Every BxDF says which it is: one with polarising interfaces provides
// MuellerF and MuellerSample (PolarizingBxDF); the others (diffuse, layered, hair) declare
// `static constexpr bool kDepolarizes = true` (DepolarizingBxDF): their Mueller matrix is the
// ideal depolariser f diag(1, 0, 0, 0), which needs no frame. A BxDF that is neither, or both,
// does not compile into the closed set (static_assert below). Sampling is the same in both
// variants: the polarised sample is the unpolarised one with its Mueller value, so both make the
// same random decisions and M00 equals the unpolarised value (except for the thin dielectric,
// whose unpolarised value follows pbrt-v4 where the polarised one must conserve each wave:
// thin_dielectric_bxdf.cpp).
#pragma once

#include <concepts>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>

#include "base/closed_set.h"
#include "materials/bxdfs/bxdf_types.h"
#include "materials/bxdfs/conductor_bxdf.h"
#include "materials/bxdfs/dielectric_bxdf.h"
#include "materials/bxdfs/diffuse_bxdf.h"
#include "materials/bxdfs/diffuse_transmission_bxdf.h"
#include "materials/bxdfs/hair_bxdf.h"
#include "materials/bxdfs/layered_bxdf.h"
#include "materials/bxdfs/measured_bxdf.h"
#include "materials/bxdfs/normalized_fresnel_bxdf.h"
#include "materials/bxdfs/polarizing_filter_bxdf.h"
#include "materials/bxdfs/thin_dielectric_bxdf.h"
#include "spectral/polarization.h"

namespace kiln {

// A BxDF that evaluates and samples its Mueller matrix (polarised transport).
template <typename B>
concept PolarizingBxDF = requires(const B& b, Vector3f w, const BSDFSample& bs,
                                  TransportMode mode) {
    { b.MuellerF(w, w, mode) } -> std::same_as<MuellerMatrix>;
    { b.MuellerSample(w, bs, mode) } -> std::same_as<MuellerMatrix>;
};
// A BxDF that declares that it depolarises.
template <typename B>
concept DepolarizingBxDF = requires {
    requires B::kDepolarizes;
};
// Exactly one of the two: what polarised transport does with it is never a silent default.
template <typename B>
concept PolarizationDefinedBxDF = PolarizingBxDF<B>
!= DepolarizingBxDF<B>;

// The BxDFs, held by value
using BxDFSet = ClosedSet<DiffuseBxDF, ConductorBxDF, DielectricBxDF, ThinDielectricBxDF,
                          CoatedDiffuseBxDF, CoatedConductorBxDF, PolarizingFilterBxDF, HairBxDF,
                          DiffuseTransmissionBxDF, MeasuredBxDF, NormalizedFresnelBxDF>;

class BxDF : public BxDFSet {
  public:
    static_assert(
        []<typename... Ts>(ClosedSet<Ts...>*) {
            return (PolarizationDefinedBxDF<Ts> && ...);
        }(static_cast<BxDFSet*>(nullptr)),
        "every BxDF provides MuellerF and MuellerSample or declares kDepolarizes (bxdf.h)");

    BxDF() = default;  // a black DiffuseBxDF
    using ClosedSet::ClosedSet;

    // BSDF value (sr^-1) per wavelength; includes no cosine factor.
    template <typename Value = SampledSpectrum>
    Value f(Vector3f wo, Vector3f wi, TransportMode mode) const {
        if constexpr (std::is_same_v<Value, SampledSpectrum>) {
            return Dispatch([&](const auto& b) { return b.f(wo, wi, mode); });
        } else {
            return Dispatch([&](const auto& b) {
                if constexpr (PolarizingBxDF<std::decay_t<decltype(b)>>)
                    return b.MuellerF(wo, wi, mode);
                else
                    return MuellerMatrix::Depolarizer(b.f(wo, wi, mode));
            });
        }
    }
    template <typename Value = SampledSpectrum>
    std::optional<BSDFSampleOf<Value>> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const {
        if constexpr (std::is_same_v<Value, SampledSpectrum>) {
            return Dispatch(
                [&](const auto& b) { return b.Sample_f(wo, uc, u, mode, sampleFlags); });
        } else {
            return Dispatch([&](const auto& b) -> std::optional<BSDFSampleOf<Value>> {
                std::optional<BSDFSample> bs = b.Sample_f(wo, uc, u, mode, sampleFlags);
                if (!bs) return {};
                if constexpr (PolarizingBxDF<std::decay_t<decltype(b)>>)
                    return BSDFSampleOf<Value>(*bs, b.MuellerSample(wo, *bs, mode));
                else
                    return BSDFSampleOf<Value>(*bs, MuellerMatrix::Depolarizer(bs->f));
            });
        }
    }
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const {
        return Dispatch([&](const auto& b) { return b.PDF(wo, wi, mode, sampleFlags); });
    }
    BxDFFlags Flags() const {
        return Dispatch([](const auto& b) { return b.Flags(); });
    }
    void Regularize() {
        Dispatch([](auto& b) { b.Regularize(); });
    }
    // Whether f is a stochastic estimate and PDF an approximation (pbrt-v4's layered BxDFs,
    // whose samples carry the right f / pdf only): f / PDF does not weigh a sample exactly.
    bool EstimatesStochastically() const {
        return Dispatch([](const auto& b) {
            using T = std::decay_t<decltype(b)>;
            return std::is_same_v<T, CoatedDiffuseBxDF> || std::is_same_v<T, CoatedConductorBxDF>;
        });
    }
    // The refractive index of the -z side over the +z side, for BxDFs whose transmission in
    // Radiance mode carries the 1 / eta'^2 of radiance crossing between media (dielectrics);
    // 1 for the others (thin sheets, diffuse transmission, hair: the same medium either side).
    Float RefractiveRatio() const {
        return Dispatch([](const auto& b) -> Float {
            if constexpr (std::is_same_v<std::decay_t<decltype(b)>, DielectricBxDF>)
                return b.Eta();
            else
                return 1;
        });
    }

    // Monte Carlo estimate of the directional albedo (reflection plus transmission) from wo,
    // using one Sample_f call per (uc[i], u2[i]) pair (pbrt-v4's BxDF::rho).
    SampledSpectrum rho(Vector3f wo, std::span<const Float> uc, std::span<const Point2f> u2) const;
};

}  // namespace kiln
