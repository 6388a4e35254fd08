// Volumetric path tracing (pbrt-v4's VolPathIntegrator): the path integrator with
// participating media.
//
// Distances in a medium are sampled by delta tracking against majorants (Medium::SampleT_maj),
// each tentative collision absorbing, scattering or passing on (null collision) with
// probabilities sigma_a, sigma_s and sigma_n = sigma_maj - sigma_t over sigma_maj of the hero
// wavelength. The other wavelengths follow with weights, and rescaled path probabilities r_u
// (unidirectional) and r_l (light sampling) combine the wavelengths and the two strategies in
// one spectral MIS estimate (Miller, Georgiev & Jarosz 2019). Shadow rays pass through
// interface surfaces and estimate transmittance by ratio tracking. Media emit at every
// tentative collision (sigma_a Le, or thermal emission: medium_emission.h). Where the scene has
// a MediumEmissionSampler (emissive media, Integrator "string mediumemission" "sampled", the
// default), every vertex that samples a light also samples a point of a hot medium by emitted
// power (SampleMediumLd), and emission met at a tentative collision is weighted against that
// strategy by the same spectral MIS (kiln; pbrt-v4 finds medium emission by tracking alone,
// as "tracked" does). Surfaces are
// handled as in PathIntegrator: emission computed from the BSDF at the hit, and thin sheets
// crossed by shadow rays (a path straight through one keeps its MIS state and depth, as at an
// interface). A path transmitted through a "subsurface" boundary continues from an exit point
// that pbrt-v4's BSSRDF samples (SampleSubsurfaceExit, materials/subsurface_material.h).
//
// Scenes without media or subsurface materials run PathIntegrator (renderer.cpp); kiln
// --generic volpath runs this one anyway, for comparisons.
#pragma once

#include <optional>

#include "base/rng.h"
#include "core/camera/sampler.h"
#include "materials/bxdfs/hg_phase_function.h"
#include "materials/subsurface_material.h"
#include "render/medium_emission_sampler.h"
#include "render/radiance.h"
#include "render/scene.h"
#include "render/thin_sheets.h"

namespace kiln {

template <typename RadianceType>
class VolPathIntegrator {
  public:
    using Radiance = RadianceType;
    using Spectrum = typename Radiance::Spectrum;
    using Throughput = typename Radiance::Throughput;

    VolPathIntegrator(const Scene& scene, PathIntegratorSettings settings)
        : scene(scene), settings(settings), mediumEmission(scene.mediumEmission.get()) {}

