#include "render/glass_windows.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "base/rng.h"
#include "spectral/cie.h"

namespace kiln {

GlassWindows::GlassWindows(std::vector<Window> w) : windows(std::move(w)) {
    std::vector<Float> area;
    area.reserve(windows.size());
    for (const Window& window : windows) {
        Float a = window.shape.Area();
        area.push_back(std::isfinite(a) && a > 0 ? a : 0);
    }
    if (std::any_of(area.begin(), area.end(), [](Float a) { return a > 0; }))
        byArea = AliasTable(area);
    else
        windows.clear();
    // One bounding sphere per hot medium, over all of its windows
    std::map<int, Bounds3f> bounds;
    for (const Window& window : windows)
        bounds[window.hot] = Union(bounds[window.hot], window.shape.Bounds());
    for (const Window& window : windows) {
        Point3f c;
        Float r;
        bounds[window.hot].BoundingSphere(&c, &r);
        center.push_back(c);
        radius.push_back(r);
    }
}

Float GlassWindows::KeepProbability(int i, Point3f from) const {
    Float d2 = DistanceSquared(from, center[size_t(i)]), r2 = Sqr(radius[size_t(i)]);
    Float solidAngle = d2 <= r2 ? 4 * Pi : 2 * Pi * (1 - SafeSqrt(1 - r2 / d2));
    Float keep = solidAngle > kSolidAngleBudget ? kSolidAngleBudget / solidAngle : 1;
    if (glowOverEnvironment2.empty()) return keep;
    Float share = glowOverEnvironment2[size_t(i)] * solidAngle / Pi;
    return share < 1 ? keep * share : keep;
}

namespace {

// Weight of a wavelength in the glow and environment estimates (the colour a film sees)
Float Weight(Float lambda) { return CIE_X(lambda) + CIE_Y(lambda) + CIE_Z(lambda); }

// The weighted mean over 360-830 nm of f, from 8 stratified sets of 4 wavelengths starting
// at offset u0 in [0, 1)
template <typename F>
Float WeightedMean(F f, Float u0) {
    double sum = 0;
    for (int k = 0; k < 8; ++k) {
        SampledWavelengths lambda = SampledWavelengths::SampleUniform((k + u0) / 8);
        SampledSpectrum v = f(lambda), pdf = lambda.PDF();
        for (int i = 0; i < NSpectrumSamples; ++i)
            if (std::isfinite(v[i]) && pdf[i] > 0) sum += double(v[i]) * Weight(lambda[i]) / pdf[i];
    }
    return Float(sum / (8 * NSpectrumSamples));
}

}  // namespace

void GlassWindows::WeighAgainstEnvironment(std::span<const Medium> media,
                                           Float environmentRadiance) {
    glowOverEnvironment2.clear();
    if (!(environmentRadiance > 0) || !std::isfinite(environmentRadiance)) return;
    // Each hot medium's glow: the largest over 4^3 stratified points of its windows' box of
    // emission / extinction (what an optically thick body of it sends out)
    std::map<int, Bounds3f> bounds;
    for (const Window& window : windows)
        bounds[window.hot] = Union(bounds[window.hot], window.shape.Bounds());
    std::map<int, Float> glow;
    for (const auto& [hot, box] : bounds) {
        const Medium& medium = media[size_t(hot)];
        RNG rng(uint64_t(hot) + 1);
        Float largest = 0;
        for (int k = 0; k < 64; ++k) {
            Float t[3] = {((k & 3) + rng.UniformFloat()) / 4,
                          ((k >> 2 & 3) + rng.UniformFloat()) / 4,
                          ((k >> 4 & 3) + rng.UniformFloat()) / 4};
            Point3f p(Lerp(t[0], box.pMin.x, box.pMax.x), Lerp(t[1], box.pMin.y, box.pMax.y),
                      Lerp(t[2], box.pMin.z, box.pMax.z));
            Float g = WeightedMean(
                [&](const SampledWavelengths& lambda) {
                    MediumProperties mp = medium.SamplePoint(p, lambda);
                    return SafeDiv(mp.emission, mp.sigma_a + mp.sigma_s);
                },
                rng.UniformFloat());
            largest = std::max(largest, g);
        }
        glow[hot] = largest;
    }
    for (const Window& window : windows)
        glowOverEnvironment2.push_back(Sqr(glow[window.hot] / environmentRadiance));
}

Float GlassWindows::EnvironmentRadiance(std::span<const Light> lights,
                                        std::span<const int> infiniteLights) {
    double sum = 0;
    constexpr int kDirections = 256;
    for (int index : infiniteLights) {
        const Light& light = lights[size_t(index)];
        RNG rng(uint64_t(index) + 7);
        for (int k = 0; k < kDirections; ++k) {
            // Stratified over the sphere (16 x 16 cells)
            Point2f u(((k & 15) + rng.UniformFloat()) / 16, ((k >> 4) + rng.UniformFloat()) / 16);
            Ray ray(Point3f(0, 0, 0), SampleUniformSphere(u));
            sum += WeightedMean(
                [&](const SampledWavelengths& lambda) { return light.Le(ray, lambda); },
                rng.UniformFloat());
        }
    }
    return Float(sum / kDirections);
}

int GlassWindows::Choose(Float u, Point3f from, Float* p) const {
    if (windows.empty()) return -1;
    Float pmf = 0, uKeep = 0;
    int i = byArea.Sample(u, &pmf, &uKeep);
    Float keep = KeepProbability(i, from);
    if (!(pmf > 0) || uKeep >= keep) return -1;
    *p = pmf * keep;
    return i;
}

}  // namespace kiln
