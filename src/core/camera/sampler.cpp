// Sampler creation from scene parameters (pbrt-v4 names and defaults).
#include "core/camera/sampler.h"

#include <cmath>

#include "core/parser/parameter_dictionary.h"
#include "core/parser/suggestions.h"

namespace kiln {

namespace {

RandomizeStrategy GetRandomization(const ParameterDictionary& params) {
    std::string s = params.GetOneString("randomization", "fastowen");
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
    std::string type = name;
    if (type == "halton" || type == "pmj02bn" || type == "sobol") {
        diag.Warn(loc, "\"" + name + "\" sampler is not supported; using \"zsobol\"");
        type = "zsobol";
    }
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

    int spp = params.GetOneInt("pixelsamples", 16);
    if (sppOverride) spp = *sppOverride;
    if (spp <= 0)
        throw SceneError(
            params.Has("pixelsamples") && !sppOverride ? params.Loc("pixelsamples") : loc,
            "\"pixelsamples\" must be positive");
    if (type == "independent") return IndependentSampler(spp, seed);
    if (type == "zsobol" || type == "paddedsobol") {
        RandomizeStrategy randomize = GetRandomization(params);
        if (!IsPowerOf2(spp))
            diag.Warn(loc, "Sobol' samplers need a power-of-two sample count; " +
                               std::to_string(spp) + " is rounded up to " +
                               std::to_string(RoundUpPow2(spp)));
        spp = RoundUpPow2(spp);
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
