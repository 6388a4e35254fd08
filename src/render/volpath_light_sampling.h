// Light sampling for volumetric path tracing (VolPathIntegrator's next-event estimation):
// lights by pbrt-v4's SampleLd with ratio-tracked transmittance through media and thin sheets,
// and kiln's emitters besides lights: hot media by emitted power (SampleMediumLd,
// medium_emission_sampler.h) and media glowing inside glass through their glass
// (SampleWindowLd, glass_windows.h); with the spectral MIS weights the path uses for emission
// it finds itself (EmissionWeight, MediumEmissionPDF).
#pragma once

#include <optional>

#include "base/rng.h"
#include "core/camera/sampler.h"
#include "materials/bxdfs/hg_phase_function.h"
#include "render/glass_windows.h"
#include "render/medium_emission_sampler.h"
#include "render/radiance.h"
#include "render/scene.h"
#include "render/thin_sheets.h"

namespace kiln {

template <typename RadianceType>
class VolPathLightSampling {
  public:
    using Radiance = RadianceType;
    using Spectrum = typename Radiance::Spectrum;
    using Throughput = typename Radiance::Throughput;

  protected:
    VolPathLightSampling(const Scene& scene, PathIntegratorSettings settings)
        : scene(scene), settings(settings), mediumEmission(scene.mediumEmission.get()) {}

    // The denominator of spectral MIS: the mean of the rescaled path probabilities over the
    // wavelengths that could have sampled the path; only the hero's once the others are
    // terminated (after a dispersive surface, which no other wavelength crosses the same way;
    // pbrt-v4 keeps averaging all four, biased where media are chromatic).
    static Float WavelengthMean(const SampledSpectrum& r, const SampledWavelengths& lambda) {
        return lambda.SecondaryTerminated() ? r[0] : r.Average();
    }

    // The factor of emission found by path sampling: 1 / r_u when light sampling could not
    // have found it (whole), else the spectral MIS weight against light sampling (pbrt-v4's
    // 1 / (r_u + r_l p_l)); per LightStrategy for comparisons.
    Float EmissionWeight(bool whole, int lightIndex, Vector3f d, const LightSampleContext& ctx,
                         const SampledSpectrum& r_u, const SampledSpectrum& r_l,
                         const SampledWavelengths& lambda) const {
        if (whole || settings.strategy == LightStrategy::BSDFOnly)
            return 1 / WavelengthMean(r_u, lambda);
        const Light& light = scene.lights[size_t(lightIndex)];
        Float p_l = scene.lightSampler->PMF(ctx, lightIndex) * light.PDF_Li(ctx, d, true);
        if (settings.strategy == LightStrategy::LightOnly)
            return p_l > 0 ? 0 : 1 / WavelengthMean(r_u, lambda);
        return 1 / WavelengthMean(r_u + r_l * p_l, lambda);
    }

    // One light sample at a surface (bsdf) or a point in a medium (phase), weighted by spectral
    // MIS; transmittance through media by ratio tracking, across interface surfaces.
    Spectrum SampleLd(const Interaction& intr, const BSDF* bsdf, const HGPhaseFunction* phase,
                      int medium, const SampledWavelengths& lambda, Sampler& sampler,
                      const Throughput& beta, const SampledSpectrum& r_p) const {
        const auto* surface = bsdf ? static_cast<const SurfaceInteraction*>(&intr) : nullptr;
        LightSampleContext ctx = surface ? LightSampleContext(*surface) : LightSampleContext(intr);
        if (bsdf) {
            BxDFFlags flags = bsdf->Flags();
            if (IsReflective(flags) && !IsTransmissive(flags))
                ctx.p = intr.OffsetRayOrigin(intr.wo);
            else if (IsTransmissive(flags) && !IsReflective(flags))
                ctx.p = intr.OffsetRayOrigin(-intr.wo);
        }
        Float uLight = sampler.Get1D();
        Point2f uPoint = sampler.Get2D();
        std::optional<SampledLight> sampled = scene.lightSampler->Sample(ctx, uLight);
        if (!sampled) return {};
        const Light& light = scene.lights[size_t(sampled->index)];
        std::optional<LightLiSample> ls = light.SampleLi(ctx, uPoint, lambda, true);
        if (!ls || ls->pdf == 0 || (!ls->deferredL && !ls->L)) return {};
        Float p_l = sampled->p * ls->pdf;

        // The BSDF or phase function towards the light
        Vector3f wo = intr.wo, wi = ls->wi;
        Throughput f_hat;
        Float scatterPDF;
        if (bsdf) {
            // With pbrt-v4's length (LightLiSample::wiLength; path_integrator.h)
            wi = ls->wi * ls->wiLength;
            Float cosTheta = AbsDot(wi, surface->shading.n);
            if (cosTheta == 0) return {};
            f_hat = bsdf->f<Throughput>(wo, wi) * cosTheta;
            scatterPDF = bsdf->PDF(wo, wi);
        } else {
            Float p = phase->p(wo, wi);
            f_hat = Radiance::Depolarizing(SampledSpectrum(p));
            scatterPDF = phase->PDF(wo, wi);
        }
        if (!f_hat) return {};

        // Transmittance to the light, through media and thin sheets
        std::optional<Transmission> tr = Transmit(intr, surface, medium, ls->pLight, lambda);
        if (!tr) return {};
        SampledSpectrum T_ray = tr->T_ray, r_l = tr->r_l, r_u = tr->r_u;
        const Throughput& T_sheets = tr->T_sheets;

        Spectrum Li = light.DeferredL<Spectrum>(*ls, lambda, *scene.job->shader);
        if (!Li) return {};
        r_l *= r_p * p_l;
        r_u *= r_p * scatterPDF;
        Spectrum contribution = Radiance::Apply(beta * f_hat * T_sheets, Li) * T_ray;
        if (IsDeltaLight(light.Type()) || settings.strategy == LightStrategy::LightOnly)
            return contribution / WavelengthMean(r_l, lambda);
        return contribution / WavelengthMean(r_l + r_u, lambda);
    }

