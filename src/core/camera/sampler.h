// Sampler: the closed set of sample generators, held by value (each thread owns a copy), and
// pbrt-v4's GetCameraSample.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "base/closed_set.h"
#include "core/camera/camera_sample.h"
#include "core/camera/halton_sampler.h"
#include "core/camera/pmj02bn_sampler.h"
#include "core/camera/samplers.h"
#include "core/camera/sobol_sampler.h"
#include "core/film/filter.h"
#include "core/parser/diagnostics.h"
#include "core/parser/file_loc.h"

namespace kiln {

class ParameterDictionary;

class Sampler : public ClosedSet<IndependentSampler, StratifiedSampler, ZSobolSampler,
                                 PaddedSobolSampler, HaltonSampler, SobolSampler, PMJ02BNSampler> {
  public:
    using ClosedSet::ClosedSet;
    Sampler() : ClosedSet(IndependentSampler(1)) {}
    // The seed its sample streams are drawn with.
    int Seed() const {
        return Dispatch([](const auto& s) { return s.Seed(); });
    }
    int SamplesPerPixel() const {
        return Dispatch([](const auto& s) { return s.SamplesPerPixel(); });
    }
    // Restarts the stream at sample `sampleIndex` of pixel p, at dimension `dimension`.
    void StartPixelSample(Point2i p, int sampleIndex, int dimension = 0) {
        Dispatch([&](auto& s) { s.StartPixelSample(p, sampleIndex, dimension); });
    }
    // Values in [0, 1).
    Float Get1D() {
        return Dispatch([](auto& s) { return s.Get1D(); });
    }
    Point2f Get2D() {
        return Dispatch([](auto& s) { return s.Get2D(); });
    }
    // The 2D sample for the position within the pixel (film plane).
    Point2f GetPixel2D() {
        return Dispatch([](auto& s) { return s.GetPixel2D(); });
    }
    Sampler Clone() const { return *this; }

    // pbrt-v4 names "independent", "stratified", "zsobol" (default in pbrt-v4),
    // "paddedsobol", "halton", "sobol", "pmj02bn". Parameters "pixelsamples" (16), "seed" (0),
    // stratified "xsamples"/"ysamples" (4)/"jitter" (true), "randomization" ("none",
    // "permutedigits", "fastowen", "owen"; default "fastowen", for halton "permutedigits",
    // which rejects "fastowen" as pbrt-v4 does). zsobol and paddedsobol round the sample count
    // up to a power of two, sobol and pmj02bn warn about counts that are not a power of 2 or 4
    // and use them as given (pbrt-v4); pmj02bn takes at most 65536. sppOverride and
    // seedOverride (command line) win over the parameters. Unknown name: SceneError.
    static Sampler Create(const std::string& name, const ParameterDictionary& params,
                          Point2i fullResolution, const FileLoc& loc, Diagnostics& diag,
                          std::optional<int> sppOverride = {},
                          std::optional<int> seedOverride = {});
};

// pbrt-v4 GetCameraSample: a filter-importance-sampled film position in pixel pPixel
// (pFilm = pPixel + (0.5, 0.5) + filter offset, raster units), the filter weight, then time
// and lens samples, in that order of sampler dimensions.
inline CameraSample GetCameraSample(Sampler& sampler, Point2i pPixel, const Filter& filter) {
    FilterSample fs = filter.Sample(sampler.GetPixel2D());
    CameraSample cs;
    cs.pFilm = Point2f(pPixel.x + 0.5f + fs.p.x, pPixel.y + 0.5f + fs.p.y);
    cs.filterWeight = fs.weight;
    cs.time = sampler.Get1D();
    cs.pLens = sampler.Get2D();
    return cs;
}

// The same with the film position uniform over pixel pPixel and filter weight 1, for films that
// spread each sample over the pixels near it (PixelReconstruction::Spread).
inline CameraSample GetUniformCameraSample(Sampler& sampler, Point2i pPixel) {
    Point2f u = sampler.GetPixel2D();
    CameraSample cs;
    cs.pFilm = Point2f(pPixel.x + u.x, pPixel.y + u.y);
    cs.filterWeight = 1;
    cs.time = sampler.Get1D();
    cs.pLens = sampler.Get2D();
    return cs;
}

}  // namespace kiln
