#include "render/medium_emission_sampler.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "base/rng.h"

namespace kiln {

MediumEmissionSampler::MediumEmissionSampler(std::span<const Medium> media,
                                             std::span<const Region> regions)
    : regions(regions.begin(), regions.end()), emitterOfMedium(media.size(), -1) {
    for (const Region& r : regions) {
        if (r.medium < 0 || size_t(r.medium) >= media.size() || r.bounds.IsEmpty() ||
            !InRenderRange(r.bounds) || emitterOfMedium[size_t(r.medium)] >= 0)
            continue;
        // A grid of cells near cubes over the region, if it has a volume
        Vector3f d = r.bounds.Diagonal();
        if (!(d.x > 0 && d.y > 0 && d.z > 0) || !std::isfinite(d.x * d.y * d.z)) continue;
        Float longest = std::max({d.x, d.y, d.z});
        Grid g{r.medium, r.bounds, {0, 0, 0}, 0, {}, 0};
        for (int a = 0; a < 3; ++a)
            g.res[a] = std::clamp(int(std::ceil(kMaxCells * d[a] / longest)), 1, kMaxCells);
        g.cellVolume = (d.x / g.res[0]) * (d.y / g.res[1]) * (d.z / g.res[2]);
        if (!(g.cellVolume > 0)) continue;

        // Each cell's emission over the visible band (W m^-3 sr^-1), from stratified points
        const Medium& medium = media[size_t(r.medium)];
        int nx = g.res[0], ny = g.res[1], nz = g.res[2];
        size_t n = size_t(nx) * ny * nz;
        std::vector<Float> emission(n, 0);
        uint64_t seed = grids.size();
        tbb::parallel_for(size_t(0), n, [&](size_t c) {
            int x = int(c % size_t(nx)), y = int(c / size_t(nx) % size_t(ny)),
                z = int(c / (size_t(nx) * ny));
            RNG rng(Hash(seed, c));
            double sum = 0;
            for (int k = 0; k < kPointsPerCell; ++k) {
                // 2 x 2 x 2 strata of the cell, jittered
                Float u[3] = {((k & 1) + rng.UniformFloat()) / 2,
                              ((k >> 1 & 1) + rng.UniformFloat()) / 2,
                              ((k >> 2 & 1) + rng.UniformFloat()) / 2};
                Point3f p(g.bounds.pMin.x + d.x * (x + u[0]) / nx,
                          g.bounds.pMin.y + d.y * (y + u[1]) / ny,
                          g.bounds.pMin.z + d.z * (z + u[2]) / nz);
                // Four of 32 stratified wavelengths over 360-830 nm
                SampledWavelengths lambda = SampledWavelengths::SampleUniform(
                    (k + rng.UniformFloat()) / (kPointsPerCell * NSpectrumSamples));
                MediumProperties mp = medium.SamplePoint(p, lambda);
                Float e = SafeDiv(mp.emission, lambda.PDF()).Average();
                if (std::isfinite(e) && e > 0) sum += e;
            }
            emission[c] = Float(sum / kPointsPerCell);
        });

        // Cells by emission with a uniform share (uniform if no emission was found)
        double sum = 0;
        for (Float e : emission) sum += double(e);
        std::vector<Float> mass(n);
        for (size_t c = 0; c < n; ++c)
            mass[c] =
                sum > 0 ? Float((1 - kUniformShare) * emission[c] / sum + kUniformShare / double(n))
                        : Float(1.0 / double(n));
        g.cells = AliasTable(mass);
        g.bounds.BoundingSphere(&g.center, &g.radius);
        g.power = 4 * Pi * sum * g.cellVolume;
        emitterOfMedium[size_t(r.medium)] = int(grids.size());
        grids.push_back(std::move(g));
    }
    // Emitters by power, uniformly if none was found
    std::vector<Float> power;
    for (const Grid& g : grids) power.push_back(Float(g.power));
    bool any = std::any_of(power.begin(), power.end(), [](Float p) { return p > 0; });
    if (!any) std::fill(power.begin(), power.end(), Float(1));
    if (!power.empty()) emitters = AliasTable(power);
}

int MediumEmissionSampler::CellOf(const Grid& g, Point3f p) {
    Vector3f d = g.bounds.Diagonal();
    int i[3];
    for (int a = 0; a < 3; ++a)
        i[a] = std::clamp(int((p[a] - g.bounds.pMin[a]) / d[a] * g.res[a]), 0, g.res[a] - 1);
    return i[0] + g.res[0] * (i[1] + g.res[1] * i[2]);
}

Float MediumEmissionSampler::KeepProbability(int emitter, Point3f from) const {
    const Grid& g = grids[size_t(emitter)];
    Float d2 = DistanceSquared(from, g.center), r2 = Sqr(g.radius);
    Float solidAngle = d2 <= r2 ? 4 * Pi : 2 * Pi * (1 - SafeSqrt(1 - r2 / d2));
    return solidAngle > kSolidAngleBudget ? kSolidAngleBudget / solidAngle : 1;
}

std::optional<MediumEmissionSampler::PointSample> MediumEmissionSampler::Sample(Point3f from,
                                                                                Float u,
                                                                                Point3f u3) const {
    if (grids.empty()) return std::nullopt;
    Float pEmitter, pmf, uKeep;
    int emitter = emitters.Sample(u, &pEmitter, &uKeep);
    Float keep = KeepProbability(emitter, from);
    if (uKeep >= keep) return std::nullopt;
    const Grid& g = grids[size_t(emitter)];
    int c = g.cells.Sample(std::min(uKeep / keep, OneMinusEpsilon), &pmf);
    if (pmf == 0 || pEmitter == 0) return std::nullopt;
    int x = c % g.res[0], y = c / g.res[0] % g.res[1], z = c / (g.res[0] * g.res[1]);
    Vector3f d = g.bounds.Diagonal();
    Point3f p(g.bounds.pMin.x + d.x * (x + u3.x) / g.res[0],
              g.bounds.pMin.y + d.y * (y + u3.y) / g.res[1],
              g.bounds.pMin.z + d.z * (z + u3.z) / g.res[2]);
    // The density PDF reports at p (that of the cell p rounds into)
    Float pdf = pEmitter * keep * g.cells.PMF(CellOf(g, p)) / g.cellVolume;
    if (!(pdf > 0)) return std::nullopt;
    return PointSample{emitter, p, pdf};
}

Float MediumEmissionSampler::PDF(Point3f from, int emitter, Point3f p) const {
    if (emitter < 0 || emitter >= Emitters()) return 0;
    const Grid& g = grids[size_t(emitter)];
    for (int a = 0; a < 3; ++a)
        if (!(p[a] >= g.bounds.pMin[a] && p[a] <= g.bounds.pMax[a])) return 0;
    return emitters.PMF(emitter) * KeepProbability(emitter, from) * g.cells.PMF(CellOf(g, p)) /
           g.cellVolume;
}

}  // namespace kiln