    // As PathIntegrator::Li; the camera ray starts in the camera's medium.
    Spectrum Li(Ray ray, SampledWavelengths& lambda, Sampler& sampler,
                VisibleSurface* visibleSurface) const {
        Spectrum L{};
        Throughput beta = Radiance::One();
        SampledSpectrum r_u(1.f), r_l(1.f);
        bool specularBounce = false, anyNonSpecularBounces = false;
        int depth = 0;
        Float etaScale = 1;
        int sheetCrossings = 0;
        LightSampleContext prevContext;
        int prevScatterMedium = -1;  // the medium prevContext scattered in (-1: a surface)
        // On the first chord inside a hot medium after refracting into it through one of its
        // glass windows: the rescaled probability r_n of window sampling making the path
        bool windowChord = false;
        SampledSpectrum r_n(0.f);
        int medium = scene.cameraMedium;
        const int maxDepth = settings.maxDepth;

        while (true) {
            std::optional<ShapeIntersection> si = scene.aggregate->Intersect(ray, Infinity);
            if (medium >= 0) {
                // Sample the medium up to the surface hit (or forever)
                bool scattered = false, terminated = false;
                Float tMax = si ? si->tHit : Infinity;
                RNG rng(Hash(sampler.Get1D()), Hash(sampler.Get1D()));
                SampledSpectrum T_maj = scene.media[size_t(medium)].SampleT_maj(
                    ray, tMax, sampler.Get1D(), rng, lambda,
                    [&](Point3f p, const MediumProperties& mp, const SampledSpectrum& sigma_maj,
                        const SampledSpectrum& T_maj) {
                        if (!beta) {
                            terminated = true;
                            return false;
                        }
                        // Emission at the tentative collision, weighted against sampling
                        // the medium's emission from the previous vertex
                        if (depth < maxDepth && mp.emission) {
                            Float pdf = sigma_maj[0] * T_maj[0];
                            SampledSpectrum r_e = r_u * sigma_maj * T_maj / pdf;
                            Float p_l = depth == 0 || specularBounce
                                            ? 0
                                            : MediumEmissionPDF(medium, p, prevContext.p,
                                                                prevScatterMedium);
                            if ((p_l > 0 || windowChord) &&
                                settings.strategy == LightStrategy::LightOnly)
                                r_e = SampledSpectrum(0.f);
                            if (r_e) {
                                SampledSpectrum r = r_e + r_l * T_maj * (p_l / pdf);
                                if (windowChord) r += r_n * sigma_maj * T_maj / pdf;
                                L += Radiance::Apply(
                                    beta * (T_maj / pdf),
                                    Radiance::Unpolarized(mp.emission / WavelengthMean(r, lambda)));
                            }
                        }
                        // Absorption, real scattering or a null collision
                        Float pAbsorb = mp.sigma_a[0] / sigma_maj[0];
                        Float pScatter = mp.sigma_s[0] / sigma_maj[0];
                        Float um = rng.UniformFloat();
                        if (um < pAbsorb) {
                            terminated = true;
                            return false;
                        }
                        if (um < pAbsorb + pScatter) {
                            if (depth++ >= maxDepth) {
                                terminated = true;
                                return false;
                            }
                            Float pdf = T_maj[0] * mp.sigma_s[0];
                            beta = beta * (T_maj * mp.sigma_s / pdf);
                            r_u *= T_maj * mp.sigma_s / pdf;
                            if (!beta || !r_u) return false;
                            // Direct light at the scattering point, then a new direction
                            Vector3f wo = -ray.d;
                            HGPhaseFunction phase(mp.g);
                            windowChord = false;
                            if (settings.strategy != LightStrategy::BSDFOnly) {
                                Interaction intr(p, Normal3f(), Point2f(), wo, ray.time);
                                L += SampleLd(intr, nullptr, &phase, medium, lambda, sampler, beta,
                                              r_u);
                                L += SampleEmittersLd(intr, nullptr, &phase, medium, depth, lambda,
                                                      sampler, beta, r_u);
                            }
                            std::optional<PhaseFunctionSample> ps =
                                phase.Sample_p(wo, sampler.Get2D());
                            if (!ps || ps->pdf == 0) {
                                terminated = true;
                                return false;
                            }
                            beta = beta * Radiance::Depolarizing(SampledSpectrum(ps->p / ps->pdf));
                            r_l = r_u / ps->pdf;
                            prevContext = LightSampleContext(Interaction(p, Normal3f(), Point2f()));
                            prevScatterMedium = medium;
                            scattered = true;
                            ray = Ray(p, ps->wi, ray.time);
                            specularBounce = false;
                            anyNonSpecularBounces = true;
                            return false;
                        }
                        // Null collision
                        SampledSpectrum sigma_n = ClampZero(sigma_maj - mp.sigma_a - mp.sigma_s);
                        Float pdf = T_maj[0] * sigma_n[0];
                        if (pdf == 0) {
                            beta = Throughput{};
                            return false;
                        }
                        beta = beta * (T_maj * sigma_n / pdf);
                        r_u *= T_maj * sigma_n / pdf;
                        r_l *= T_maj * sigma_maj / pdf;
                        if (windowChord) r_n *= T_maj * sigma_maj / pdf;
                        return bool(beta) && bool(r_u);
                    });
                if (terminated || !beta || !r_u) return L;
                if (scattered) continue;
                if (T_maj[0] == 0) return L;
                beta = beta * (T_maj / T_maj[0]);
                r_u *= T_maj / T_maj[0];
                r_l *= T_maj / T_maj[0];
            }
            windowChord = false;  // a chord ends at the first surface

            // Escaped rays: emission from infinite lights
            if (!si) {
                for (int index : scene.infiniteLights) {
                    const Light& light = scene.lights[size_t(index)];
                    SampledSpectrum Le = light.Le(ray, lambda);
                    if (!Le) continue;
                    Float w = EmissionWeight(depth == 0 || specularBounce, index, ray.d,
                                             prevContext, r_u, r_l, lambda);
                    L += Radiance::Apply(beta, Radiance::Unpolarized(Le * w));
                }
                break;
            }
            SurfaceInteraction& isect = si->intr;

            // The BSDF at the hit; emission computed from it
            BSDF bsdf = scene.GetBSDF(isect, lambda);
            if (Spectrum Le = scene.SurfaceLe<Spectrum>(isect, bsdf, -ray.d, lambda)) {
                bool whole = depth == 0 || specularBounce || isect.lightIndex < 0;
                Float w =
                    EmissionWeight(whole, isect.lightIndex, ray.d, prevContext, r_u, r_l, lambda);
                L += Radiance::Apply(beta, Le * w);
            }
            // Medium boundaries without a material are crossed
            if (!bsdf) {
                medium = isect.MediumAfter(ray.d, medium);
                ray = isect.SpawnRay(ray.d);
                continue;
            }
            if (depth == 0 && sheetCrossings == 0 && visibleSurface)
                *visibleSurface = scene.MakeVisibleSurface(isect, bsdf, lambda);

            // Straight through a thin sheet, which shadow rays cross too (thin_sheets.h)
            std::optional<BSDFSampleOf<Throughput>> sheetSample;
            if (IsStraightThrough(bsdf.Flags())) {
                sheetSample = SampleSheet<Throughput>(bsdf, isect.wo, sampler);
                if (!sheetSample) break;
                if (sheetSample->IsStraightThrough()) {
                    if (++sheetCrossings > kMaxSheetCrossings) break;
                    beta = beta * CrossingWeight(*sheetSample, isect.shading.n);
                    medium = isect.MediumAfter(sheetSample->wi, medium);
                    ray = isect.SpawnRay(sheetSample->wi);
                    continue;
                }
            }

            if (depth++ >= maxDepth) return L;
            if (settings.regularize && anyNonSpecularBounces) bsdf.Regularize();

            // Direct lighting by light sampling
            if (IsNonSpecular(bsdf.Flags()) && settings.strategy != LightStrategy::BSDFOnly) {
                L += SampleLd(isect, &bsdf, nullptr, medium, lambda, sampler, beta, r_u);
                L += SampleEmittersLd(isect, &bsdf, nullptr, medium, depth, lambda, sampler, beta,
                                      r_u);
            }
            LightSampleContext sampledFrom = prevContext;  // the vertex before this one
            prevContext = LightSampleContext(isect);
            prevScatterMedium = -1;

            // Continue by sampling the BSDF (a sheet's reflection is sampled already)
            Vector3f wo = isect.wo;
            std::optional<BSDFSampleOf<Throughput>> bs = sheetSample;
            if (!bs) {
                Float u = sampler.Get1D();
                bs = bsdf.Sample_f<Throughput>(wo, u, sampler.Get2D());
            }
            if (!bs || bs->pdf == 0 || !bs->f) break;
            // Refracting into a hot medium through its glass window after a vertex that
            // sampled lights: the chord inside is weighted against window sampling
            if (isect.windowIndex >= 0 && WindowsActive() && depth > 1 && !specularBounce &&
                bs->IsSpecular() && bs->IsTransmission() && !IsNonSpecular(bsdf.Flags())) {
                const GlassWindows::Window& w = (*scene.glassWindows)[isect.windowIndex];
                if (medium != w.hot && isect.MediumAfter(bs->wi, medium) == w.hot) {
                    ShapeSampleContext ctx(sampledFrom.p, sampledFrom.n, sampledFrom.ns, ray.time);
                    Float q = scene.glassWindows->PMF(isect.windowIndex, sampledFrom.p) *
                              w.shape.PDF(ctx, Normalize(ray.d));
                    r_n = r_l * (q / bs->pdf);
                    windowChord = q > 0;
                }
            }
            beta = beta * (bs->f * (AbsDot(bs->wi, isect.shading.n) / bs->pdf));
            r_l = r_u / (bs->pdfIsProportional ? bsdf.PDF(wo, bs->wi) : bs->pdf);
            specularBounce = bs->IsSpecular();
            anyNonSpecularBounces |= !bs->IsSpecular();
            if (bs->IsTransmission()) etaScale *= Sqr(bs->eta);
            medium = isect.MediumAfter(bs->wi, medium);
            ray = isect.SpawnRay(bs->wi);

            // Below a "subsurface" boundary: the BSSRDF moves the path to an exit point on the
            // same material, whose NormalizedFresnelBxDF sends it on (pbrt-v4; no bounce is
            // counted)
            if (bs->IsTransmission() && scene.features.subsurface > 0)
                if (const auto* material = isect.material->GetIf<SubsurfaceMaterial>()) {
                    std::optional<SubsurfaceExit> exit =
                        SampleSubsurfaceExit(*material, isect, ray.time, lambda, sampler);
                    if (!exit) break;
                    beta = beta * Radiance::Depolarizing(exit->weight);
                    r_u *= exit->r_uFactor;
                    SurfaceInteraction& pi = exit->intr;
                    BSDF Sw(pi.shading.n, pi.shading.dpdu,
                            BxDF(NormalizedFresnelBxDF(material->Parameters().eta)), pi.n);
                    prevContext = LightSampleContext(pi);
                    prevScatterMedium = -1;
                    anyNonSpecularBounces = true;
                    if (settings.strategy != LightStrategy::BSDFOnly) {
                        L += SampleLd(pi, &Sw, nullptr, medium, lambda, sampler, beta, r_u);
                        L += SampleEmittersLd(pi, &Sw, nullptr, medium, depth, lambda, sampler,
                                              beta, r_u);
                    }
                    Float u = sampler.Get1D();
                    std::optional<BSDFSampleOf<Throughput>> es =
                        Sw.Sample_f<Throughput>(pi.wo, u, sampler.Get2D());
                    if (!es || es->pdf == 0 || !es->f) break;
                    beta = beta * (es->f * (AbsDot(es->wi, pi.shading.n) / es->pdf));
                    r_l = r_u / es->pdf;
                    specularBounce = false;
                    medium = pi.MediumAfter(es->wi, medium);
                    ray = pi.SpawnRay(es->wi);
                }

            // Russian roulette
            if (!beta) break;
            Float rrBeta = Radiance::RouletteWeight(beta) * etaScale / WavelengthMean(r_u, lambda);
            Float uRR = sampler.Get1D();
            if (rrBeta < 1 && depth > 1) {
                Float q = std::max<Float>(0, 1 - rrBeta);
                if (uRR < q) break;
                beta = beta / (1 - q);
            }
        }
        return L;
    }

