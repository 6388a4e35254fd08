#include "lights/thermal_area_light.h"

#include <cmath>
#include <vector>

#include "core/geometry/shape.h"
#include "spectral/planck.h"

namespace kiln {

namespace {

// Grid sizes over the parameterisation: a probe for triangles (power estimate and
// concentration test), and the sampling distribution
constexpr int kTriangleProbe = 2, kQuadricGrid = 32, kTriangleGrid = 16;

// The concentration of power (mean of squares over square of mean over the cells) from which
// sampling by power beats the shape's own sampling: a sphere's cone sampling never wastes
// samples on its far side (worth about a factor 2), spherical triangles beat area sampling
// nearby; disks, cylinders and bilinear patches sample by area anyway.
double MinConcentration(const Shape& shape) {
    if (shape.GetIf<Sphere>()) return 2;
    if (shape.GetIf<Triangle>()) return 1.5;
    return 1.25;
}

// Integral of B(lambda, T) over the band, W m^-2 sr^-1 (as BandExitance integrates it)
Float BandBlackbody(Float T, const SpectralRange& band) {
    return Float(std::min(planck_band_radiance(band.min, band.max, T),
                          double(std::numeric_limits<Float>::max())));
}

}  // namespace

SurfaceInteraction ThermalAreaLight::InteractionAt(Point3f p, Float time, Vector3f wo) const {
    SurfaceInteraction si = shape->InteractionAt(p, time, wo);
    si.material = material;
    si.thermal = emission;  // as a ray hit there reports it (the shader reads both)
    return si;
}

ThermalAreaLight::ThermalAreaLight(const Shape* shape, const Material* material,
                                   const ThermalEmission* emission, const BSDFAt& bsdfAt,
                                   std::optional<Uniform> uniform, bool powerSampling,
                                   const AlphaMask* alpha)
    : shape(shape),
      alpha(alpha),
      material(material),
      emission(emission),
      powerSampling(powerSampling) {
    area = shape->Area();
    if (!(area > 0)) return;
    if (uniform) {
        // The caller's exitance holds everywhere: sample by solid angle
        bandPower = uniform->exitance * area;
        meanTemperature = uniform->temperature;
        return;
    }
    EstimatePower(bsdfAt);
}

void ThermalAreaLight::EstimatePower(const BSDFAt& bsdfAt) {
    distribution.reset();
    bandPower = meanTemperature = 0;
    if (!(area > 0)) return;
    // The exitance M (W m^-2) at the centres of an n x n grid over the parameterisation; the
    // power is the integral of M dA = integral over u of M / q (q the area density of u), and
    // the cell values M / q make the sampling distribution
    struct Grid {
        int n;
        std::vector<Float> cells;
        double power = 0, power2 = 0, weightedT = 0;
        // How concentrated the power is: mean(w^2) / mean(w)^2 over the cells (1: uniform)
        double Concentration() const { return power > 0 ? power2 * (n * n) / (power * power) : 1; }
    };
    auto evaluate = [&](int n) {
        Grid g{n, std::vector<Float>(size_t(n) * n, 0.f)};
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                std::optional<ShapeSample> ss =
                    shape->SampleParametric(Point2f((i + 0.5f) / n, (j + 0.5f) / n));
                if (!ss || !(ss->pdf > 0)) continue;
                SurfaceInteraction si = InteractionAt(ss->intr.p, 0, Vector3f(ss->intr.n));
                Float T = emission->Temperature(si), M = 0;
                if (T > 0) {
                    SampledWavelengths lambda = SampledWavelengths::FromWavelength(550);
                    BSDF bsdf = bsdfAt(si, lambda);
                    M = emission->BandExitance(si, bsdf);
                }
                Float w = M / ss->pdf;
                g.cells[size_t(j) * n + i] = w;
                g.power += w;
                g.power2 += double(w) * w;
                g.weightedT += double(w) * T;
            }
        return g;
    };
    // Triangles: a 2 x 2 probe first (meshes have many), the full grid only where the power
    // is concentrated and the mesh small; other shapes: the full grid. Sampling by power pays
    // where the power is concentrated (a hot spot, a hot side); otherwise the shape's own
    // solid-angle sampling is better (a sphere's cone never picks its far side).
    const Triangle* tri = shape->GetIf<Triangle>();
    bool mayDistribute =
        powerSampling && (!tri || tri->GetMesh()->NumTriangles() <= kMaxDistributionTriangles);
    Grid g = evaluate(tri || !mayDistribute ? kTriangleProbe : kQuadricGrid);
    double minConcentration = MinConcentration(*shape);
    if (tri && mayDistribute && g.Concentration() >= minConcentration) g = evaluate(kTriangleGrid);
    if (mayDistribute && g.power > 0 && g.Concentration() >= minConcentration)
        distribution.emplace(g.cells, g.n, g.n);
    bandPower = Float(g.power / (g.n * g.n));
    meanTemperature = g.power > 0 ? Float(g.weightedT / g.power) : 0;
}

