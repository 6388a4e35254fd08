// Volumetric path tracing (pbrt-v4's VolPathIntegrator): the path integrator with
// participating media.
//
// Distances in a medium are sampled by delta tracking against majorants (Medium::SampleT_maj),
// each tentative collision absorbing, scattering or passing on (null collision) with
// probabilities sigma_a, sigma_s and sigma_n = sigma_maj - sigma_t over sigma_maj of the hero
// wavelength. The other wavelengths follow with weights, and rescaled path probabilities r_u
// (unidirectional) and r_l (light sampling) combine the wavelengths and the two strategies in
// one spectral MIS estimate (Miller, Georgiev & Jarosz 2019). While a path carries much
// (Integrator "bool weightabsorption"), absorption weighs it rather than ending it: passing a
// collision, by sigma_n / (sigma_n + sigma_a); in a uniform medium only scattering is sampled
// and the path carries exp(-sigma_a t). r_u and r_l stay those of the tracking above, as light
// sampling computes them; beta divides by what was sampled. Shadow rays pass through
// interface surfaces and estimate transmittance by ratio tracking. Media emit at every
// tentative collision (sigma_a Le, or thermal emission: medium_emission.h), except where a
// uniform medium's emission along the whole segment is integrated exactly (Integrator "bool
// exactmediumemission", on segments no light sampling could have found, and on chords behind
// glass windows, weighted against window sampling as a whole). Light sampling
// (volpath_light_sampling.h) also samples kiln's emitters besides lights, by default
// (Integrator "string mediumemission" "sampled"): a point of a hot medium by emitted power,
// and a hot medium inside glass through its glass ("bool glasswindows"); emission the path
// meets at a tentative collision is weighted against those strategies by the same spectral
// MIS (pbrt-v4 finds medium emission by tracking alone, as "tracked" does). Surfaces are
// handled as in PathIntegrator: emission computed from the BSDF at the hit, and thin sheets
// crossed by shadow rays (a path straight through one keeps its MIS state and depth, as at an
// interface). A path transmitted through a "subsurface" boundary continues from an exit point
// that pbrt-v4's BSSRDF samples (SampleSubsurfaceExit, render/subsurface_exit.h).
//
// Scenes without media or subsurface materials run PathIntegrator (renderer.cpp); kiln
// --generic volpath runs this one anyway, for comparisons.
#pragma once

#include <optional>

#include "base/rng.h"
#include "core/camera/sampler.h"
#include "materials/bxdfs/hg_phase_function.h"
#include "render/dielectric_split.h"
#include "render/radiance.h"
#include "render/scene.h"
#include "render/subsurface_exit.h"
#include "render/volpath_light_sampling.h"

namespace kiln {

template <typename RadianceType>
class VolPathIntegrator : private VolPathLightSampling<RadianceType> {
    using Base = VolPathLightSampling<RadianceType>;
    using Base::EmissionWeight;
    using Base::kMaxInterfaceCrossings;
    using Base::MediumEmissionPDF;
    using Base::MediumEmissionSampled;
    using Base::SampleEmittersLd;
    using Base::SampleLd;
    using Base::scene;
    using Base::settings;
    using Base::WavelengthMean;
    using Base::WindowsActive;

  public:
    using Radiance = RadianceType;
    using Spectrum = typename Radiance::Spectrum;
    using Throughput = typename Radiance::Throughput;

    VolPathIntegrator(const Scene& scene, PathIntegratorSettings settings)
        : Base(scene, settings) {}

    // Absorption weighs paths whose Russian-roulette weight is at least this (Integrator "bool
    // weightabsorption"); below it, absorption ends them as in pbrt-v4
    static constexpr Float kWeightAbsorptionAbove = 0.25f;

    // As PathIntegrator::Li; the camera ray starts in the camera's medium.
    Spectrum Li(Ray ray, SampledWavelengths& lambda, Sampler& sampler,
                VisibleSurface* visibleSurface) const {
        PathState start;
        start.medium = scene.cameraMedium;
        return Trace(ray, start, lambda, sampler, visibleSurface);
    }

  private:
    // A path's state where it starts: at the camera, or where a smooth dielectric split it
    struct PathState {
        Throughput beta = Radiance::One();
        SampledSpectrum r_u{1.f}, r_l{1.f};
        bool specularBounce = false, anyNonSpecularBounces = false;
        int depth = 0;
        Float etaScale = 1;
        int sheetCrossings = 0;
        LightSampleContext prevContext;
        int medium = -1;
        bool mayBranch = true;  // a branch splits no further
    };

