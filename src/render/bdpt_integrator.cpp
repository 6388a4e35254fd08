#include "render/bdpt_integrator.h"

#include <cmath>

namespace kiln {

BDPTIntegrator::BDPTIntegrator(const Scene& scene, PathIntegratorSettings settings)
    : scene(scene),
      settings(settings),
      camera(scene.camera->GetIf<PerspectiveCamera>()),
      film(scene.job->film),
      sampleBounds(scene.job->film->SampleBounds()),
      lightSampler(std::span<const Light>(scene.lights)) {
    Point2i full = film->FullResolution();
    // One light subpath per camera sample, of every pixel sampled (with spread reconstruction,
    // also those of the margin around the pixel bounds)
    splatScale = Float(double(full.x) * full.y / double(film->SpreadPixelBounds().Area()));
    Point3f center;
    scene.aggregate->Bounds().BoundingSphere(&center, &sceneRadius);
}

// Densities
Float BDPTIntegrator::InfiniteLightDensity(Vector3f w) const {
    Float pdf = 0;
    for (int index : scene.infiniteLights)
        pdf +=
            scene.lights[size_t(index)].PDF_Li(LightSampleContext(), -w) * lightSampler.PMF(index);
    return pdf;
}

Float BDPTIntegrator::PDF(const BDPTVertex& v, const BDPTVertex* prev,
                          const BDPTVertex& next) const {
    if (v.type == BDPTVertexType::Light) return PDFLight(v, next);
    Vector3f wn = next.p() - v.p();
    if (LengthSquared(wn) == 0) return 0;
    wn = Normalize(wn);
    Float pdf = 0;
    if (v.type == BDPTVertexType::Camera) {
        pdf = camera->PDF_We(Ray(v.p(), wn, v.si.time), sampleBounds).dir;
    } else {
        if (!prev) return 0;
        Vector3f wp = prev->p() - v.p();
        if (LengthSquared(wp) == 0) return 0;
        pdf = v.bsdf.PDF(Normalize(wp), wn);
    }
    return v.ConvertDensity(pdf, next);
}

Float BDPTIntegrator::PDFLight(const BDPTVertex& v, const BDPTVertex& next) const {
    Vector3f w = next.p() - v.p();
    Float d2 = LengthSquared(w);
    if (d2 == 0) return 0;
    Float invDist2 = 1 / d2;
    w = w * std::sqrt(invDist2);
    Float pdf;
    if (v.IsInfiniteLight()) {
        // Rays from lights at infinity start uniformly on the disk the scene presents
        pdf = 1 / (Pi * Sqr(sceneRadius));
    } else if (v.IsOnSurface()) {
        pdf = LightOf(v).PDF_Le(v.si, w).dir * invDist2;
    } else {
        pdf = LightOf(v).PDF_Le(Ray(v.p(), w)).dir * invDist2;
    }
    if (next.IsOnSurface()) pdf *= AbsDot(next.ng(), w);
    return pdf;
}

Float BDPTIntegrator::PDFLightOrigin(const BDPTVertex& v, const BDPTVertex& next) const {
    Vector3f w = next.p() - v.p();
    if (LengthSquared(w) == 0) return 0;
    w = Normalize(w);
    if (v.IsInfiniteLight()) return InfiniteLightDensity(w);
    int index = LightIndexOf(v);
    if (index < 0) return 0;
    const Light& light = scene.lights[size_t(index)];
    LightLePDF pdf = v.IsOnSurface() ? light.PDF_Le(v.si, w) : light.PDF_Le(Ray(v.p(), w));
    return pdf.pos * lightSampler.PMF(index);
}

SampledSpectrum BDPTIntegrator::Le(const BDPTVertex& v, const BDPTVertex& to,
                                   const SampledWavelengths& lambda) const {
    Vector3f w = to.p() - v.p();
    if (LengthSquared(w) == 0) return SampledSpectrum(0);
    w = Normalize(w);
    if (v.IsInfiniteLight()) {
        SampledSpectrum L(0);
        for (int index : scene.infiniteLights)
            L += scene.lights[size_t(index)].Le(Ray(v.p(), -w), lambda);
        return L;
    }
    if (v.type == BDPTVertexType::Surface) return scene.SurfaceLe(v.si, v.bsdf, w, lambda);
    return SampledSpectrum(0);
}

bool BDPTIntegrator::Unoccluded(const Interaction& a, const Interaction& b) const {
    return !scene.aggregate->IntersectP(a.SpawnRayTo(b), 1 - ShadowEpsilon);
}

// Subpaths
int BDPTIntegrator::CameraSubpath(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler,
                                  BDPTVertex* path, VisibleSurface* visibleSurface) const {
    int maxDepth = settings.maxDepth + 2;
    BDPTVertex& v = path[0];
    v = BDPTVertex();
    v.type = BDPTVertexType::Camera;
    v.beta = SampledSpectrum(1);
    v.si.p = ray.o;
    v.si.time = ray.time;
    Float pdfDir = camera->PDF_We(ray, sampleBounds).dir;
    return RandomWalk(lambda, ray, sampler, v.beta, pdfDir, maxDepth - 1, TransportMode::Radiance,
                      path + 1, visibleSurface) +
           1;
}

int BDPTIntegrator::LightSubpath(SampledWavelengths& lambda, Sampler& sampler, BDPTVertex* path,
                                 Float time) const {
    int maxDepth = settings.maxDepth + 1;
    std::optional<SampledLight> sampled = lightSampler.Sample(sampler.Get1D());
    Point2f u1 = sampler.Get2D(), u2 = sampler.Get2D();
    if (!sampled) return 0;
    const Light& light = scene.lights[size_t(sampled->index)];
    std::optional<LightLeSample> les = light.SampleLe(u1, u2, lambda, *scene.job->shader);
    if (!les || les->pdfPos == 0 || les->pdfDir == 0 || !les->L) return 0;

    les->ray.time = time;  // the camera ray's: moving objects are where the camera sees them
    Float pLight = sampled->p * les->pdfPos;
    BDPTVertex& v = path[0];
    v = BDPTVertex();
    v.si.time = time;
    v.type = BDPTVertexType::Light;
    v.light = sampled->index;
    v.lightType = light.Type();
    v.beta = les->L;
    v.pdfFwd = pLight;
    if (les->intr) {
        v.si.p = les->intr->p;
        v.si.n = les->intr->n;
        v.si.uv = les->intr->uv;
    } else {
        v.si.p = les->ray.o;
    }
    SampledSpectrum beta = les->L * les->AbsCosTheta(les->ray.d) / (pLight * les->pdfDir);
    int n = RandomWalk(lambda, les->ray, sampler, beta, les->pdfDir, maxDepth - 1,
                       TransportMode::Importance, path + 1, nullptr);
    // Lights at infinity: the first hit's density is by area of the disk the rays start on,
    // the light vertex's that of the direction
    if (v.IsInfiniteLight()) {
        if (n > 0) {
            path[1].pdfFwd = les->pdfPos;
            if (path[1].IsOnSurface()) path[1].pdfFwd *= AbsDot(les->ray.d, path[1].ng());
        }
        v.pdfFwd = InfiniteLightDensity(les->ray.d);
    }
    return n + 1;
}

int BDPTIntegrator::RandomWalk(SampledWavelengths& lambda, Ray ray, Sampler& sampler,
                               SampledSpectrum beta, Float pdf, int maxDepth, TransportMode mode,
                               BDPTVertex* path, VisibleSurface* visibleSurface) const {
    if (maxDepth == 0) return 0;
    int bounces = 0;
    bool anyNonSpecularBounces = false;
    Float pdfFwd = pdf;
    while (beta) {
        BDPTVertex &vertex = path[bounces], &prev = path[bounces - 1];
        std::optional<ShapeIntersection> si = scene.aggregate->Intersect(ray, Infinity);
        if (!si) {
            // Escaped camera rays end at the lights at infinity
            if (mode == TransportMode::Radiance) {
                vertex = BDPTVertex();
                vertex.type = BDPTVertexType::Light;
                vertex.beta = beta;
                vertex.si.p = ray.o + ray.d;
                vertex.si.n = Normal3f(-ray.d);
                vertex.pdfFwd = pdfFwd;
                ++bounces;
            }
            break;
        }
        SurfaceInteraction& isect = si->intr;
        BSDF bsdf = scene.GetBSDF(isect, lambda);
        if (!bsdf) {
            ray = isect.SpawnRay(ray.d);  // an interface between media: no vertex
            continue;
        }
        if (bounces == 0 && visibleSurface)
            *visibleSurface = scene.MakeVisibleSurface(isect, bsdf, lambda);
        if (settings.regularize && anyNonSpecularBounces) bsdf.Regularize();

        vertex = BDPTVertex();
        vertex.type = BDPTVertexType::Surface;
        vertex.si = isect;
        vertex.bsdf = bsdf;
        vertex.beta = beta;
        vertex.pdfFwd = prev.ConvertDensity(pdfFwd, vertex);
        if (++bounces >= maxDepth) break;

        Vector3f wo = isect.wo;
        Float u = sampler.Get1D();
        std::optional<BSDFSample> bs = bsdf.Sample_f(wo, u, sampler.Get2D(), mode);
        if (!bs || bs->pdf == 0 || !bs->f) break;
        pdfFwd = bs->pdfIsProportional ? bsdf.PDF(wo, bs->wi, mode) : bs->pdf;
        anyNonSpecularBounces |= !bs->IsSpecular();
        if (mode == TransportMode::Importance && !bs->IsSpecular() &&
            BDPTVertex::AdjointSwaps(bsdf)) {
            // The adjoint (BDPTVertex::AdjointF) over the density of the sampled direction
            Float pdf = bsdf.PDF(wo, bs->wi, mode);
            if (pdf == 0) break;
            beta *= BDPTVertex::AdjointF(bsdf, isect, wo, bs->wi) *
                    (AbsDot(bs->wi, isect.shading.n) / pdf);
        } else {
            beta *= bs->f * AbsDot(bs->wi, isect.shading.n) / bs->pdf;
            if (mode == TransportMode::Importance)
                beta *= BDPTVertex::ShadingNormalAdjoint(isect, wo, bs->wi);
        }
        ray = isect.SpawnRay(bs->wi);
        TransportMode reverse =
            mode == TransportMode::Radiance ? TransportMode::Importance : TransportMode::Radiance;
        Float pdfRev = bsdf.PDF(bs->wi, wo, reverse);
        if (bs->IsSpecular()) {
            vertex.delta = true;
            pdfRev = pdfFwd = 0;
        }
        prev.pdfRev = vertex.ConvertDensity(pdfRev, prev);
    }
    return bounces;
}

// Strategies
SampledSpectrum BDPTIntegrator::Li(Ray ray, SampledWavelengths& lambda, Sampler& sampler,
                                   VisibleSurface* visibleSurface) const {
    // The two subpaths' vertices, in a buffer each thread keeps (no allocation per sample)
    thread_local std::vector<BDPTVertex> vertices;
    size_t nMax = 2 * size_t(settings.maxDepth) + 3;
    if (vertices.size() < nMax) vertices.resize(nMax);
    BDPTVertex* cameraVertices = vertices.data();
    BDPTVertex* lightVertices = vertices.data() + settings.maxDepth + 2;
    int nCamera = CameraSubpath(ray, lambda, sampler, cameraVertices, visibleSurface);
    int nLight = LightSubpath(lambda, sampler, lightVertices, ray.time);

    // Light sampling (s = 1) runs whether or not the light subpath could start: its MIS weight
    // counts on it. (pbrt-v4 skips it with the light subpath, which darkens scenes whose light
    // subpaths may fail, e.g. lights with cut-outs: 0.84 of the true mean in a test scene.)
    const int sMax = std::max(nLight, 1);
    SampledSpectrum L(0);
    for (int t = 1; t <= nCamera; ++t)
        for (int s = 0; s <= sMax; ++s) {
            int depth = t + s - 2;
            if ((s == 1 && t == 1) || depth < 0 || depth > settings.maxDepth) continue;
            Point2f pRaster;
            SampledSpectrum Lpath =
                Connect(lambda, lightVertices, cameraVertices, s, t, sampler, &pRaster);
            if (t != 1)
                L += Lpath;
            else if (Lpath)
                film->AddSplat(pRaster, Lpath, lambda);
        }
    return L;
}

SampledSpectrum BDPTIntegrator::Connect(SampledWavelengths& lambda, BDPTVertex* lightVertices,
                                        BDPTVertex* cameraVertices, int s, int t, Sampler& sampler,
                                        Point2f* pRaster) const {
    // A camera path that ended at infinity connects to nothing
    if (t > 1 && s != 0 && cameraVertices[t - 1].type == BDPTVertexType::Light)
        return SampledSpectrum(0);

    SampledSpectrum L(0);
    BDPTVertex sampled;
    if (s == 0) {
        // The camera path found emission
        const BDPTVertex& pt = cameraVertices[t - 1];
        if (pt.type == BDPTVertexType::Light || pt.type == BDPTVertexType::Surface)
            L = Le(pt, cameraVertices[t - 2], lambda) * pt.beta;
        // Emission no light stands for (only this strategy finds it): all of it
        if (L && !pt.IsLight()) return L;
    } else if (t == 1) {
        // The light path's end seen from a point sampled on the lens
        const BDPTVertex& qs = lightVertices[s - 1];
        if (qs.IsConnectible()) {
            std::optional<CameraWiSample> cs =
                camera->SampleWi(qs.p(), qs.si.time, sampler.Get2D(), sampleBounds);
            if (cs) {
                *pRaster = cs->pRaster;
                sampled.type = BDPTVertexType::Camera;
                sampled.si.p = cs->pLens;
                sampled.si.time = qs.si.time;
                sampled.si.n = cs->nLens;
                sampled.beta = cs->Wi / cs->pdf;
                L = qs.beta * qs.f(sampled, TransportMode::Importance) * sampled.beta;
                if (qs.IsOnSurface()) L *= AbsDot(cs->wi, qs.ns());
                if (L && !Unoccluded(qs.si, Interaction(cs->pLens, Normal3f(), Point2f())))
                    L = SampledSpectrum(0);
                L *= splatScale;
            }
        }
    } else if (s == 1) {
        // A light sampled from the camera path's end
        const BDPTVertex& pt = cameraVertices[t - 1];
        if (pt.IsConnectible()) {
            std::optional<SampledLight> chosen = lightSampler.Sample(sampler.Get1D());
            Point2f u = sampler.Get2D();
            if (chosen) {
                const Light& light = scene.lights[size_t(chosen->index)];
                LightSampleContext ctx(pt.si);
                // Towards the side of the surface the BSDF scatters to
                BxDFFlags flags = pt.bsdf.Flags();
                if (IsReflective(flags) && !IsTransmissive(flags))
                    ctx.p = pt.si.OffsetRayOrigin(pt.si.wo);
                else if (IsTransmissive(flags) && !IsReflective(flags))
                    ctx.p = pt.si.OffsetRayOrigin(-pt.si.wo);
                std::optional<LightLiSample> ls = light.SampleLi(ctx, u, lambda);
                // The density per steradian at the vertex itself, where the strategy and its
                // MIS weight are evaluated (SampleLi's is at ctx.p, moved off the surface):
                // through the point's density per area. Near a concave emitter a point close
                // to the vertex and nearly tangent otherwise weighs up to a hundred times too
                // much.
                Float pdf = ls ? ls->pdf : 0;
                Vector3f wi = ls ? ls->wi : Vector3f();
                if (ls && pdf > 0 && ls->pLight.n != Normal3f(0, 0, 0)) {
                    Vector3f dc = ls->pLight.p - ctx.p, dv = ls->pLight.p - pt.p();
                    Float d2c = LengthSquared(dc), d2v = LengthSquared(dv);
                    Float cosV = d2v > 0 ? AbsDot(ls->pLight.n, dv) / std::sqrt(d2v) : 0;
                    if (d2c > 0 && cosV > 0) {
                        Float cosC = AbsDot(ls->pLight.n, dc) / std::sqrt(d2c);
                        pdf *= cosC / d2c * d2v / cosV;
                        wi = dv / std::sqrt(d2v);
                    } else {
                        pdf = 0;
                    }
                }
                if (ls && pdf > 0 && std::isfinite(pdf) && (ls->deferredL || ls->L)) {
                    sampled.type = BDPTVertexType::Light;
                    sampled.light = chosen->index;
                    sampled.lightType = light.Type();
                    sampled.si.p = ls->pLight.p;
                    sampled.si.n = ls->pLight.n;
                    sampled.si.uv = ls->pLight.uv;
                    sampled.beta = SampledSpectrum(1 / (pdf * chosen->p));
                    sampled.pdfFwd = PDFLightOrigin(sampled, pt);
                    L = pt.beta * pt.f(sampled, TransportMode::Radiance) * sampled.beta;
                    if (pt.IsOnSurface()) L *= AbsDot(wi, pt.ns());
                    if (L && !Unoccluded(pt.si, ls->pLight)) L = SampledSpectrum(0);
                    if (L) {
                        SampledSpectrum Li =
                            light.DeferredL<SampledSpectrum>(*ls, lambda, *scene.job->shader);
                        sampled.beta *= Li;
                        L *= Li;
                    }
                }
            }
        }
    } else {
        // The general connection of the two subpaths' ends
        const BDPTVertex &qs = lightVertices[s - 1], &pt = cameraVertices[t - 1];
        if (qs.IsConnectible() && pt.IsConnectible()) {
            L = qs.beta * qs.f(pt, TransportMode::Importance) * pt.f(qs, TransportMode::Radiance) *
                pt.beta;
            if (L) {
                Vector3f d = qs.p() - pt.p();
                Float g = 1 / LengthSquared(d);
                d = d * std::sqrt(g);
                if (qs.IsOnSurface()) g *= AbsDot(qs.ns(), d);
                if (pt.IsOnSurface()) g *= AbsDot(pt.ns(), d);
                L *= g;
                if (L && !Unoccluded(qs.si, pt.si)) L = SampledSpectrum(0);
            }
        }
    }
    if (!L) return L;
    return L * MISWeight(lightVertices, cameraVertices, sampled, s, t);
}

Float BDPTIntegrator::MISWeight(BDPTVertex* lightVertices, BDPTVertex* cameraVertices,
                                BDPTVertex& sampled, int s, int t) const {
    if (s + t == 2) return 1;
    // The ratio of a vertex's reverse to forward density. A density is 0 where the vertex it
    // is sampled from scatters specularly (RandomWalk zeroes it): taken as 1 there (pbrt-v4's
    // remap0; the delta flags keep those strategies out of the sum). A reverse density that is
    // 0 otherwise is a strategy that cannot make the path (a folding BSDF, bsdf.h, scatters
    // between some pairs of directions it samples in one order only) and ends the chain:
    // remapped to 1 it was counted, and a closed cavity of smooth-shaded diffuse walls of
    // albedo 0.8 rendered 0.9915 of B(T).
    auto RevOverFwd = [](const BDPTVertex& v, bool revFromDelta) {
        Float rev = v.pdfRev != 0 || !revFromDelta ? v.pdfRev : 1;
        return rev / (v.pdfFwd != 0 ? v.pdfFwd : 1);
    };

    BDPTVertex* qs = s > 0 ? &lightVertices[s - 1] : nullptr;
    BDPTVertex* pt = t > 0 ? &cameraVertices[t - 1] : nullptr;
    BDPTVertex* qsMinus = s > 1 ? &lightVertices[s - 2] : nullptr;
    BDPTVertex* ptMinus = t > 1 ? &cameraVertices[t - 2] : nullptr;

    // The vertices this strategy changes, restored before returning (pbrt-v4's
    // ScopedAssignment): the sampled end point, the connection's delta flags and reverse
    // densities
    BDPTVertex* replaced = s == 1 ? qs : t == 1 ? pt : nullptr;
    BDPTVertex savedEnd;
    if (replaced) {
        savedEnd = *replaced;
        *replaced = sampled;
    }
    struct Saved {
        bool ptDelta, qsDelta;
        Float ptRev, ptMinusRev, qsRev, qsMinusRev;
    } saved{pt && pt->delta,     qs && qs->delta,
            pt ? pt->pdfRev : 0, ptMinus ? ptMinus->pdfRev : 0,
            qs ? qs->pdfRev : 0, qsMinus ? qsMinus->pdfRev : 0};
    if (pt) pt->delta = false;
    if (qs) qs->delta = false;
    // Reverse densities at the connection and one vertex beyond on each side
    Float ptRev = 0, ptMinusRev = 0, qsRev = 0, qsMinusRev = 0;
    if (pt) ptRev = s > 0 ? PDF(*qs, qsMinus, *pt) : PDFLightOrigin(*pt, *ptMinus);
    if (ptMinus) ptMinusRev = s > 0 ? PDF(*pt, qs, *ptMinus) : PDFLight(*pt, *ptMinus);
    if (qs) qsRev = PDF(*pt, ptMinus, *qs);
    if (qsMinus) qsMinusRev = PDF(*qs, pt, *qsMinus);
    if (pt) pt->pdfRev = ptRev;
    if (ptMinus) ptMinus->pdfRev = ptMinusRev;
    if (qs) qs->pdfRev = qsRev;
    if (qsMinus) qsMinus->pdfRev = qsMinusRev;

    // Other strategies along the camera subpath
    Float sumRi = 0, ri = 1;
    for (int i = t - 1; i > 0; --i) {
        ri *= RevOverFwd(cameraVertices[i], i + 1 < t && cameraVertices[i + 1].delta);
        if (i == 1) ri /= splatScale;
        if (!cameraVertices[i].delta && !cameraVertices[i - 1].delta) sumRi += ri;
    }
    // ... and along the light subpath
    ri = 1;
    for (int i = s - 1; i >= 0; --i) {
        ri *= RevOverFwd(lightVertices[i], i + 1 < s && lightVertices[i + 1].delta);
        bool deltaLightVertex =
            i > 0 ? lightVertices[i - 1].delta : lightVertices[0].IsDeltaLight();
        if (!lightVertices[i].delta && !deltaLightVertex) sumRi += ri;
    }
    // Light tracing from a crop window has splatScale times fewer samples per pixel than the
    // strategies of the pixel's own camera paths (its contribution is scaled up by as much,
    // Connect): the balance heuristic weighs its density by 1 / splatScale. pbrt-v4 (issue 347)
    // divides the other strategies' ratios by splatScale for t = 1 too, which brightens crops
    // (measured: a test box's central crop +47 %, test/render/bdpt_test.cpp); they are
    // multiplied here.
    if (t == 1) sumRi *= splatScale;

    if (pt) {
        pt->delta = saved.ptDelta;
        pt->pdfRev = saved.ptRev;
    }
    if (qs) {
        qs->delta = saved.qsDelta;
        qs->pdfRev = saved.qsRev;
    }
    if (ptMinus) ptMinus->pdfRev = saved.ptMinusRev;
    if (qsMinus) qsMinus->pdfRev = saved.qsMinusRev;
    if (replaced) *replaced = savedEnd;
    return 1 / (1 + sumRi);
}

}  // namespace kiln
