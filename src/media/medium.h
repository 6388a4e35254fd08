// Medium: the closed set of participating media behind one small value type (pbrt-v4's
// Medium, with std::variant of pointers in place of its TaggedPointer), and SampleT_maj, the
// distance sampling every volumetric estimator is built on. Media live in the scene's
// ObjectArena and are identified by their index in Scene::media (MediumInterface).
//
// Units: coefficients per unit length of render space (pbrt-v4: a medium's transform does not
// scale them), emission in W m^-2 sr^-1 nm^-1 per unit length.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "base/closed_set.h"
#include "base/rng.h"
#include "base/sampling.h"
#include "base/transform.h"
#include "core/parser/diagnostics.h"
#include "media/cloud_medium.h"
#include "media/grid_medium.h"
#include "media/homogeneous_medium.h"
#include "media/rgb_grid_medium.h"

namespace kiln {

class Medium : public ClosedSet<HomogeneousMedium*, GridMedium*, RGBGridMedium*, CloudMedium*> {
  public:
    using ClosedSet::ClosedSet;
    // type: "homogeneous", "uniformgrid", "rgbgrid", "cloud", "nanovdb" (an OpenVDB .vdb file;
    // .nvdb files are refused with a message) or kiln's "vdb". modelOverride: the command
    // line's --emission for thermal media. SceneError for invalid parameters or a singular
    // transform.
    static Medium Create(const std::string& type, const TextureParameterDictionary& params,
                         const Transform& renderFromMedium,
                         std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                         ObjectArena& arena, Diagnostics& diag);

    bool IsEmissive() const {
        return Dispatch([](auto m) { return m->IsEmissive(); });
    }
    // Thermal emission inside a body of refractive index eta (medium_emission.h).
    void SetRefractiveIndex(const Spectrum& eta) {
        Dispatch([&](auto m) { m->Emission().SetRefractiveIndex(eta); });
    }
    // Coefficients and emission the same everywhere (UniformSegmentEmission is exact).
    bool IsUniform() const {
        return Dispatch([](auto m) { return m->IsUniform(); });
    }
    // MediumEmission::RepresentativeTemperature.
    std::optional<Float> EmissionTemperature() const {
        return Dispatch([](auto m) { return m->Emission().RepresentativeTemperature(); });
    }
    bool IsThermal() const {
        return Dispatch([](auto m) { return m->Emission().IsThermal(); });
    }
    MediumProperties SamplePoint(Point3f p, const SampledWavelengths& lambda) const {
        return Dispatch([&](auto m) { return m->SamplePoint(p, lambda); });
    }
    // The emission reaching a ray's origin from its first `distance` (render-space units; may
    // be infinite) inside the medium: the integral of T(t) sigma_a Le over [0, distance], per
    // wavelength, W m^-2 sr^-1 nm^-1. Computed exactly where the medium and its emission are
    // the same everywhere, (1 - exp(-sigma_t d)) sigma_a Le / sigma_t (homogeneous media
    // with constant emission); nullopt elsewhere (grids, textured temperatures).
    std::optional<SampledSpectrum> UniformSegmentEmission(Float distance,
                                                          const SampledWavelengths& lambda) const {
        return Dispatch([&](auto m) -> std::optional<SampledSpectrum> {
            if (!m->IsUniform()) return std::nullopt;
            MediumProperties mp = m->SamplePoint(Point3f(0, 0, 0), lambda);
            SampledSpectrum E;
            for (int i = 0; i < NSpectrumSamples; ++i) {
                // Every emission model emits on extinction: none without it
                Float sigma_t = mp.sigma_a[i] + mp.sigma_s[i];
                if (mp.emission[i] == 0 || !(sigma_t > 0)) continue;
                Float x = sigma_t * distance;
                // 1 - exp(-x) over sigma_t, to distance where x is small
                E[i] = mp.emission[i] *
                       (x > Float(1e-4) ? -std::expm1(-x) / sigma_t : distance * (1 - x / 2));
            }
            return E;
        });
    }
    // The majorant segments of ray (render space, unit direction) over [0, tMax].
    MajorantIterator SampleRay(const Ray& ray, Float tMax, const SampledWavelengths& lambda) const {
        return Dispatch([&](auto m) { return m->SampleRay(ray, tMax, lambda); });
    }
    // The majorant delta tracking uses at render-space point p (0 outside the medium's box):
    // that of the majorant segment holding p.
    SampledSpectrum MajorantAt(Point3f p, const SampledWavelengths& lambda) const {
        std::optional<RayMajorantSegment> seg =
            SampleRay(Ray(p, Vector3f(1, 0, 0)), kMajorantProbe, lambda).Next();
        return seg ? seg->sigma_maj : SampledSpectrum(0.f);
    }
    // A render-space box outside which the medium has no extent (nullopt: unbounded).
    std::optional<Bounds3f> RenderBounds() const {
        return Dispatch([](auto m) -> std::optional<Bounds3f> { return m->RenderBounds(); });
    }