  private:
    // Where a path below a subsurface boundary leaves the material, with the estimator's
    // factors: weight = Sp / (p_choice pdf_hero) and r_u's factor pdf / pdf_hero (spectral MIS
    // over the wavelengths' exit densities, pbrt-v4)
    struct SubsurfaceExit {
        SurfaceInteraction intr;  // wo: the shading normal (the exit BxDF's outside)
        SampledSpectrum weight, r_uFactor;
    };

    // pbrt-v4's BSSRDF sampling: a probe segment (TabulatedBSSRDF::SampleSp), intersected with
    // the scene; one of its hits on the same material chosen uniformly (weighted reservoir
    // sampling with unit weights), then Sp and the density of that exit point.
    std::optional<SubsurfaceExit> SampleSubsurfaceExit(const SubsurfaceMaterial& material,
                                                       const SurfaceInteraction& isect, Float time,
                                                       const SampledWavelengths& lambda,
                                                       Sampler& sampler) const {
        TabulatedBSSRDF bssrdf = material.GetBSSRDF(MaterialEvalContext(isect), lambda);
        Float uc = sampler.Get1D();
        Point2f up = sampler.Get2D();
        std::optional<BSSRDFProbeSegment> probe = bssrdf.SampleSp(uc, up);
        if (!probe) return std::nullopt;
        RNG rng(Hash(sampler.Get1D()));
        std::optional<SurfaceInteraction> chosen;
        int hits = 0;
        Interaction base(probe->p0, Normal3f(), Point2f(), Vector3f(), time);
        // The probe's hits, each a candidate (a path along thousands of them stops there)
        for (int crossings = 0; crossings < kMaxInterfaceCrossings; ++crossings) {
            Ray r = base.SpawnRayTo(probe->p1);
            if (r.d == Vector3f(0, 0, 0)) break;
            std::optional<ShapeIntersection> si = scene.aggregate->Intersect(r, 1);
            if (!si) break;
            base = si->intr;
            if (si->intr.material != isect.material) continue;
            if (rng.UniformFloat() * Float(++hits) < 1) chosen = si->intr;
        }
        if (!chosen) return std::nullopt;
        SampledSpectrum Sp = bssrdf.Sp(chosen->p), pdf = bssrdf.PDF_Sp(chosen->p, chosen->n);
        if (!Sp || !pdf || pdf[0] == 0) return std::nullopt;
        SubsurfaceExit exit{*chosen, Sp * (Float(hits) / pdf[0]), pdf / pdf[0]};
        exit.intr.wo = Vector3f(exit.intr.shading.n);
        return exit;
    }

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

