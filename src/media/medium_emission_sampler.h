// MediumEmissionSampler: points in emissive media drawn in proportion to their emission, so
// that volumetric path tracing can sample hot media as light sources (next-event estimation)
// rather than find them only by tracking.
//
// Each emissive medium gets a box (its own render-space box, or that of the shapes it fills,
// or both intersected) divided into at most kMaxCells cells per axis. A cell's weight is its
// emission over the visible band, W m^-3 sr^-1: the mean of sigma_a Le (MediumProperties::
// emission) integrated over 360-830 nm, estimated once at load from kPointsPerCell stratified
// points with four wavelengths each (together stratified over 360-830 nm). Cells are drawn from one
// alias table over every medium: medium m in proportion to its estimated power, a cell of m with
// probability (1 - kUniformShare) weight / sum of m's weights + kUniformShare / cells of m, then a
// point uniformly in the cell. The uniform share keeps the density above zero wherever the estimate
// missed emission; PDF is the exact density of Sample, so estimators that combine it with
// tracking by multiple importance sampling stay unbiased whatever the estimate.
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
    // Estimates the cells' weights of every region (in parallel); media[region.medium] must
    // outlive the sampler.
    MediumEmissionSampler(std::span<const Medium> media, std::span<const Region> regions);

    bool Empty() const { return grids.empty(); }
    // How many media it samples, and where.
    int Media() const { return int(grids.size()); }
    const std::vector<Region>& Regions() const { return regions; }

    struct PointSample {
        int medium;  // index into the scene's media
        Point3f p;   // render space
        Float pdf;   // per unit volume of render space, the choice of medium included
    };
    // A point from u (cell) and u3 (place in the cell).
    std::optional<PointSample> Sample(Float u, Point3f u3) const;
    // The density per unit volume with which Sample returns medium and p (0 outside its box
    // or for media it does not sample).
    Float PDF(int medium, Point3f p) const;

    static constexpr int kMaxCells = 24;
    static constexpr int kPointsPerCell = 8;
    static constexpr Float kUniformShare = 0.1f;

  private:
    struct Grid {
        int medium;
        Bounds3f bounds;
        int res[3];
        size_t firstCell;
        Float cellVolume;
    };
    // The grid's cell holding p (clamped to the box), as an index into cellGrid.
    size_t CellOf(const Grid& g, Point3f p) const;

    std::vector<Region> regions;  // as given
    std::vector<Grid> grids;
    std::vector<int> gridOfMedium;  // by medium index, -1: not sampled
    std::vector<int> cellGrid;      // the grid of every cell
    AliasTable cells;
};

}  // namespace kiln
