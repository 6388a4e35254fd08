// "uniformgrid" (pbrt-v4's GridMedium): coefficients times a density on a grid over the box
// [p0, p1] of the medium's space; also what a volume file becomes ("nanovdb" with a .vdb or
// .nvdb file, kiln's "vdb"; vdb_file.h), the box then being the grid's (in index space, its
// samples possibly reaching beyond it). Majorants per voxel of a 16^3 grid.
#pragma once

#include <optional>

#include "base/object_arena.h"
#include "base/transform.h"
#include "core/parser/diagnostics.h"
#include "media/majorant_grid.h"
#include "media/medium_emission.h"
#include "media/medium_parameters.h"
#include "media/sampled_grid.h"

namespace kiln {

class GridMedium {
  public:
    // renderFromMedium maps the medium's space (where bounds is) to render space. The density
    // (and emission) samples span sampleBounds (bounds if not given; a volume file's samples
    // may reach beyond the medium's box).
    GridMedium(const Bounds3f& bounds, const Transform& renderFromMedium,
               const MediumCoefficients& c, SampledGrid<Float> density, MediumEmission emission,
               std::optional<Bounds3f> sampleBounds = std::nullopt);
    // "density" (nx * ny * nz values, x fastest), "nx", "ny", "nz", "p0", "p1", the shared
    // coefficients, "Le" with "Lescale" (one value or one per voxel), "temperature" (one per
    // voxel: pbrt-v4's peak-normalised blackbody times "Lescale"; with kiln's "emission",
    // kelvin) with "temperatureoffset" (or "temperaturecutoff") and "temperaturescale"; or
    // kiln's textured "temperature", or one value for a grid of several voxels.
    static GridMedium* Create(const TextureParameterDictionary& params,
                              const Transform& renderFromMedium,
                              std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                              ObjectArena& arena, Diagnostics& diag);
    // "nanovdb" / "vdb": the "density" grid (or "gridname") of an OpenVDB or NanoVDB file,
    // temperatures from its "temperature" grid (or "temperaturename") if present.
    static GridMedium* CreateFromVDB(const TextureParameterDictionary& params,
                                     const Transform& renderFromMedium,
                                     std::optional<EmissionModel> modelOverride, const FileLoc& loc,
                                     ObjectArena& arena, Diagnostics& diag);

    bool IsEmissive() const { return emission.IsEmissive(); }
    bool IsUniform() const { return false; }
    MediumEmission& Emission() { return emission; }
    MediumProperties SamplePoint(Point3f p, const SampledWavelengths& lambda) const;
    MajorantIterator SampleRay(const Ray& ray, Float tMax, const SampledWavelengths& lambda) const;
    // The render-space box holding the medium (nothing is outside it).
    Bounds3f RenderBounds() const { return renderFromMedium(bounds); }

  private:
    // pMedium's place in the unit cube of box
    static Point3f UnitPoint(const Bounds3f& box, Point3f pMedium);

    Bounds3f bounds, sampleBounds;
    Transform renderFromMedium;
    Spectrum sigma_a, sigma_s;
    Float scale, g;
    SampledGrid<Float> density;
    MediumEmission emission;
    MajorantGrid majorants;
};

// How a grid medium glows from its parameters (shared by "uniformgrid" and volume files):
// temperature: one value per voxel of the density grid, or empty. constantLeScale: one
// "Lescale" value scales a temperature grid's glow everywhere (pbrt-v4's NanoVDBMedium), not
// as a one-voxel grid fading toward the box's faces (its GridMedium).
MediumEmission ReadGridEmission(const TextureParameterDictionary& params,
                                SampledGrid<Float> temperature, int nx, int ny, int nz,
                                std::optional<EmissionModel> modelOverride, ObjectArena& arena,
                                bool constantLeScale = false);

}  // namespace kiln