    // The density per unit solid angle and distance (dV / t^2) with which SampleMediumLd at
    // `from` would draw point p of `medium` (0 without medium sampling, and from a point
    // scattering in that medium itself: fromMedium).
    Float MediumEmissionPDF(int medium, Point3f p, Point3f from, int fromMedium) const {
        if (!mediumEmission || settings.strategy == LightStrategy::BSDFOnly || medium == fromMedium)
            return 0;
        Float pdf = mediumEmission->PDF(from, mediumEmission->EmitterOf(medium), p);
        return pdf > 0 ? pdf * DistanceSquared(from, p) : 0;
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
        Vector3f wo = intr.wo, wi = Normalize(toPoint);
        const auto* surface = bsdf ? static_cast<const SurfaceInteraction*>(&intr) : nullptr;
        Throughput f_hat;
        Float scatterPDF;
        if (bsdf) {
            Float cosTheta = AbsDot(wi, surface->shading.n);
            if (cosTheta == 0) return {};
            f_hat = bsdf->f<Throughput>(wo, wi) * cosTheta;
            scatterPDF = bsdf->PDF(wo, wi);
        } else {
            f_hat = Radiance::Depolarizing(SampledSpectrum(phase->p(wo, wi)));
            scatterPDF = phase->PDF(wo, wi);
        }
        if (!f_hat) return {};
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
    // inside by ratio tracking. Each emission point is weighted by spectral MIS against the
    // path that refracts at s itself, whose density is the scattering pdf times P_T (in the
    // same measure: directions at intr) and whose null collisions have sigma_n's density
    // rather than sigma_maj's.
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
            ShapeSampleContext ctx =
                surface ? ShapeSampleContext(*surface)
                        : ShapeSampleContext(intr.p, Normal3f(), Normal3f(), intr.time);
            std::optional<ShapeSample> ss = w.shape.Sample(ctx, uPoint);
            if (!ss || !(ss->pdf > 0)) return {};
            Vector3f toWindow = ss->intr.p - intr.p;
            if (LengthSquared(toWindow) == 0) return {};
            Vector3f wo = intr.wo, wi = Normalize(toWindow);
            Float q = pmf * ss->pdf;
            // The scattering towards the window
            Throughput f_hat;
            Float scatterPDF;
            if (bsdf) {
                Float cosTheta = AbsDot(wi, surface->shading.n);
                if (cosTheta == 0) return {};
                f_hat = bsdf->f<Throughput>(wo, wi) * cosTheta;
                scatterPDF = bsdf->PDF(wo, wi);
            } else {
                f_hat = Radiance::Depolarizing(SampledSpectrum(phase->p(wo, wi)));
                scatterPDF = phase->PDF(wo, wi);
            }
            if (!f_hat) return {};
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
            // The chord inside, by ratio tracking with emission at every tentative collision
            Ray chord = si.SpawnRay(bt->wi);
            std::optional<ShapeIntersection> end = scene.aggregate->Intersect(chord, Infinity);
            SampledSpectrum Rl = tr->r_l * r_p * q, Ru = tr->r_u * r_p * (scatterPDF * bt->pdf);
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
