#include "render/scene.h"

#include <array>
#include <cstdio>

#include "materials/shading_perturbation.h"
#include "thermal/thermal_emission.h"

namespace kiln {

Scene::~Scene() = default;

std::string SceneFeatures::ToString() const {
    auto onOff = [](bool b) { return b ? "on" : "off"; };
    const char* base =
        sensorResponseWavelengths ? "the thermal sensor's response" : "the visible density";
    char wavelengths[128];
    if (wavelengthVisibleShare < 1)
        std::snprintf(wavelengths, sizeof(wavelengths),
                      "%.0f %% by %s, the rest by hot matter's %s", 100 * wavelengthVisibleShare,
                      base, sensorResponseWavelengths ? "spectrum times it" : "spectrum");
    else
        std::snprintf(wavelengths, sizeof(wavelengths), "by %s", base);
    char buf[1600];
    std::snprintf(
        buf, sizeof(buf),
        "thermal emission %s (%d lights, %d emissivity tables in %.2f s%s); texture footprints "
        "at %d of %d materials; pixel loop: AOVs %s, %d wavelength%s, %s; "
        "light sampler %s%s; area lights %s, environment light %s, dispersion %s; shadow rays "
        "cross %d sheet material%s; subsurface materials %d (%d BSSRDF tables in %.3f s); "
        "polarisation %s; media %d (%d emissive, %d thermal, %d sampled as lights in %.3f s, "
        "%d glass windows onto hot media%s, %d uniform ones integrated exactly along rays; "
        "absorption %s, lights sampled at %s on camera rays and after specular bounces); "
        "wavelengths %s, "
        "camera rays %s at smooth dielectrics; integrator %s%s%s%s",
        onOff(thermalEmission), thermalLights, emissivityTables, emissivitySeconds,
        varyingTemperatures ? ", varying temperatures" : "", footprintMaterials, materials,
        onOff(aovs), singleWavelength ? 1 : NSpectrumSamples, singleWavelength ? "" : "s",
        fixedPixelCenter ? "fixed pixel positions"
        : spreadSamples  ? "samples spread over the pixels within the filter's radius"
                         : "pixel positions importance-sampled from the filter",
        bidirectional                               ? "power (bdpt)"
        : lightSelection == LightSelection::BVH     ? "bvh"
        : lightSelection == LightSelection::Power   ? "power"
        : lightSelection == LightSelection::Uniform ? "uniform"
                                                    : "area",
        skipsUniformEnvironment ? " (leaving out the uniform environment BSDF sampling covers)"
                                : "",
        onOff(areaLights), onOff(environmentLight), onOff(dispersion), sheets,
        sheets == 1 ? "" : "s", subsurface, bssrdfTables, bssrdfSeconds,
        polarized ? "on (Stokes vectors, Mueller matrices)" : "off", media, emissiveMedia,
        thermalMedia, sampledMedia, mediumSamplerSeconds, glassWindows,
        glassWindowsAgainstEnvironment ? " (weighed against the environment's radiance)" : "",
        exactEmissionMedia, weightAbsorption ? "weighting paths" : "ending paths",
        collisionLightSampling ? "collisions" : "scatterings", wavelengths,
        splitDielectrics ? "split" : "choose a way",
        ambientOcclusion ? "ambientocclusion"
        : bidirectional  ? "bdpt"
        : volumetric     ? "volpath"
                         : "path",
        genericVolumes ? "; generic volpath (--generic)" : "",
        genericFootprints ? "; generic footprints (--generic)" : "",
        genericAOVs ? "; generic AOVs (--generic)" : "");
    return buf;
}

// SceneShader
BSDF SceneShader::GetBSDF(SurfaceInteraction& si, SampledWavelengths& lambda) const {
    if (!si.material) return {};
    // Screen-space footprint for texture filtering, where a texture uses it
    if (footprintsAlways || si.material->UsesFootprint() ||
        (si.thermal && si.thermal->UsesFootprint())) {
        camera->Approximate_dp_dxy(si.p, si.n, si.time, samplesPerPixel, &si.dpdx, &si.dpdy);
        // Solve for the uv derivatives from dp/dx and dp/dy (pbrt-v4's least squares)
        Float ata00 = Dot(si.dpdu, si.dpdu), ata01 = Dot(si.dpdu, si.dpdv),
              ata11 = Dot(si.dpdv, si.dpdv);
        Float invDet = 1 / (ata00 * ata11 - ata01 * ata01);
        invDet = std::isfinite(invDet) ? invDet : 0.f;
        Float atb0x = Dot(si.dpdu, si.dpdx), atb1x = Dot(si.dpdv, si.dpdx);
        Float atb0y = Dot(si.dpdu, si.dpdy), atb1y = Dot(si.dpdv, si.dpdy);
        auto finiteOr0 = [](Float v) { return std::isfinite(v) ? Clamp(v, -1e8f, 1e8f) : 0.f; };
        si.dudx = finiteOr0((ata11 * atb0x - ata01 * atb1x) * invDet);
        si.dvdx = finiteOr0((ata00 * atb1x - ata01 * atb0x) * invDet);
        si.dudy = finiteOr0((ata11 * atb0y - ata01 * atb1y) * invDet);
        si.dvdy = finiteOr0((ata00 * atb1y - ata01 * atb0y) * invDet);
    }
    MaterialEvalContext ctx(si);
    const Material* material = si.material->ChooseMaterial(ctx);
    si.material = material;
    if (!material || material->IsInterface()) return {};
    // Optical constants that follow the temperature: the one the surface emits at
    if (si.thermal && material->UsesTemperature()) ctx.temperature = si.thermal->Temperature(si);
    // Bump or normal map: the shading frame the BSDF (and emission) is built in (only the
    // shading frame changes; the geometric normal stays)
    if (const ShadingPerturbation& p = material->Perturbation(); p.Any()) {
        ApplyShadingPerturbation(p, si);
        ctx.ns = si.shading.n;
        ctx.dpdus = si.shading.dpdu;
    }
    return material->GetBSDF(ctx, lambda);
}

// Scene
VisibleSurface Scene::MakeVisibleSurface(const SurfaceInteraction& isect, const BSDF& bsdf,
                                         const SampledWavelengths& lambda) const {
    (void)lambda;
    VisibleSurface vs;
    vs.set = true;
    vs.p = isect.p;
    // Normals on the side the ray came from, as pbrt-v4's VisibleSurface
    vs.n = FaceForward(isect.n, isect.wo);
    vs.ns = FaceForward(isect.shading.n, isect.wo);
    vs.uv = isect.uv;
    // dp/dx and dp/dy: set by the pixel loop from the camera ray's differentials
    // (SetCameraDifferentials)
    // Albedo from a fixed stratified sample set, as pbrt-v4's VisibleSurface
    constexpr int n = 16;
    std::array<Float, n> uc;
    std::array<Point2f, n> u2;
    for (int i = 0; i < n; ++i) {
        uc[i] = (i + 0.5f) / n;
        u2[i] = Point2f((i % 4 + 0.5f) / 4, (i / 4 + 0.5f) / 4);
    }
    vs.albedo = bsdf.rho(isect.wo, uc, u2);
    return vs;
}

}  // namespace kiln