    // The light that reaches `to` from intr along a shadow ray, through media (ratio tracking,
    // with the rescaled probabilities r_l and r_u of its null collisions) and thin sheets
    // (T_sheets), across interface surfaces; `medium` is the medium the ray ends in. nullopt
    // if something opaque is in the way or the estimate is 0.
    struct Transmission {
        SampledSpectrum T_ray, r_l, r_u;
        Throughput T_sheets;
        int medium;
    };
    std::optional<Transmission> Transmit(const Interaction& intr, const SurfaceInteraction* surface,
                                         int medium, const Interaction& to,
                                         const SampledWavelengths& lambda) const {
        Ray lightRay = intr.SpawnRayTo(to);
        if (surface) medium = surface->MediumAfter(lightRay.d, medium);
        Transmission tr{SampledSpectrum(1.f), SampledSpectrum(1.f), SampledSpectrum(1.f),
                        Radiance::One(), medium};
        SampledSpectrum &T_ray = tr.T_ray, &r_l = tr.r_l, &r_u = tr.r_u;
        RNG rng(Hash(lightRay.o), Hash(lightRay.d));
        for (int crossings = 0;; ++crossings) {
            std::optional<ShapeIntersection> si =
                scene.aggregate->Intersect(lightRay, 1 - ShadowEpsilon);
            if (si && si->intr.material && !si->intr.material->IsInterface()) {
                std::optional<Throughput> T =
                    SheetTransmittance<Throughput>(scene, si->intr, lambda);
                if (!T) return std::nullopt;
                tr.T_sheets = tr.T_sheets * *T;
            }
            if (tr.medium >= 0) {
                Float tMax = si ? si->tHit : 1 - ShadowEpsilon;
                SampledSpectrum T_maj = scene.media[size_t(tr.medium)].SampleT_maj(
                    lightRay, tMax, rng.UniformFloat(), rng, lambda,
                    [&](Point3f, const MediumProperties& mp, const SampledSpectrum& sigma_maj,
                        const SampledSpectrum& T_maj) {
                        // Ratio tracking, with Russian roulette on small transmittance
                        SampledSpectrum sigma_n = ClampZero(sigma_maj - mp.sigma_a - mp.sigma_s);
                        Float pdf = T_maj[0] * sigma_maj[0];
                        T_ray *= T_maj * sigma_n / pdf;
                        r_l *= T_maj * sigma_maj / pdf;
                        r_u *= T_maj * sigma_n / pdf;
                        SampledSpectrum Tr = T_ray / WavelengthMean(r_l + r_u, lambda);
                        if (Tr.MaxComponentValue() < 0.05f) {
                            if (rng.UniformFloat() < 0.75f)
                                T_ray = SampledSpectrum(0.f);
                            else
                                T_ray /= 0.25f;
                        }
                        return bool(T_ray);
                    });
                if (T_maj[0] == 0) return std::nullopt;
                T_ray *= T_maj / T_maj[0];
                r_l *= T_maj / T_maj[0];
                r_u *= T_maj / T_maj[0];
            }
            if (!T_ray) return std::nullopt;
            if (!si) break;
            // Past an interface surface; a path through thousands of them is treated as blocked
            if (crossings == kMaxInterfaceCrossings) return std::nullopt;
            tr.medium = si->intr.MediumAfter(lightRay.d, tr.medium);
            lightRay = si->intr.SpawnRayTo(to);
        }
        return tr;
    }