    // Delta-tracking distance sampling along ray up to tMax (pbrt-v4's SampleT_maj): draws
    // tentative collisions with density sigma_maj[0] exp(-sigma_maj[0] t) per majorant
    // segment, and calls callback(p, MediumProperties, sigma_maj, T_maj) at each, T_maj being
    // the majorant transmittance since the previous one; the callback returns whether to go
    // on. Returns the majorant transmittance from the last collision to tMax (1 if stopped).
    // u: the first uniform sample; rng supplies the rest. A ray that makes kMaxCollisions
    // tentative collisions (majorants far above the extinction, as hostile input can make
    // them) ends there with transmittance 0 rather than hang.
    template <typename F>
    SampledSpectrum SampleT_maj(Ray ray, Float tMax, Float u, RNG& rng,
                                const SampledWavelengths& lambda, F callback) const {
        // Unit direction, tMax in its units
        Float len = Length(ray.d);
        tMax *= len;
        ray.d = ray.d / len;
        return Dispatch([&](auto m) {
            MajorantIterator iter = m->SampleRay(ray, tMax, lambda);
            SampledSpectrum T_maj(1.f);
            int collisions = 0;
            while (std::optional<RayMajorantSegment> seg = iter.Next()) {
                if (seg->sigma_maj[0] == 0) {
                    // No collisions here: only the transmittance of the other wavelengths
                    T_maj *= FastExpTransmittance(seg->tMax - seg->tMin, seg->sigma_maj);
                    continue;
                }
                Float tMin = seg->tMin;
                while (true) {
                    Float t = tMin + SampleExponential(u, seg->sigma_maj[0]);
                    u = rng.UniformFloat();
                    if (t >= seg->tMax) {
                        T_maj *= FastExpTransmittance(seg->tMax - tMin, seg->sigma_maj);
                        break;
                    }
                    if (++collisions > kMaxCollisions) return SampledSpectrum(0.f);
                    T_maj *= FastExpTransmittance(t - tMin, seg->sigma_maj);
                    Point3f p = ray(t);
                    if (!callback(p, m->SamplePoint(p, lambda), seg->sigma_maj, T_maj))
                        return SampledSpectrum(1.f);
                    T_maj = SampledSpectrum(1.f);
                    tMin = t;
                }
            }
            return T_maj;
        });
    }

    static constexpr int kMaxCollisions = 1 << 20;
    // The length of the ray MajorantAt looks along: short against any majorant voxel.
    static constexpr Float kMajorantProbe = 1e-6f;

    // exp(-dt sigma) per wavelength; an infinite segment with sigma 0 transmits everything.
    // One exponential where every wavelength has the same coefficient (grey media and their
    // majorants), the same values.
    static SampledSpectrum FastExpTransmittance(Float dt, const SampledSpectrum& sigma) {
        bool grey = true;
        for (int i = 1; i < NSpectrumSamples; ++i) grey &= sigma[i] == sigma[0];
        if (grey) return SampledSpectrum(sigma[0] == 0 ? 1 : std::exp(-dt * sigma[0]));
        SampledSpectrum T;
        for (int i = 0; i < NSpectrumSamples; ++i)
            T[i] = sigma[i] == 0 ? 1 : std::exp(-dt * sigma[i]);
        return T;
    }
};

}  // namespace kiln
