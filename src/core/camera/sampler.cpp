// Sampler creation from scene parameters (pbrt-v4 names and defaults).
#include "core/camera/sampler.h"

#include <cmath>

#include "core/parser/parameter_dictionary.h"
#include "core/parser/suggestions.h"

namespace kiln {

namespace {

RandomizeStrategy GetRandomization(const ParameterDictionary& params,
                                   const std::string& def = "fastowen") {
    std::string s = params.GetOneString("randomization", def);
    if (s == "none") return RandomizeStrategy::None;
    if (s == "permutedigits") return RandomizeStrategy::PermuteDigits;
    if (s == "fastowen") return RandomizeStrategy::FastOwen;
    if (s == "owen") return RandomizeStrategy::Owen;
    throw SceneError(params.Loc("randomization"), "unknown randomization strategy \"" + s + "\"",
                     s);
}

}  // namespace

Sampler Sampler::Create(const std::string& name, const ParameterDictionary& params,
                        Point2i fullResolution, const FileLoc& loc, Diagnostics& diag,
                        std::optional<int> sppOverride, std::optional<int> seedOverride) {
    const std::string& type = name;
    // Parameters the command line overrides are still read, so they are not reported unused.
    int seed = params.GetOneInt("seed", 0);
    if (seedOverride) seed = *seedOverride;

    if (type == "stratified") {
        bool jitter = params.GetOneBool("jitter", true);
        int xSamples = params.GetOneInt("xsamples", 4);
        int ySamples = params.GetOneInt("ysamples", 4);
        if (sppOverride) {
            // Factor the requested count into the most nearly square grid.
            int n = std::max(1, *sppOverride);
            int div = std::max(1, int(std::sqrt(double(n))));
            while (n % div) --div;
            ySamples = n / div;
            xSamples = n / ySamples;
        }
        if (xSamples <= 0 || ySamples <= 0)
            throw SceneError(params.Has("xsamples") && xSamples <= 0 ? params.Loc("xsamples")
                                                                     : params.Loc("ysamples"),
                             "\"xsamples\" and \"ysamples\" must be positive");
        return StratifiedSampler(xSamples, ySamples, jitter, seed);
    }

    // pbrt-v4's defaults: 4 for the independent sampler, 16 for the others
    int spp = params.GetOneInt("pixelsamples", type == "independent" ? 4 : 16);
    if (sppOverride) spp = *sppOverride;
    if (spp <= 0)
        throw SceneError(
            params.Has("pixelsamples") && !sppOverride ? params.Loc("pixelsamples") : loc,
            "\"pixelsamples\" must be positive");
    if (type == "independent") return IndependentSampler(spp, seed);
    if (type == "halton") {
        RandomizeStrategy randomize = GetRandomization(params, "permutedigits");
        if (randomize == RandomizeStrategy::FastOwen)
            throw SceneError(params.Loc("randomization"),
                             "\"fastowen\" randomization is not supported by the halton sampler",
                             "fastowen");
        return HaltonSampler(spp, fullResolution, randomize, seed);
    }
    if (type == "sobol") {
        RandomizeStrategy randomize = GetRandomization(params);
        if (!IsPowerOf2(spp))
            diag.Warn(loc, "the sobol sampler performs best with a power-of-two sample count (" +
                               std::to_string(spp) + " given)");
        return SobolSampler(spp, fullResolution, randomize, seed);
    }
    if (type == "pmj02bn") {
        if (spp > kPMJ02Samples)
            throw SceneError(
                params.Has("pixelsamples") && !sppOverride ? params.Loc("pixelsamples") : loc,
                "the pmj02bn sampler supports at most " + std::to_string(kPMJ02Samples) +
                    " samples per pixel");
        if (!IsPowerOf2(spp) || Log2Int(uint64_t(spp)) % 2 != 0)
            diag.Warn(loc, "the pmj02bn sampler performs best with a power-of-4 sample count (" +
                               std::to_string(spp) + " given)");
        return PMJ02BNSampler(spp, seed);
    }
    if (type == "zsobol" || type == "paddedsobol") {
        RandomizeStrategy randomize = GetRandomization(params);
        // As pbrt-v4: zsobol renders the largest power of two not above the count, paddedsobol
        // the count itself (its samples are then no longer a complete net)
        if (!IsPowerOf2(spp)) {
            int rounded = 1 << Log2Int(uint64_t(spp));
            diag.Warn(loc, type == "zsobol"
                               ? "the zsobol sampler needs a power-of-two sample count; " +
                                     std::to_string(spp) + " is rounded down to " +
                                     std::to_string(rounded) + " (as pbrt-v4)"
                               : "Sobol' samplers work best with a power-of-two sample count (" +
                                     std::to_string(spp) + " given)");
            if (type == "zsobol") spp = rounded;
        }
        if (type == "zsobol") return ZSobolSampler(spp, fullResolution, randomize, seed);
        return PaddedSobolSampler(spp, randomize, seed);
    }
    throw SceneError(
        loc,
        "unknown sampler type \"" + name + "\"" +
            DidYouMean(name, std::initializer_list<std::string_view>{"independent", "stratified",
                                                                     "zsobol", "halton", "pmj02bn",
                                                                     "sobol", "paddedsobol"}),
        name);
}

}  // namespace kiln