    // The scattering at intr towards wi, by the BSDF (f |cos|) at a surface or the phase
    // function in a medium, with the density of sampling wi by it; nullopt if it is zero.
    struct Scattering {
        Throughput f_hat;
        Float pdf;
    };
    std::optional<Scattering> ScatteringTowards(const Interaction& intr, const BSDF* bsdf,
                                                const HGPhaseFunction* phase, Vector3f wi) const {
        Scattering s;
        if (bsdf) {
            const auto& surface = static_cast<const SurfaceInteraction&>(intr);
            Float cosTheta = AbsDot(wi, surface.shading.n);
            if (cosTheta == 0) return std::nullopt;
            s.f_hat = bsdf->f<Throughput>(intr.wo, wi) * cosTheta;
            s.pdf = bsdf->PDF(intr.wo, wi);
        } else {
            s.f_hat = Radiance::Depolarizing(SampledSpectrum(phase->p(intr.wo, wi)));
            s.pdf = phase->PDF(intr.wo, wi);
        }
        if (!s.f_hat) return std::nullopt;
        return s;
    }

    // The density per unit solid angle and distance (dV / t^2) with which SampleMediumLd at
    // `from` would draw point p of `medium` (0 without medium sampling, and from a point
    // scattering in that medium itself: fromMedium).
    Float MediumEmissionPDF(int medium, Point3f p, Point3f from, int fromMedium) const {
        if (!mediumEmission || settings.strategy == LightStrategy::BSDFOnly || medium == fromMedium)
            return 0;
        Float pdf = mediumEmission->PDF(from, mediumEmission->EmitterOf(medium), p);
        return pdf > 0 ? pdf * DistanceSquared(from, p) : 0;
    }

    // Whether a vertex (scattering in fromMedium, or a surface: -1) samples medium's emission as
    // a light, so that emission met in it is weighted against that (MediumEmissionPDF > 0).
    bool MediumEmissionSampled(int medium, int fromMedium) const {
        return mediumEmission && settings.strategy != LightStrategy::BSDFOnly &&
               medium != fromMedium && mediumEmission->EmitterOf(medium) >= 0;
    }

    // Next-event estimation of medium emission: a point of a hot medium drawn by emitted
    // power (MediumEmissionSampler), its emission sigma_a Le through the shadow ray's
    // transmittance, weighted by spectral MIS against meeting it at a tentative collision of
    // the path (whose density there is the scattering pdf times sigma_maj at the point, in
    // the same measure). Nothing if the shadow ray ends in another medium, or from a point
    // scattering in the chosen medium itself (phase and `medium`): there the path finds the
    // emission around it by tracking, and a shadow ray into the same medium rarely pays for
    // itself (a 40^3 plume: 1.4 times the time for no gain).
    Spectrum SampleMediumLd(const Interaction& intr, const BSDF* bsdf, const HGPhaseFunction* phase,
                            int medium, const SampledWavelengths& lambda, Sampler& sampler,
                            const Throughput& beta, const SampledSpectrum& r_p) const {
        if (!mediumEmission) return {};
        Float u = sampler.Get1D();
        Point2f u2 = sampler.Get2D();
        Float u1 = sampler.Get1D();
        std::optional<MediumEmissionSampler::PointSample> ps =
            mediumEmission->Sample(intr.p, u, Point3f(u2.x, u2.y, u1));
        if (!ps) return {};
        int emitterMedium = mediumEmission->MediumOf(ps->emitter);
        if (phase && emitterMedium == medium) return {};
        Vector3f toPoint = ps->p - intr.p;
        Float dist2 = LengthSquared(toPoint);
        if (!(dist2 > 0)) return {};
        Vector3f wi = Normalize(toPoint);
        const auto* surface = bsdf ? static_cast<const SurfaceInteraction*>(&intr) : nullptr;
        std::optional<Scattering> scattering = ScatteringTowards(intr, bsdf, phase, wi);
        if (!scattering) return {};
        const Throughput& f_hat = scattering->f_hat;
        Float scatterPDF = scattering->pdf;
        Interaction target(ps->p, Normal3f(), Point2f(), Vector3f(), intr.time);
        std::optional<Transmission> tr = Transmit(intr, surface, medium, target, lambda);
        if (!tr || tr->medium != emitterMedium) return {};
        const Medium& m = scene.media[size_t(emitterMedium)];
        MediumProperties mp = m.SamplePoint(ps->p, lambda);
        if (!mp.emission) return {};
        SampledSpectrum r_l = tr->r_l * r_p * (ps->pdf * dist2);
        SampledSpectrum r_u = tr->r_u * r_p * scatterPDF * m.MajorantAt(ps->p, lambda);
        Spectrum contribution =
            Radiance::Apply(beta * f_hat * tr->T_sheets, Radiance::Unpolarized(mp.emission)) *
            tr->T_ray;
        if (settings.strategy == LightStrategy::LightOnly)
            return contribution / WavelengthMean(r_l, lambda);
        return contribution / WavelengthMean(r_l + r_u, lambda);
    }

