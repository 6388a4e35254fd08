// MediumEmissionSampler: points in the emissive media of a scene drawn in proportion to their
// emission, so that volumetric path tracing samples hot media as light sources rather than
// find them only by tracking.
//
// Each emissive medium (an emitter) gets a box (its own render-space box, or that of the
// shapes it fills, or both intersected) divided into at most kMaxCells cells per axis. A
// cell's weight is its emission over the visible band, W m^-3 sr^-1: the mean of sigma_a Le
// (MediumProperties::emission) integrated over 360-830 nm, estimated once at load from
// kPointsPerCell stratified points with four wavelengths each (together stratified over
// 360-830 nm). An emitter is chosen in proportion to its power, 4 pi times the sum of weight
// times volume (uniformly if none was found); from a point where its box's bounding sphere
// subtends a solid angle Omega above kSolidAngleBudget, it is then kept only with probability
// kSolidAngleBudget / Omega (paths find so large an emitter often by themselves, and a shadow
// ray into it costs a tracking); then a cell of it with probability (1 - kUniformShare)
// weight / sum of its weights + kUniformShare / cells, then a point uniformly in the cell. The
// uniform share keeps the density above zero wherever the estimate missed emission; PDF is the
// exact density of Sample, so estimators that combine it with tracking by multiple importance
// sampling stay unbiased whatever the estimate. A medium's power counts all it emits, also what it
// absorbs again itself.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "base/sampling.h"
#include "base/vecmath.h"
#include "media/medium.h"

namespace kiln {

class MediumEmissionSampler {
  public:
    // Where a medium is sampled: a render-space box (empty or flat: not sampled).
    struct Region {
        int medium;
        Bounds3f bounds;
    };
    // Estimates the cells' weights of every region (in parallel).
    MediumEmissionSampler(std::span<const Medium> media, std::span<const Region> regions);

    // The emitters, numbered from 0: media that are sampled, in the order of the regions.
    int Emitters() const { return int(grids.size()); }
    int MediumOf(int emitter) const { return grids[size_t(emitter)].medium; }
    // The emitter of a medium (-1: not sampled).
    int EmitterOf(int medium) const {
        return medium >= 0 && size_t(medium) < emitterOfMedium.size()
                   ? emitterOfMedium[size_t(medium)]
                   : -1;
    }
    // Its power, W over 360-830 nm.
    double Power(int emitter) const { return grids[size_t(emitter)].power; }
    const std::vector<Region>& Regions() const { return regions; }

    struct PointSample {
        int emitter;
        Point3f p;  // render space
        Float pdf;  // per unit volume of render space, the choice of the emitter included
    };
    // A point to light `from`, from u (emitter, whether to keep it, cell) and u3 (place in the
    // cell); nullopt if none (the emitter not kept).
    std::optional<PointSample> Sample(Point3f from, Float u, Point3f u3) const;
    // The density per unit volume with which Sample(from, ...) returns emitter and p (0 outside
    // its box).
    Float PDF(Point3f from, int emitter, Point3f p) const;
    // The probability that Sample keeps the emitter it chose, from `from`.
    Float KeepProbability(int emitter, Point3f from) const;

    static constexpr int kMaxCells = 24;
    static constexpr int kPointsPerCell = 8;
    static constexpr Float kUniformShare = 0.1f;
    static constexpr Float kSolidAngleBudget = 0.5f;  // sr

  private:
    struct Grid {
        int medium;
        Bounds3f bounds;
        int res[3];
        Float cellVolume;
        AliasTable cells;
        double power;    // W over 360-830 nm
        Point3f center;  // the box's bounding sphere
        Float radius;
    };
    // The grid's cell holding p (clamped to the box).
    static int CellOf(const Grid& g, Point3f p);

    std::vector<Region> regions;  // as given
    std::vector<Grid> grids;
    AliasTable emitters;               // by power
    std::vector<int> emitterOfMedium;  // by medium index, -1: not sampled
};

}  // namespace kiln
