#include "media/rgb_grid_medium.h"

#include <algorithm>

namespace kiln {

RGBGridMedium::RGBGridMedium(const Bounds3f& bounds, const Transform& renderFromMedium, Float g,
                             SampledGrid<Spectrum> sigma_a, SampledGrid<Spectrum> sigma_s,
                             Float scale, SampledGrid<Spectrum> Le, Float LeScale,
                             MediumEmission thermal)
    : bounds(bounds),
      renderFromMedium(renderFromMedium),
      g(g),
      sigma_a(std::move(sigma_a)),
      sigma_s(std::move(sigma_s)),
      Le(std::move(Le)),
      scale(scale),
      LeScale(LeScale),
      thermal(std::move(thermal)),
      majorants(bounds, 16) {
    auto max = [](const Spectrum& s) { return s.MaxValue(); };
    majorants.Fill([&](const Bounds3f& b) {
        Float a = this->sigma_a.Empty() ? 1 : this->sigma_a.MaxValue(b, max);
        Float s = this->sigma_s.Empty() ? 1 : this->sigma_s.MaxValue(b, max);
        return this->scale * (a + s);
    });
}

MediumProperties RGBGridMedium::SamplePoint(Point3f p, const SampledWavelengths& lambda) const {
    Point3f pm = renderFromMedium.ApplyInverse(p);
    Vector3f d = bounds.Diagonal();
    Point3f pUnit((pm.x - bounds.pMin.x) / d.x, (pm.y - bounds.pMin.y) / d.y,
                  (pm.z - bounds.pMin.z) / d.z);
    if (!InsideUnitCube(pUnit)) return {};
    auto sample = [&](const Spectrum& s) { return s.Sample(lambda); };
    MediumProperties mp;
    mp.sigma_a = scale * (sigma_a.Empty() ? SampledSpectrum(1.f) : sigma_a.Lookup(pUnit, sample));
    mp.sigma_s = scale * (sigma_s.Empty() ? SampledSpectrum(1.f) : sigma_s.Lookup(pUnit, sample));
    mp.g = g;
    if (!Le.Empty() && LeScale > 0)
        mp.emission = mp.sigma_a * (LeScale * Le.Lookup(pUnit, sample));
    else
        thermal.Apply(mp, p, pUnit, lambda);
    return mp;
}

MajorantIterator RGBGridMedium::SampleRay(const Ray& ray, Float tMax,
                                          const SampledWavelengths&) const {
    std::optional<MediumRaySegment> r = RayInMedium(renderFromMedium, bounds, ray, tMax);
    if (!r) return {};
    return MajorantIterator(r->o, r->d, r->tMin, r->tMax, &majorants, SampledSpectrum(1.f));
}

RGBGridMedium* RGBGridMedium::Create(const TextureParameterDictionary& params,
                                     const Transform& renderFromMedium,
                                     std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                                     ObjectArena& arena, Diagnostics&) {
    const ParameterDictionary& dict = params.Dict();
    std::vector<Spectrum> sa = dict.GetSpectrumArray("sigma_a", SpectrumType::Unbounded);
    std::vector<Spectrum> ss = dict.GetSpectrumArray("sigma_s", SpectrumType::Unbounded);
    std::vector<Spectrum> le = dict.GetSpectrumArray("Le", SpectrumType::Illuminant);
    if (sa.empty() && ss.empty())
        throw SceneError(loc, "RGB grid requires \"sigma_a\" and/or \"sigma_s\" values", "rgbgrid");
    size_t n = sa.empty() ? ss.size() : sa.size();
    if (!sa.empty() && !ss.empty() && sa.size() != ss.size())
        throw SceneError(params.Loc("sigma_s"),
                         "different number of samples (" + std::to_string(sa.size()) + " vs " +
                             std::to_string(ss.size()) + ") for \"sigma_a\" and \"sigma_s\"",
                         "sigma_s");
    if (!le.empty() && sa.empty())
        throw SceneError(params.Loc("Le"), "RGB grid requires \"sigma_a\" if \"Le\" is given",
                         "Le");
    if (!le.empty() && le.size() != n)
        throw SceneError(params.Loc("Le"), "expected " + std::to_string(n) + " \"Le\" values",
                         std::to_string(le.size()));
    std::array<int, 3> res = ReadGridResolution(params, n, "RGB", loc);
    int nx = res[0], ny = res[1], nz = res[2];
    Bounds3f bounds = ReadGridBounds(params, loc);
    Float LeScale = params.GetOneFloat("Lescale", 1);
    Float g = ReadHGAsymmetry(params);
    Float scale = ReadCoefficientScale(params, loc);
    std::optional<MediumEmission> thermal = ReadMediumThermalEmission(params, modelOverride, arena);
    if (thermal && !le.empty())
        throw SceneError(params.Loc("temperature"),
                         "a medium glows either by \"Le\" or by its \"temperature\", not both",
                         "temperature");
    double sigmaMax = 0;
    for (size_t i = 0; i < n; ++i)
        sigmaMax = std::max(sigmaMax, (sa.empty() ? 1 : double(sa[i].MaxValue())) +
                                          (ss.empty() ? 1 : double(ss[i].MaxValue())));
    CheckExtinction(sigmaMax * scale, params, loc);
    double LePeak = 0;
    for (const Spectrum& s : le) LePeak = std::max(LePeak, double(s.MaxValue()));
    if (!le.empty()) CheckMediumEmissionPeak(LePeak * LeScale, params);
    auto grid = [&](std::vector<Spectrum> v) {
        return v.empty() ? SampledGrid<Spectrum>()
                         : SampledGrid<Spectrum>(std::move(v), nx, ny, nz);
    };
    return arena.New<RGBGridMedium>(bounds, renderFromMedium, g, grid(std::move(sa)),
                                    grid(std::move(ss)), scale, grid(std::move(le)), LeScale,
                                    thermal ? std::move(*thermal) : MediumEmission());
}

}  // namespace kiln