    // The radiance arriving along ray at a path in state start.
    Spectrum Trace(Ray ray, const PathState& start, SampledWavelengths& lambda, Sampler& sampler,
                   VisibleSurface* visibleSurface) const {
        Spectrum L{};
        Throughput beta = start.beta;
        SampledSpectrum r_u = start.r_u, r_l = start.r_l;
        bool specularBounce = start.specularBounce,
             anyNonSpecularBounces = start.anyNonSpecularBounces;
        int depth = start.depth;
        Float etaScale = start.etaScale;
        int sheetCrossings = start.sheetCrossings;
        LightSampleContext prevContext = start.prevContext;
        int prevScatterMedium = -1;  // the medium prevContext scattered in (-1: a surface)
        // On the first chord inside a hot medium after refracting into it through one of its
        // glass windows: the rescaled probability r_n of window sampling making the path
        bool windowChord = false;
        SampledSpectrum r_n(0.f);
        int medium = start.medium;
        const int maxDepth = settings.maxDepth;

        while (true) {
            std::optional<ShapeIntersection> si = scene.aggregate->Intersect(ray, Infinity);
            if (medium >= 0) {
                // Sample the medium up to the surface hit (or forever)
                bool scattered = false, terminated = false;
                Float tMax = si ? si->tHit : Infinity;
                // A uniform medium's emission along the whole segment, integrated exactly
                // where no light sampling strategy could have found it (MIS would weigh it
                // point by point): camera rays, after specular bounces, from a point
                // scattering in the medium itself, or a medium not sampled as a light; and on
                // a window chord, which window sampling integrates the same way (the two are
                // weighted against each other as a whole, r_n being window sampling's)
                bool emissionDone = false;
                if (depth < maxDepth && !scene.exactEmissionMedia.empty() &&
                    scene.exactEmissionMedia[size_t(medium)] &&
                    (depth == 0 || specularBounce ||
                     !MediumEmissionSampled(medium, prevScatterMedium))) {
                    if (std::optional<SampledSpectrum> E =
                            scene.media[size_t(medium)].UniformSegmentEmission(tMax * Length(ray.d),
                                                                               lambda)) {
                        emissionDone = true;
                        SampledSpectrum r = windowChord ? r_u + r_n : r_u;
                        if (windowChord && settings.strategy == LightStrategy::LightOnly)
                            *E = SampledSpectrum(0.f);
                        if (*E)
                            L += Radiance::Apply(
                                beta, Radiance::Unpolarized(*E / WavelengthMean(r, lambda)));
                        windowChord = false;
                    }
                }
                // Light sampling at tentative collisions rather than at real scatterings, on
                // segments no scattering could have started (camera rays, after specular
                // bounces): what a thin medium scatters towards the camera is estimated on
                // every path, not on the few that scatter (Integrator "bool
                // collisionlightsampling")
                bool lightAtCollisions = settings.collisionLightSampling && !windowChord &&
                                         settings.strategy != LightStrategy::BSDFOnly &&
                                         (depth == 0 || specularBounce);
                int segmentCollisions = 0;
                // A real scattering at p, its weight in beta and r_u: direct light there (unless
                // sampled at collisions), then a new direction (scattered), or the path's end
                // (terminated)
                auto scatterAt = [&](Point3f p, const MediumProperties& mp) {
                    KeepInRange(beta, r_u, r_l, r_n);
                    if (!beta || !r_u) return;
                    Vector3f wo = -ray.d;
                    HGPhaseFunction phase(mp.g);
                    windowChord = false;
                    if (settings.strategy != LightStrategy::BSDFOnly && !lightAtCollisions) {
                        Interaction intr(p, Normal3f(), Point2f(), wo, ray.time);
                        L += SampleLd(intr, nullptr, &phase, medium, lambda, sampler, beta, r_u);
                        L += SampleEmittersLd(intr, nullptr, &phase, medium, depth, lambda, sampler,
                                              beta, r_u);
                    }
                    std::optional<PhaseFunctionSample> ps = phase.Sample_p(wo, sampler.Get2D());
                    if (!ps || ps->pdf == 0) {
                        terminated = true;
                        return;
                    }
                    beta = beta * Radiance::Depolarizing(SampledSpectrum(ps->p / ps->pdf));
                    r_l = r_u / ps->pdf;
                    prevContext = LightSampleContext(Interaction(p, Normal3f(), Point2f()));
                    prevScatterMedium = medium;
                    scattered = true;
                    ray = Ray(p, ps->wi, ray.time);
                    specularBounce = false;
                    anyNonSpecularBounces = true;
                };
                const Medium& segmentMedium = scene.media[size_t(medium)];
                RNG rng(Hash(sampler.Get1D()), Hash(sampler.Get1D()));
                Float uDistance = sampler.Get1D();
                // A uniform medium whose emission is settled (or that has none), on a path that
                // carries much: only scattering is sampled, and absorption weighs the path,
                // exp(-sigma_a t) (a uniform medium's majorant is its extinction, so the
                // tracking below has no null collision absorption could weigh)
                if (settings.weightAbsorption && !windowChord && segmentMedium.IsUniform() &&
                    (emissionDone || !segmentMedium.IsEmissive()) &&
                    Radiance::RouletteWeight(beta) * etaScale / WavelengthMean(r_u, lambda) >=
                        kWeightAbsorptionAbove) {
                    lightAtCollisions = false;  // no tentative collisions here
                    MediumProperties mp = segmentMedium.SamplePoint(ray.o, lambda);
                    const SampledSpectrum sigma_t = mp.sigma_a + mp.sigma_s;
                    const Float len = Length(ray.d), distance = tMax * len;
                    Float t =
                        mp.sigma_s[0] > 0 ? SampleExponential(uDistance, mp.sigma_s[0]) : Infinity;
                    // beta divides by the probability of what was done; the rescaled
                    // probabilities are those of pbrt-v4's tracking (as for null collisions)
                    if (t < distance) {
                        if (depth++ >= maxDepth) return L;
                        SampledSpectrum T_t = Medium::FastExpTransmittance(t, sigma_t);
                        Float pdf = mp.sigma_s[0] * T_t[0];
                        if (!(pdf > 0)) return L;
                        Float pdfScatter =
                            mp.sigma_s[0] * Medium::FastExpTransmittance(t, mp.sigma_s)[0];
                        beta = beta * (mp.sigma_s * T_t / pdfScatter);
                        r_u *= mp.sigma_s * T_t / pdf;
                        scatterAt(ray(t / len), mp);
                        if (terminated || !beta || !r_u) return L;
                        continue;
                    }
                    // Through to the surface (or forever, where nothing scatters): the light
                    // strategy's transmittance is the majorant's, exp(-sigma_t d)
                    Float pdfPass = Medium::FastExpTransmittance(distance, mp.sigma_s)[0];
                    SampledSpectrum T_t = Medium::FastExpTransmittance(distance, sigma_t);
                    if (!(T_t[0] > 0)) return L;
                    beta = beta * (T_t / pdfPass);
                    r_u *= T_t / T_t[0];
                    r_l *= T_t / T_t[0];
                    if (!beta || !r_u) return L;
                } else {
                    SampledSpectrum T_maj = segmentMedium.SampleT_maj(
                        ray, tMax, uDistance, rng, lambda,
                        [&](Point3f p, const MediumProperties& mp, const SampledSpectrum& sigma_maj,
                            const SampledSpectrum& T_maj) {
                            if (!beta) {
                                terminated = true;
                                return false;
                            }
                            // Emission at the tentative collision, weighted against sampling
                            // the medium's emission from the previous vertex
                            if (depth < maxDepth && !emissionDone && mp.emission) {
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
                                        Radiance::Unpolarized(mp.emission /
                                                              WavelengthMean(r, lambda)));
                                }
                            }
                            // Light sampling at the k-th tentative collision of the segment
                            // with probability 1 / k (about the log of their number in all),
                            // weighted by the probability of scattering there; MIS as for a
                            // real scattering
                            ++segmentCollisions;
                            if (lightAtCollisions && depth < maxDepth && mp.sigma_s[0] > 0 &&
                                (segmentCollisions == 1 ||
                                 rng.UniformFloat() * Float(segmentCollisions) < 1)) {
                                Float pdfRef = T_maj[0] * mp.sigma_s[0];
                                Float pdfDone = T_maj[0] * sigma_maj[0] / Float(segmentCollisions);
                                Throughput betaS = beta * (T_maj * mp.sigma_s / pdfDone);
                                SampledSpectrum r_s = r_u * T_maj * mp.sigma_s / pdfRef;
                                HGPhaseFunction phase(mp.g);
                                Interaction intr(p, Normal3f(), Point2f(), -ray.d, ray.time);
                                L += SampleLd(intr, nullptr, &phase, medium, lambda, sampler, betaS,
                                              r_s);
                                L += SampleEmittersLd(intr, nullptr, &phase, medium, depth + 1,
                                                      lambda, sampler, betaS, r_s);
                            }
                            // Absorption, real scattering or a null collision. While the path
                            // carries much (its throughput over the wavelengths' mean probability,
                            // as Russian roulette weighs it: the same whichever wavelength is the
                            // hero), absorption is a weight on passing on rather than an end
                            bool weightAbsorption = settings.weightAbsorption &&
                                                    Radiance::RouletteWeight(beta) * etaScale /
                                                            WavelengthMean(r_u, lambda) >=
                                                        kWeightAbsorptionAbove;
                            Float pAbsorb = weightAbsorption ? 0 : mp.sigma_a[0] / sigma_maj[0];
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
                                scatterAt(p, mp);
                                return false;
                            }
                            // Null collision (or absorption, weighted). The rescaled
                            // probabilities stay those of pbrt-v4's tracking, as light sampling
                            // computes them along shadow rays, so that MIS weights still sum to
                            // one; beta divides by the probability of what was done
                            SampledSpectrum sigma_n =
                                ClampZero(sigma_maj - mp.sigma_a - mp.sigma_s);
                            Float pdf = T_maj[0] * sigma_n[0];
                            if (pdf == 0) {
                                beta = Throughput{};
                                return false;
                            }
                            Float pdfPass =
                                weightAbsorption ? T_maj[0] * (sigma_n[0] + mp.sigma_a[0]) : pdf;
                            beta = beta * (T_maj * sigma_n / pdfPass);
                            r_u *= T_maj * sigma_n / pdf;
                            r_l *= T_maj * sigma_maj / pdf;
                            if (windowChord) r_n *= T_maj * sigma_maj / pdf;
                            KeepInRange(beta, r_u, r_l, r_n);
                            return bool(beta) && bool(r_u);
                        });
                    if (terminated || !beta || !r_u) return L;
                    if (scattered) continue;
                    if (T_maj[0] == 0) return L;
                    beta = beta * (T_maj / T_maj[0]);
                    r_u *= T_maj / T_maj[0];
                    r_l *= T_maj / T_maj[0];
                }
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
            if (Spectrum Le = scene.template SurfaceLe<Spectrum>(isect, bsdf, -ray.d, lambda)) {
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
                Point2f u2 = sampler.Get2D();
                if (SplitsAt(settings, start.mayBranch, depth, bsdf)) {
                    // Reflection as a branch of its own, transmission here (dielectric_split.h)
                    DielectricSplit<Throughput> split =
                        SplitDielectric<Throughput>(bsdf, wo, u, u2);
                    if (const auto& rs = split.reflection) {
                        PathState branch;
                        branch.beta = beta * (rs->f * (AbsDot(rs->wi, isect.shading.n) / rs->pdf));
                        branch.r_u = r_u;
                        branch.r_l = r_u / rs->pdf;
                        branch.specularBounce = true;
                        branch.anyNonSpecularBounces = anyNonSpecularBounces;
                        branch.depth = depth;
                        branch.etaScale = etaScale;
                        branch.sheetCrossings = sheetCrossings;
                        branch.prevContext = prevContext;
                        branch.medium = isect.MediumAfter(rs->wi, medium);
                        branch.mayBranch = false;
                        L += Trace(isect.SpawnRay(rs->wi), branch, lambda, sampler, nullptr);
                    }
                    bs = split.transmission;
                } else {
                    bs = bsdf.Sample_f<Throughput>(wo, u, u2);
                }
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
                        SampleSubsurfaceExit(scene, *material, isect, ray.time, lambda, sampler);
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
    // beta and the rescaled probabilities r_u, r_l, r_n enter every estimate as ratios (beta
    // over a mean of r's), so one common factor changes nothing. Where a medium's extinction
    // differs by orders of magnitude between the wavelengths, each collision multiplies them
    // all by that ratio, and after a few they overflow single precision together (pbrt-v4's
    // volpath then returns NaN); dividing them by their largest r keeps them in range.
    static void KeepInRange(Throughput& beta, SampledSpectrum& r_u, SampledSpectrum& r_l,
                            SampledSpectrum& r_n) {
        Float m = std::max(r_u.MaxComponentValue(), r_l.MaxComponentValue());
        if (!(m > kRescaleAbove)) return;
        Float k = 1 / m;
        beta = beta * Radiance::Depolarizing(SampledSpectrum(k));
        r_u *= k;
        r_l *= k;
        r_n *= k;
    }
    static constexpr Float kRescaleAbove = 1e16f;
};

}  // namespace kiln
