// Unidirectional path tracing with multiple importance sampling (pbrt-v4's PathIntegrator).
//
// The radiance representation is a template parameter (see radiance.h): the same code renders
// unpolarised and polarised light. At each surface the integrator builds the BSDF,
// adds the surface's emission (computed from that BSDF, in its shading frame: thermal emission
// is a property of the surface; MIS-weighted against light sampling when the surface is a
// light), samples one light (MIS-weighted against BSDF sampling), then continues the path by
// sampling the BSDF, with Russian roulette after the first bounces.
//
// Thin sheets (BxDFFlags::StraightThrough: a bulb, a window pane) are crossed by shadow rays,
// attenuated by their transmittance, so light sampling sees a lamp through its glass. A path
// that goes straight through one therefore keeps the vertex before it for MIS (as pbrt-v4
// keeps it across interface surfaces) and counts no bounce: both strategies cover the same
// paths. pbrt-v4 blocks shadow rays at every surface and finds such a lamp only by BSDF
// sampling: the same mean, far more noise (a point light in a bulb lights nothing at all).
#pragma once

#include <optional>

#include "core/camera/sampler.h"
#include "render/dielectric_split.h"
#include "render/radiance.h"
#include "render/scene.h"
#include "render/thin_sheets.h"

namespace kiln {

template <typename RadianceType>
class PathIntegrator {
  public:
    using Radiance = RadianceType;
    using Spectrum = typename Radiance::Spectrum;
    using Throughput = typename Radiance::Throughput;

    PathIntegrator(const Scene& scene, PathIntegratorSettings settings)
        : scene(scene), settings(settings) {}

    // Radiance arriving along ray at the wavelengths lambda (polarised: Stokes in the implicit
    // frame of -ray.d). visibleSurface (if non-null) gets the first hit's geometry and albedo
    // for AOVs.
    Spectrum Li(Ray ray, SampledWavelengths& lambda, Sampler& sampler,
                VisibleSurface* visibleSurface) const {
        return Trace(ray, PathState{}, lambda, sampler, visibleSurface);
    }

  private:
    // A path's state where it starts: at the camera, or where a smooth dielectric split it
    struct PathState {
        Throughput beta = Radiance::One();
        bool specularBounce = false, anyNonSpecularBounces = false;
        int depth = 0;
        Float etaScale = 1;
        Float prevBsdfPdf = 0;
        int sheetCrossings = 0;
        LightSampleContext prevContext;
        bool mayBranch = true;  // a branch splits no further
    };

