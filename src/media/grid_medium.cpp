#include "media/grid_medium.h"

#include <algorithm>
#include <cmath>

#include "media/vdb_file.h"
#include "spectral/cie.h"
#include "spectral/planck.h"
#include "thermal/thermal_properties.h"

namespace kiln {

// GridMedium
GridMedium::GridMedium(const Bounds3f& bounds, const Transform& renderFromMedium,
                       const MediumCoefficients& c, SampledGrid<Float> density,
                       MediumEmission emission, std::optional<Bounds3f> sampleBounds)
    : bounds(bounds),
      sampleBounds(sampleBounds.value_or(bounds)),
      renderFromMedium(renderFromMedium),
      sigma_a(c.sigma_a),
      sigma_s(c.sigma_s),
      scale(c.scale),
      g(c.g),
      density(std::move(density)),
      emission(std::move(emission)),
      majorants(bounds, 16) {
    // Majorant voxels are in the unit cube of bounds; the samples' lookups in that of
    // sampleBounds
    majorants.Fill([&](const Bounds3f& b) {
        if (this->sampleBounds.pMin == this->bounds.pMin &&
            this->sampleBounds.pMax == this->bounds.pMax)
            return this->density.MaxValue(b, [](Float d) { return d; });
        Vector3f d = bounds.Diagonal();
        auto medium = [&](Point3f u) {
            return Point3f(bounds.pMin.x + u.x * d.x, bounds.pMin.y + u.y * d.y,
                           bounds.pMin.z + u.z * d.z);
        };
        Bounds3f s(UnitPoint(this->sampleBounds, medium(b.pMin)),
                   UnitPoint(this->sampleBounds, medium(b.pMax)));
        return this->density.MaxValue(s, [](Float d) { return d; });
    });
}

Point3f GridMedium::UnitPoint(const Bounds3f& box, Point3f p) {
    Vector3f d = box.Diagonal();
    return Point3f((p.x - box.pMin.x) / d.x, (p.y - box.pMin.y) / d.y, (p.z - box.pMin.z) / d.z);
}

MediumProperties GridMedium::SamplePoint(Point3f p, const SampledWavelengths& lambda) const {
    Point3f pMedium = renderFromMedium.ApplyInverse(p);
    // The medium ends at its box (the interpolation would reach half a voxel beyond)
    if (!InsideUnitCube(UnitPoint(bounds, pMedium))) return {};
    Point3f pUnit = UnitPoint(sampleBounds, pMedium);
    Float d = scale * density.Lookup(pUnit);
    MediumProperties mp{sigma_a.Sample(lambda) * d, sigma_s.Sample(lambda) * d, g, {}};
    emission.Apply(mp, p, pUnit, lambda);
    return mp;
}

MajorantIterator GridMedium::SampleRay(const Ray& ray, Float tMax,
                                       const SampledWavelengths& lambda) const {
    std::optional<MediumRaySegment> r = RayInMedium(renderFromMedium, bounds, ray, tMax);
    if (!r) return {};
    SampledSpectrum sigma_t = (sigma_a.Sample(lambda) + sigma_s.Sample(lambda)) * scale;
    return MajorantIterator(r->o, r->d, r->tMin, r->tMax, &majorants, sigma_t);
}

// Creation
MediumEmission ReadGridEmission(const TextureParameterDictionary& params,
                                SampledGrid<Float> temperature, int nx, int ny, int nz,
                                std::optional<EmissionModel> modelOverride, ObjectArena& arena,
                                bool constantLeScale) {
    std::optional<Spectrum> Le = ReadMediumLe(params);
    if (Le && !temperature.Empty())
        throw SceneError(params.Loc("Le"), "both \"Le\" and \"temperature\" values were provided",
                         "Le");
    // "Lescale": one value, or one per voxel
    std::vector<Float> LeScaleValues = params.GetFloatArray("Lescale");
    SampledGrid<Float> LeScale;
    Float LeScaleConstant = 1;
    size_t n = size_t(nx) * size_t(ny) * size_t(nz);
    // The largest "Lescale", constant or per voxel, for the emission's limit
    double LeScaleMax = LeScaleValues.empty() ? 1 : 0;
    for (Float s : LeScaleValues) LeScaleMax = std::max(LeScaleMax, double(s));
    if (LeScaleValues.size() == 1) {
        LeScaleConstant = LeScaleValues[0];
    } else if (!LeScaleValues.empty()) {
        if (LeScaleValues.size() != n)
            throw SceneError(
                params.Loc("Lescale"),
                "expected one \"Lescale\" value or one per voxel (" + std::to_string(n) + ")",
                std::to_string(LeScaleValues.size()));
        LeScale = SampledGrid<Float>(std::move(LeScaleValues), nx, ny, nz);
    }
    Float offset =
        params.GetOneFloat("temperatureoffset", params.GetOneFloat("temperaturecutoff", 0));
    Float tScale = params.GetOneFloat("temperaturescale", 1);
    if (!temperature.Empty()) {
        if (params.Has("emission")) {
            // kiln: kelvin, thermal emission in absolute units, up to kMaxRenderTemperature
            Float hottest = temperature.MaxValue(Bounds3f(Point3f(0, 0, 0), Point3f(1, 1, 1)),
                                                 [&](Float T) { return (T - offset) * tScale; });
            if (!(hottest <= kMaxRenderTemperature))
                throw SceneError(params.Loc("temperature"),
                                 "grid temperatures must be kelvin up to 1e27 (after "
                                 "\"temperatureoffset\" and \"temperaturescale\")",
                                 FormatKelvin(hottest));
            ThermalProperties t = ReadThermalProperties(params, true, arena);
            EmissionModel model =
                modelOverride ? *modelOverride : t.model.value_or(EmissionModel::Kirchhoff);
            return MediumEmission::Thermal(std::move(temperature), offset, tScale, model);
        }
        // pbrt-v4's blackbody peaks at 1 (times CIE_Y_integral, medium_emission.h)
        CheckMediumEmissionPeak(LeScaleMax * CIE_Y_integral, params);
        if (LeScale.Empty() && constantLeScale)
            return MediumEmission::NormalizedBlackbody(std::move(temperature), offset, tScale, {},
                                                       LeScaleConstant);
        if (LeScale.Empty()) LeScale = SampledGrid<Float>({LeScaleConstant}, 1, 1, 1);
        return MediumEmission::NormalizedBlackbody(std::move(temperature), offset, tScale,
                                                   std::move(LeScale));
    }
    if (std::optional<MediumEmission> thermal =
            ReadMediumThermalEmission(params, modelOverride, arena)) {
        if (Le)
            throw SceneError(params.Loc("temperature"),
                             "a medium glows either by \"Le\" or by its \"temperature\", not both",
                             "temperature");
        return *thermal;
    }
    if (!Le) return {};
    Spectrum normalized = NormalizedLe(*Le, LeScaleConstant);
    CheckMediumEmissionPeak(double(normalized.MaxValue()) * (LeScale.Empty() ? 1 : LeScaleMax),
                            params);
    return MediumEmission::Radiance(std::move(normalized), std::move(LeScale));
}

GridMedium* GridMedium::Create(const TextureParameterDictionary& params,
                               const Transform& renderFromMedium,
                               std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                               ObjectArena& arena, Diagnostics& diag) {
    std::vector<Float> density = params.GetFloatArray("density");
    if (density.empty())
        throw SceneError(loc, "no \"density\" values provided for grid medium", "uniformgrid");
    std::array<int, 3> res = ReadGridResolution(params, density.size(), "density", loc);
    int nx = res[0], ny = res[1], nz = res[2];
    for (Float d : density)
        if (!(d >= 0) || !std::isfinite(d))
            throw SceneError(params.Loc("density"), "grid densities must be finite and >= 0",
                             std::to_string(d));
    // "float temperature": one value per voxel is a grid (pbrt-v4's, or kiln's kelvin with
    // "emission"); one value for several voxels is kiln's constant temperature
    SampledGrid<Float> temperature;
    if (params.TypeOf("temperature") == "float") {
        std::vector<Float> t = params.GetFloatArray("temperature");
        bool grid = t.size() == density.size() && (t.size() > 1 || !params.Has("emission"));
        if (!grid && t.size() != 1)
            throw SceneError(params.Loc("temperature"),
                             "different number of samples (" + std::to_string(density.size()) +
                                 " vs " + std::to_string(t.size()) +
                                 ") provided for \"density\" and \"temperature\"",
                             "temperature");
        if (grid) temperature = SampledGrid<Float>(std::move(t), nx, ny, nz);
    }
    MediumCoefficients c = ReadMediumCoefficients(params, loc, diag);
    CheckExtinction(c, *std::max_element(density.begin(), density.end()), params, loc);
    MediumEmission emission =
        ReadGridEmission(params, std::move(temperature), nx, ny, nz, modelOverride, arena);
    return arena.New<GridMedium>(ReadGridBounds(params, loc), renderFromMedium, c,
                                 SampledGrid<Float>(std::move(density), nx, ny, nz),
                                 std::move(emission));
}

GridMedium* GridMedium::CreateFromVDB(const TextureParameterDictionary& params,
                                      const Transform& renderFromMedium,
                                      std::optional<EmissionModel> modelOverride,
                                      const FileLoc& loc, ObjectArena& arena, Diagnostics& diag) {
    std::string filename = params.GetOneFilename("filename", "");
    if (filename.empty()) throw SceneError(loc, "a volume medium needs a \"filename\"", "filename");
    VDBVolume v = ReadVDBVolume(filename, params.GetOneString("gridname", "density"),
                                params.GetOneString("temperaturename", "temperature"),
                                params.Loc("filename"), size_t(1) << 30, &arena.Budget());
    MediumCoefficients c = ReadMediumCoefficients(params, loc, diag);
    CheckExtinction(
        c,
        v.density.MaxValue(Bounds3f(Point3f(0, 0, 0), Point3f(1, 1, 1)), [](Float d) { return d; }),
        params, loc);
    int nx = v.density.XSize(), ny = v.density.YSize(), nz = v.density.ZSize();
    MediumEmission emission =
        ReadGridEmission(params, std::move(v.temperature), nx, ny, nz, modelOverride, arena, true);
    return arena.New<GridMedium>(v.indexBounds, renderFromMedium * v.mediumFromIndex, c,
                                 std::move(v.density), std::move(emission), v.sampleBounds);
}

}  // namespace kiln
