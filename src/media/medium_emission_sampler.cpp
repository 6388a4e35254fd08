#include "media/medium_emission_sampler.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "base/rng.h"

namespace kiln {

MediumEmissionSampler::MediumEmissionSampler(std::span<const Medium> media,
                                             std::span<const Region> regions)
    : regions(regions.begin(), regions.end()), gridOfMedium(media.size(), -1) {
    // A grid of cells over each region with a volume, cells near cubes
    size_t cellCount = 0;
    for (const Region& r : regions) {
        if (r.medium < 0 || size_t(r.medium) >= media.size() || r.bounds.IsEmpty() ||
            !InRenderRange(r.bounds) || gridOfMedium[size_t(r.medium)] >= 0)
            continue;
        Vector3f d = r.bounds.Diagonal();
        Float longest = std::max({d.x, d.y, d.z});
        if (!(d.x > 0 && d.y > 0 && d.z > 0) || !std::isfinite(d.x * d.y * d.z)) continue;
        Grid g{r.medium, r.bounds, {0, 0, 0}, cellCount, 0};
        for (int a = 0; a < 3; ++a)
            g.res[a] = std::clamp(int(std::ceil(kMaxCells * d[a] / longest)), 1, kMaxCells);
        g.cellVolume = (d.x / g.res[0]) * (d.y / g.res[1]) * (d.z / g.res[2]);
        if (!(g.cellVolume > 0)) continue;
        cellCount += size_t(g.res[0]) * g.res[1] * g.res[2];
        gridOfMedium[size_t(r.medium)] = int(grids.size());
        grids.push_back(g);
    }
    if (grids.empty()) return;

    // Each cell's emission over the visible band (W m^-3 sr^-1), from stratified points
    std::vector<Float> emission(cellCount, 0);
    cellGrid.resize(cellCount);
    for (int gi = 0; gi < int(grids.size()); ++gi) {
        const Grid& g = grids[size_t(gi)];
        const Medium& medium = media[size_t(g.medium)];
        int nx = g.res[0], ny = g.res[1], nz = g.res[2];
        size_t n = size_t(nx) * ny * nz;
        tbb::parallel_for(size_t(0), n, [&](size_t c) {
            cellGrid[g.firstCell + c] = gi;
            int x = int(c % size_t(nx)), y = int(c / size_t(nx) % size_t(ny)),
                z = int(c / (size_t(nx) * ny));
            RNG rng(Hash(gi, c));
            double sum = 0;
            for (int k = 0; k < kPointsPerCell; ++k) {
                // 2 x 2 x 2 strata of the cell, jittered
                Float u[3] = {((k & 1) + rng.UniformFloat()) / 2,
                              ((k >> 1 & 1) + rng.UniformFloat()) / 2,
                              ((k >> 2 & 1) + rng.UniformFloat()) / 2};
                Vector3f d = g.bounds.Diagonal();
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
            emission[g.firstCell + c] = Float(sum / kPointsPerCell);
        });
    }

    // Masses: each medium by its estimated power (all alike if none was found), its cells by
    // emission with a uniform share
    std::vector<double> power(grids.size(), 0);
    for (size_t gi = 0; gi < grids.size(); ++gi) {
        const Grid& g = grids[gi];
        size_t n = size_t(g.res[0]) * g.res[1] * g.res[2];
        for (size_t c = 0; c < n; ++c) power[gi] += double(emission[g.firstCell + c]);
        power[gi] *= g.cellVolume;
    }
    double totalPower = 0;
    for (double p : power) totalPower += p;
    std::vector<Float> mass(cellCount, 0);
    for (size_t gi = 0; gi < grids.size(); ++gi) {
        const Grid& g = grids[gi];
        size_t n = size_t(g.res[0]) * g.res[1] * g.res[2];
        double pMedium = totalPower > 0 ? power[gi] / totalPower : 1.0 / double(grids.size());
        double sum = power[gi] / g.cellVolume;
        for (size_t c = 0; c < n; ++c) {
            double share = kUniformShare / double(n);
            if (sum > 0)
                share += (1 - kUniformShare) * emission[g.firstCell + c] / sum;
            else
                share = 1.0 / double(n);
            mass[g.firstCell + c] = Float(pMedium * share);
        }
    }
    cells = AliasTable(mass);
}

size_t MediumEmissionSampler::CellOf(const Grid& g, Point3f p) const {
    Vector3f d = g.bounds.Diagonal();
    int i[3];
    for (int a = 0; a < 3; ++a)
        i[a] = std::clamp(int((p[a] - g.bounds.pMin[a]) / d[a] * g.res[a]), 0, g.res[a] - 1);
    return g.firstCell + size_t(i[0]) + size_t(g.res[0]) * (size_t(i[1]) + size_t(g.res[1]) * i[2]);
}

std::optional<MediumEmissionSampler::PointSample> MediumEmissionSampler::Sample(Float u,
                                                                                Point3f u3) const {
    if (grids.empty()) return std::nullopt;
    Float pmf;
    int c = cells.Sample(u, &pmf);
    if (pmf == 0) return std::nullopt;
    const Grid& g = grids[size_t(cellGrid[size_t(c)])];
    size_t local = size_t(c) - g.firstCell;
    int x = int(local % size_t(g.res[0])), y = int(local / size_t(g.res[0]) % size_t(g.res[1])),
        z = int(local / (size_t(g.res[0]) * g.res[1]));
    Vector3f d = g.bounds.Diagonal();
    Point3f p(g.bounds.pMin.x + d.x * (x + u3.x) / g.res[0],
              g.bounds.pMin.y + d.y * (y + u3.y) / g.res[1],
              g.bounds.pMin.z + d.z * (z + u3.z) / g.res[2]);
    // The density PDF reports at p (the cell p rounds into)
    Float pdf = cells.PMF(int(CellOf(g, p))) / g.cellVolume;
    if (!(pdf > 0)) return std::nullopt;
    return PointSample{g.medium, p, pdf};
}

Float MediumEmissionSampler::PDF(int medium, Point3f p) const {
    if (medium < 0 || size_t(medium) >= gridOfMedium.size() || gridOfMedium[size_t(medium)] < 0)
        return 0;
    const Grid& g = grids[size_t(gridOfMedium[size_t(medium)])];
    for (int a = 0; a < 3; ++a)
        if (!(p[a] >= g.bounds.pMin[a] && p[a] <= g.bounds.pMax[a])) return 0;
    return cells.PMF(int(CellOf(g, p))) / g.cellVolume;
}

}  // namespace kiln