    // The radiance arriving along ray at a path in state start.
    Spectrum Trace(Ray ray, const PathState& start, SampledWavelengths& lambda, Sampler& sampler,
                   VisibleSurface* visibleSurface) const {
        Spectrum L{};
        Throughput beta = start.beta;
        bool specularBounce = start.specularBounce,
             anyNonSpecularBounces = start.anyNonSpecularBounces;
        int depth = start.depth;
        Float etaScale = start.etaScale;
        Float prevBsdfPdf =
            start.prevBsdfPdf;  // pdf (solid angle) of the BSDF sample that made ray
        int sheetCrossings = start.sheetCrossings;
        LightSampleContext prevContext = start.prevContext;

        while (true) {
            std::optional<ShapeIntersection> si = scene.aggregate->Intersect(ray, Infinity);

            // Escaped rays: add emission from infinite lights
            if (!si) {
                for (int index : scene.infiniteLights) {
                    const Light& light = scene.lights[size_t(index)];
                    SampledSpectrum Le = light.Le(ray, lambda);
                    if (!Le) continue;
                    if (depth == 0 || specularBounce) {
                        L += Radiance::Apply(beta, Radiance::Unpolarized(Le));
                    } else {
                        Float lightPdf = scene.lightSampler->PMF(prevContext, index) *
                                         light.PDF_Li(prevContext, ray.d, true);
                        Float w = EmissionWeight(prevBsdfPdf, lightPdf);
                        L += Radiance::Apply(beta, Radiance::Unpolarized(w * Le));
                    }
                }
                break;
            }
            SurfaceInteraction& isect = si->intr;

            // The BSDF at the hit (invalid for interface materials, which only mark
            // boundaries); emission is computed from it, in its shading frame
            BSDF bsdf = scene.GetBSDF(isect, lambda);
            if (Spectrum Le = scene.SurfaceLe<Spectrum>(isect, bsdf, -ray.d, lambda)) {
                if (depth == 0 || specularBounce || isect.lightIndex < 0) {
                    // All of it: light sampling could not have found it
                    L += Radiance::Apply(beta, Le);
                } else {
                    const Light& light = scene.lights[size_t(isect.lightIndex)];
                    Float lightPdf = scene.lightSampler->PMF(prevContext, isect.lightIndex) *
                                     light.PDF_Li(prevContext, ray.d, true);
                    Float w = EmissionWeight(prevBsdfPdf, lightPdf);
                    L += Radiance::Apply(beta, Le * w);
                }
            }
            if (!bsdf) {
                specularBounce = true;
                ray = isect.SpawnRay(ray.d);
                continue;
            }
            if (depth == 0 && sheetCrossings == 0 && visibleSurface)
                *visibleSurface = scene.MakeVisibleSurface(isect, bsdf, lambda);
            if (settings.regularize && anyNonSpecularBounces) bsdf.Regularize();

            // Straight through a thin sheet, which shadow rays cross too (thin_sheets.h)
            std::optional<BSDFSampleOf<Throughput>> sheetSample;
            if (IsStraightThrough(bsdf.Flags())) {
                sheetSample = SampleSheet<Throughput>(bsdf, isect.wo, sampler);
                if (!sheetSample) break;
                if (sheetSample->IsStraightThrough()) {
                    if (++sheetCrossings > kMaxSheetCrossings) break;
                    beta = beta * CrossingWeight(*sheetSample, isect.shading.n);
                    ray = isect.SpawnRay(sheetSample->wi);
                    continue;
                }
            }

            if (depth++ == settings.maxDepth) break;

            // Direct lighting by light sampling
            Vector3f wo = -ray.d;
            if (IsNonSpecular(bsdf.Flags()) && settings.strategy != LightStrategy::BSDFOnly) {
                Spectrum Ld = SampleLd(isect, bsdf, lambda, sampler);
                if (Ld) L += Radiance::Apply(beta, Ld);
            }

            // Continue the path by sampling the BSDF (a sheet's reflection is sampled already)
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
                        branch.specularBounce = true;
                        branch.anyNonSpecularBounces = anyNonSpecularBounces;
                        branch.depth = depth;
                        branch.etaScale = etaScale;
                        branch.prevBsdfPdf = rs->pdf;
                        branch.sheetCrossings = sheetCrossings;
                        branch.prevContext = LightSampleContext(isect);
                        branch.mayBranch = false;
                        L += Trace(isect.SpawnRay(rs->wi), branch, lambda, sampler, nullptr);
                    }
                    bs = split.transmission;
                } else {
                    bs = bsdf.Sample_f<Throughput>(wo, u, u2);
                }
            }
            if (!bs || bs->pdf == 0 || !bs->f) break;
            beta = beta * (bs->f * (AbsDot(bs->wi, isect.shading.n) / bs->pdf));
            prevBsdfPdf = bs->pdfIsProportional ? bsdf.PDF(wo, bs->wi) : bs->pdf;
            specularBounce = bs->IsSpecular();
            anyNonSpecularBounces |= !bs->IsSpecular();
            if (bs->IsTransmission()) etaScale *= Sqr(bs->eta);
            prevContext = LightSampleContext(isect);
            ray = isect.SpawnRay(bs->wi);