    // Whether glass windows are sampled: the scene has them, light sampling is on, the
    // unpolarised variant (the window's transmission would need its Mueller matrix) and no
    // regularisation (which would roughen the path's window but not the sampled one).
    bool WindowsActive() const {
        return scene.glassWindows && !Radiance::Polarized && !settings.regularize &&
               settings.strategy != LightStrategy::BSDFOnly;
    }

    // The emitters light sampling looks for besides lights, at a vertex whose path has made
    // `depth` scattering events: hot media (if the path could still count medium emission
    // found by its next segment, depth < maxDepth) and hot media through their glass windows
    // (if the chord after the refraction could still count it, depth + 1 < maxDepth).
    Spectrum SampleEmittersLd(const Interaction& intr, const BSDF* bsdf,
                              const HGPhaseFunction* phase, int medium, int depth,
                              const SampledWavelengths& lambda, Sampler& sampler,
                              const Throughput& beta, const SampledSpectrum& r_p) const {
        Spectrum L{};
        if (depth < settings.maxDepth)
            L += SampleMediumLd(intr, bsdf, phase, medium, lambda, sampler, beta, r_p);
        if (depth + 1 < settings.maxDepth && WindowsActive())
            L += SampleWindowLd(intr, bsdf, phase, medium, lambda, sampler, beta, r_p);
        return L;
    }

