#include "lights/thermal_area_light.h"

#include <cmath>

#include "core/geometry/shape.h"
#include "core/geometry/triangle.h"
#include "lights/area_light_sampling.h"
#include "materials/material.h"
#include "spectral/planck.h"

namespace kiln {

ThermalAreaLight::ThermalAreaLight(const Shape* shape, const Material* material,
                                   FloatTexture temperature, EmissionModel model, Float scale,
                                   const ReflectanceTable* reflectance)
    : shape(shape),
      material(material),
      temperature(temperature),
      model(model),
      scale(scale),
      reflectance(reflectance) {}

Float ThermalAreaLight::Temperature(Point3f p, Normal3f n, Point2f uv) const {
    TextureEvalContext ctx;
    ctx.p = p;
    ctx.n = n;
    ctx.uv = uv;
    // Per-vertex temperatures on triangle meshes need the triangle and barycentrics
    if (const Triangle* tri = shape->Get<Triangle>()) {
        ctx.mesh = tri->GetMesh();
        ctx.triIndex = tri->TriangleIndex();
        ctx.b = tri->Barycentrics(p);
    }
    Float T = temperature.Evaluate(ctx);
    return std::isfinite(T) && T > 0 ? T : 0;
}

// Emissivity 1 - R(w) of the material at the point (Kirchhoff's law)
SampledSpectrum ThermalAreaLight::Emissivity(Point3f p, Normal3f n, Point2f uv, Vector3f w,
                                             const SampledWavelengths& lambda) const {
    if (reflectance) {
        Float cosTheta = AbsDot(Normalize(Vector3f(n)), w);
        return Clamp(SampledSpectrum(1.f) - reflectance->Reflectance(cosTheta, lambda), Float(0),
                     Float(1));
    }
    // Varying material: evaluate its BSDF here, one wavelength set at a time (a dispersive
    // coating keeps only the hero wavelength, so then each wavelength is done separately).
    SampledWavelengths l = lambda;
    BSDF bsdf = EmissionBSDF(*material, p, n, uv, w, l);
    SampledSpectrum R = HemisphericalReflectance(bsdf, w, 16);
    if (l.SecondaryTerminated()) {
        for (int i = 1; i < NSpectrumSamples; ++i) {
            SampledWavelengths li = SampledWavelengths::FromWavelength(lambda[i]);
            BSDF b = EmissionBSDF(*material, p, n, uv, w, li);
            R[i] = HemisphericalReflectance(b, w, 16)[0];
        }
    }
    return Clamp(SampledSpectrum(1.f) - R, Float(0), Float(1));
}

SampledSpectrum ThermalAreaLight::L(Point3f p, Normal3f n, Point2f uv, Vector3f w,
                                    const SampledWavelengths& lambda) const {
    Float T = Temperature(p, n, uv);
    if (T <= 0) return SampledSpectrum(0.f);
    SampledSpectrum B = scale * planck_radiance(lambda, T);
    if (model != EmissionModel::Kirchhoff) return B;
    return B * Emissivity(p, n, uv, w, lambda);
}

std::optional<LightLiSample> ThermalAreaLight::SampleLi(const LightSampleContext& ctx, Point2f u,
                                                        const SampledWavelengths& lambda,
                                                        bool) const {
    return SampleAreaLi(*shape, ctx, u, [&](Point3f p, Normal3f n, Point2f uv, Vector3f w) {
        return L(p, n, uv, w, lambda);
    });
}

Float ThermalAreaLight::PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool) const {
    return AreaPDF_Li(*shape, ctx, wi);
}

Float ThermalAreaLight::Area() const { return shape->Area(); }

SampledSpectrum ThermalAreaLight::Phi(const SampledWavelengths& lambda) const {
    Float area = shape->Area();
    if (!(area > 0)) return SampledSpectrum(0.f);
    // Mean over the surface of B(lambda, T) eps_h(lambda) from a fixed stratified point set;
    // eps_h is the hemispherical emissivity (cosine-weighted mean over directions).
    constexpr int n = 4;
    SampledSpectrum sum(0.f);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            std::optional<ShapeSample> ss = shape->Sample(Point2f((i + 0.5f) / n, (j + 0.5f) / n));
            if (!ss) continue;
            const Interaction& it = ss->intr;
            Float T = Temperature(it.p, it.n, it.uv);
            if (T <= 0) continue;
            SampledSpectrum B = planck_radiance(lambda, T);
            if (model == EmissionModel::Kirchhoff) {
                // Two directions at the Gauss-Legendre nodes of int eps(mu) 2 mu dmu
                Vector3f nn = Normalize(Vector3f(it.n)), t1, t2;
                CoordinateSystem(nn, &t1, &t2);
                SampledSpectrum eps(0.f);
                for (Float mu : {0.355051f, 0.844949f}) {
                    Vector3f w = mu * nn + std::sqrt(1 - mu * mu) * t1;
                    eps += (mu < 0.5f ? 0.363917f : 0.636083f) *
                           Emissivity(it.p, it.n, it.uv, w, lambda);
                }
                B *= eps;
            }
            sum += B;
        }
    return 2 * Pi * area * scale * sum / Float(n * n);
}

}  // namespace kiln