SampledSpectrum ThermalAreaLight::Phi(const SampledWavelengths& lambda) const {
    if (!(bandPower > 0) || !(meanTemperature > 0)) return SampledSpectrum(0.f);
    return bandPower / BandBlackbody(meanTemperature, emission->Band()) *
           planck_radiance(lambda, meanTemperature);
}

std::optional<Float> ThermalAreaLight::ParametricPDF(Point3f p) const {
    Point2f u = shape->InvertParametric(p);
    std::optional<ShapeSample> ss = shape->SampleParametric(u);
    if (!ss) return std::nullopt;
    return distribution->PDF(u) * ss->pdf;
}

std::optional<LightLiSample> ThermalAreaLight::SampleLi(const LightSampleContext& ctx, Point2f u,
                                                        const SampledWavelengths&, bool) const {
    // A point on the shape: by power over its parameterisation, or by solid angle
    Point3f p;
    Normal3f n;
    Float pdf;
    if (distribution) {
        Float pdfU;
        Point2f up = distribution->Sample(u, &pdfU);
        std::optional<ShapeSample> ss = shape->SampleParametric(up);
        if (!ss || !(pdfU > 0)) return {};
        p = ss->intr.p;
        n = ss->intr.n;
        Vector3f d = p - ctx.p;
        Float dist2 = LengthSquared(d), cosLight = AbsDot(n, Normalize(d));
        if (dist2 == 0 || cosLight == 0) return {};
        pdf = pdfU * ss->pdf * dist2 / cosLight;
    } else {
        std::optional<ShapeSample> ss =
            shape->Sample(ShapeSampleContext(ctx.p, ctx.n, ctx.ns, 0), u);
        if (!ss) return {};
        p = ss->intr.p;
        n = ss->intr.n;
        pdf = ss->pdf;
    }
    if (!(pdf > 0) || !std::isfinite(pdf) || LengthSquared(p - ctx.p) == 0) return {};
    LightLiSample ls;
    ls.wi = Normalize(p - ctx.p);
    ls.pdf = pdf;
    ls.pLight = Interaction(p, n, Point2f());
    ls.deferredL = true;
    return ls;
}

std::optional<ShapeSample> ThermalAreaLight::SamplePosition(Point2f u) const {
    std::optional<ShapeSample> ss;
    if (distribution) {
        Float pdfU = 0;
        Point2f up = distribution->Sample(u, &pdfU);
        ss = shape->SampleParametric(up);
        if (ss) ss->pdf *= pdfU;
    } else {
        ss = shape->Sample(u);
    }
    if (!ss || !(ss->pdf > 0) || !std::isfinite(ss->pdf)) return {};
    return ss;
}

LightLePDF ThermalAreaLight::PDF_Le(const Interaction& intr, Vector3f w) const {
    Float pdfPos = 0;
    if (distribution) {
        std::optional<Float> p = ParametricPDF(intr.p);
        pdfPos = p ? *p : 0;
    } else {
        pdfPos = shape->PDF(intr);
    }
    return {std::isfinite(pdfPos) ? pdfPos : 0, EmissionDirectionPDF(intr.n, TwoSided(), w)};
}

Float ThermalAreaLight::PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool) const {
    ShapeSampleContext shapeCtx(ctx.p, ctx.n, ctx.ns, 0);
    if (!distribution) {
        Float pdf = shape->PDF(shapeCtx, wi);
        return std::isfinite(pdf) ? pdf : 0;
    }
    std::optional<ShapeIntersection> isect = shape->Intersect(shapeCtx.SpawnRay(wi));
    if (!isect) return 0;
    std::optional<Float> pdfArea = ParametricPDF(isect->intr.p);
    Float cosLight = AbsDot(isect->intr.n, Normalize(wi));
    if (!pdfArea || cosLight == 0) return 0;
    Float pdf = *pdfArea * DistanceSquared(ctx.p, isect->intr.p) / cosLight;
    return std::isfinite(pdf) ? pdf : 0;
}

}  // namespace kiln