            // Russian roulette, on throughput with the radiance scaling of refraction removed
            Float rrBeta = Radiance::RouletteWeight(beta) * etaScale;
            if (rrBeta < 1 && depth > 1) {
                Float q = std::max<Float>(0, 1 - rrBeta);
                if (sampler.Get1D() < q) break;
                beta = beta / (1 - q);
            }
        }
        return L;
    }

  private:
    // Weight of emission found by BSDF sampling: MIS against light sampling (pbrt-v4), all of
    // it when lights are never sampled, none of it when only light sampling finds emitters.
    Float EmissionWeight(Float bsdfPdf, Float lightPdf) const {
        switch (settings.strategy) {
            case LightStrategy::MIS:
                return PowerHeuristic(1, bsdfPdf, 1, lightPdf);
            case LightStrategy::BSDFOnly:
                return 1;
            case LightStrategy::LightOnly:
                return lightPdf > 0 ? 0 : 1;
        }
        return 1;
    }

    // One light sample: pick a light by power, sample a point on it, MIS-weight against the BSDF.
    Spectrum SampleLd(const SurfaceInteraction& intr, const BSDF& bsdf,
                      const SampledWavelengths& lambda, Sampler& sampler) const {
        LightSampleContext ctx(intr);
        // Move the reference point to the side the BSDF can scatter to, for one-sided BSDFs.
        BxDFFlags flags = bsdf.Flags();
        if (IsReflective(flags) && !IsTransmissive(flags))
            ctx.p = intr.OffsetRayOrigin(intr.wo);
        else if (IsTransmissive(flags) && !IsReflective(flags))
            ctx.p = intr.OffsetRayOrigin(-intr.wo);

        Float uLight = sampler.Get1D();
        Point2f uPoint = sampler.Get2D();
        std::optional<SampledLight> sampled = scene.lightSampler->Sample(ctx, uLight);
        if (!sampled) return {};
        const Light& light = scene.lights[size_t(sampled->index)];
        // The light's radiance is evaluated last, only for a usable sample
        std::optional<LightLiSample> ls = light.SampleLi(ctx, uPoint, lambda, true);
        if (!ls || ls->pdf == 0 || (!ls->deferredL && !ls->L)) return {};

        // The BSDF and its cosine see the light's direction with pbrt-v4's length (1 but for
        // environment maps under transforms that change lengths: LightLiSample::wiLength)
        Vector3f wo = intr.wo, wi = ls->wi * ls->wiLength;
        Float cosTheta = AbsDot(wi, intr.shading.n);
        if (cosTheta == 0) return {};
        Throughput f = bsdf.f<Throughput>(wo, wi);
        if (!f) return {};
        if (scene.features.sheets == 0) {
            if (scene.aggregate->IntersectP(intr.SpawnRayTo(ls->pLight), 1 - ShadowEpsilon))
                return {};
        } else {
            std::optional<Throughput> sheets = SheetsTransmittance(intr, ls->pLight, lambda);
            if (!sheets) return {};
            f = f * *sheets;
        }
        Spectrum Li = light.DeferredL<Spectrum>(*ls, lambda, *scene.job->shader);
        if (!Li) return {};

        Float lightPdf = sampled->p * ls->pdf;
        if (IsDeltaLight(light.Type())) return Radiance::Apply(f, Li) * (cosTheta / lightPdf);
        Float bsdfPdf = bsdf.PDF(wo, wi);
        Float w = settings.strategy == LightStrategy::MIS ? PowerHeuristic(1, lightPdf, 1, bsdfPdf)
                                                          : Float(1);
        return Radiance::Apply(f, Li) * (w * cosTheta / lightPdf);
    }

    // What reaches intr from pLight through the thin sheets between them (the product of their
    // transmittances), or nothing when another surface is in the way.
    std::optional<Throughput> SheetsTransmittance(const Interaction& intr,
                                                  const Interaction& pLight,
                                                  const SampledWavelengths& lambda) const {
        Throughput T = Radiance::One();
        Ray ray = intr.SpawnRayTo(pLight);
        for (int crossings = 0;; ++crossings) {
            std::optional<ShapeIntersection> si =
                scene.aggregate->Intersect(ray, 1 - ShadowEpsilon);
            if (!si) return T;
            if (crossings == kMaxSheetCrossings) return std::nullopt;
            std::optional<Throughput> sheet =
                SheetTransmittance<Throughput>(scene, si->intr, lambda);
            if (!sheet) return std::nullopt;
            T = T * *sheet;
            ray = si->intr.SpawnRayTo(pLight);
        }
    }

    const Scene& scene;
    PathIntegratorSettings settings;
};

}  // namespace kiln