    // Light sampling of a medium glowing inside glass (glass_windows.h): a point s on one of
    // its windows, the window's specular transmission there (f cos of its transmission
    // sample, P_T its probability in a path), and the emission along the refracted chord
    // inside: integrated exactly in a uniform medium and weighted as a whole by spectral MIS
    // against the path that refracts at s itself (which integrates it the same way), whose
    // density is the scattering pdf times P_T (in the same measure: directions at intr);
    // elsewhere by ratio tracking, each emission point weighted against that path, whose null
    // collisions have sigma_n's density rather than sigma_maj's.
    Spectrum SampleWindowLd(const Interaction& intr, const BSDF* bsdf, const HGPhaseFunction* phase,
                            int medium, const SampledWavelengths& lambda, Sampler& sampler,
                            const Throughput& beta, const SampledSpectrum& r_p) const {
        if constexpr (Radiance::Polarized) {
            return {};
        } else {
            Float uWindow = sampler.Get1D();
            Point2f uPoint = sampler.Get2D();
            Float pmf = 0;
            int k = scene.glassWindows->Choose(uWindow, intr.p, &pmf);
            if (k < 0) return {};
            const GlassWindows::Window& w = (*scene.glassWindows)[k];
            const auto* surface = bsdf ? static_cast<const SurfaceInteraction*>(&intr) : nullptr;
            // From inside the hot medium itself nothing is sampled: a window is seen from there
            // only from its hot side (the path finds that emission by tracking)
            if (!surface && medium == w.hot) return {};
            ShapeSampleContext ctx =
                surface ? ShapeSampleContext(*surface)
                        : ShapeSampleContext(intr.p, Normal3f(), Normal3f(), intr.time);
            std::optional<ShapeSample> ss = w.shape.Sample(ctx, uPoint);
            if (!ss || !(ss->pdf > 0)) return {};
            Vector3f toWindow = ss->intr.p - intr.p;
            if (LengthSquared(toWindow) == 0) return {};
            Vector3f wi = Normalize(toWindow);
            Float q = pmf * ss->pdf;
            std::optional<Scattering> scattering = ScatteringTowards(intr, bsdf, phase, wi);
            if (!scattering) return {};
            const Throughput& f_hat = scattering->f_hat;
            Float scatterPDF = scattering->pdf;
            // The window point as a ray arriving from intr finds it, and its transmission
            SurfaceInteraction si = w.shape.InteractionAt(ss->intr.p, intr.time, -wi);
            si.material = w.material;
            si.mediumInterface = w.media;
            si.windowIndex = k;
            SampledWavelengths windowLambda = lambda;  // non-dispersive: left as it is
            BSDF windowBSDF = scene.GetBSDF(si, windowLambda);
            if (!windowBSDF || IsNonSpecular(windowBSDF.Flags())) return {};
            std::optional<BSDFSampleOf<Throughput>> bt =
                windowBSDF.Sample_f<Throughput>(si.wo, OneMinusEpsilon, Point2f(0.5f, 0.5f));
            if (!bt || !bt->IsSpecular() || !bt->IsTransmission() || !(bt->pdf > 0) ||
                si.MediumAfter(bt->wi, -1) != w.hot)
                return {};
            Throughput F = bt->f * AbsDot(bt->wi, si.shading.n);
            // Unoccluded up to the window, arriving from its cold side
            std::optional<Transmission> tr = Transmit(intr, surface, medium, si, lambda);
            if (!tr || tr->medium == w.hot || si.MediumAfter(-wi, -2) != tr->medium) return {};
            // The chord inside: its emission integrated exactly in a uniform medium (as the
            // path that refracts at s integrates it), else by ratio tracking with emission at
            // every tentative collision
            Ray chord = si.SpawnRay(bt->wi);
            std::optional<ShapeIntersection> end = scene.aggregate->Intersect(chord, Infinity);
            SampledSpectrum Rl = tr->r_l * r_p * q, Ru = tr->r_u * r_p * (scatterPDF * bt->pdf);
            Float denomExact = settings.strategy == LightStrategy::LightOnly
                                   ? WavelengthMean(Rl, lambda)
                                   : WavelengthMean(Rl + Ru, lambda);
            if (!(denomExact > 0)) return {};
            if (!scene.exactEmissionMedia.empty() && scene.exactEmissionMedia[size_t(w.hot)])
                if (std::optional<SampledSpectrum> E =
                        scene.media[size_t(w.hot)].UniformSegmentEmission(
                            (end ? end->tHit : Infinity) * Length(chord.d), lambda))
                    return beta * f_hat * tr->T_sheets * tr->T_ray * F * (*E / denomExact);
            SampledSpectrum Tr(1.f), emitted(0.f);
            RNG rng(Hash(chord.o), Hash(chord.d));
            scene.media[size_t(w.hot)].SampleT_maj(
                chord, end ? end->tHit : Infinity, rng.UniformFloat(), rng, lambda,
                [&](Point3f, const MediumProperties& mp, const SampledSpectrum& sigma_maj,
                    const SampledSpectrum& T_maj) {
                    Float pdf = T_maj[0] * sigma_maj[0];
                    if (mp.emission) {
                        SampledSpectrum rl = Rl * T_maj * sigma_maj / pdf;
                        SampledSpectrum ru = Ru * T_maj * sigma_maj / pdf;
                        Float denom = settings.strategy == LightStrategy::LightOnly
                                          ? WavelengthMean(rl, lambda)
                                          : WavelengthMean(rl + ru, lambda);
                        emitted += Tr * T_maj * mp.emission / (pdf * denom);
                    }
                    SampledSpectrum sigma_n = ClampZero(sigma_maj - mp.sigma_a - mp.sigma_s);
                    Tr *= T_maj * sigma_n / pdf;
                    Rl *= T_maj * sigma_maj / pdf;
                    Ru *= T_maj * sigma_n / pdf;
                    // Russian roulette on small transmittance
                    if (Tr.MaxComponentValue() < 0.05f) {
                        if (rng.UniformFloat() < 0.75f)
                            Tr = SampledSpectrum(0.f);
                        else
                            Tr /= 0.25f;
                    }
                    return bool(Tr);
                });
            return beta * f_hat * tr->T_sheets * tr->T_ray * F * emitted;
        }
    }

    static constexpr int kMaxInterfaceCrossings = 1024;
    const Scene& scene;
    PathIntegratorSettings settings;
    // Points of hot media by emitted power (nullptr: medium emission is found by tracking)
    const MediumEmissionSampler* mediumEmission;
};

}  // namespace kiln
