// Helpers for render tests: build and render a scene given as text or file, in process.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "base/statistics.h"
#include "core/parser/parser.h"
#include "render/renderer.h"
#include "render/scene_builder.h"
#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/planck.h"

namespace kiln::testing {

struct RenderedScene {
    std::unique_ptr<Scene> scene;
    RenderStats stats;
    std::vector<Diagnostics::Warning> warnings;
};

inline std::unique_ptr<Scene> BuildScene(const std::string& text, Diagnostics& diag,
                                         RenderOptions overrides = {}) {
    SceneBuilder builder(diag);
    ParseString(builder, text, diag, "<test>");
    return Scene::Create(builder.Description(), overrides, diag);
}

inline RenderedScene RenderText(const std::string& text, int threads = 0,
                                RenderOptions overrides = {}) {
    Diagnostics diag(nullptr);
    RenderedScene r;
    r.scene = BuildScene(text, diag, overrides);
    RenderSettings settings;
    settings.threads = threads;
    r.stats = Render(*r.scene, settings);
    r.warnings = diag.Warnings();
    return r;
}

inline RenderedScene RenderFile(const std::string& filename, RenderOptions overrides = {}) {
    Diagnostics diag(nullptr);
    RenderedScene r;
    SceneBuilder builder(diag);
    ParseFile(builder, filename, diag);
    r.scene = Scene::Create(builder.Description(), overrides, diag);
    RenderSettings settings;
    r.stats = Render(*r.scene, settings);
    r.warnings = diag.Warnings();
    return r;
}

// Luminance Y of a blackbody at T (kelvin): the Y the film reports for B(lambda, T).
inline double BlackbodyLuminance(double T) {
    double sum = 0;
    for (int l = cie::kCMFLambdaMin; l <= cie::kCMFLambdaMax; ++l)
        sum += planck_radiance(l, T) * CIE_Y(Float(l));
    return sum / CIE_Y_integral;
}

// The start of a cavity scene: a 24 x 24 film, zsobol at spp, the integrator with maxdepth 500,
// a camera at (0, 0, -3) looking at the origin (fov 40), and everything at temperature T from
// WorldBegin on. The walls and their contents follow.
inline std::string CavityPreamble(double T, int spp, const char* integrator = "path") {
    std::ostringstream s;
    s << "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 24\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << spp << "\n"
      << "Integrator \"" << integrator << "\" \"integer maxdepth\" 500\n"
      << "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
      << "WorldBegin\nAttribute \"shape\" \"float temperature\" " << T << "\n";
    return s.str();
}

// A closed UV sphere of triangles with per-vertex normals (inward for a wall) and uv.
inline std::string MeshSphere(double r, int nu, int nv, double cx, double cy, double cz,
                              bool inward) {
    std::ostringstream P, N, UV, I;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            double th = Pi * j / nv, ph = 2 * Pi * i / nu;
            double n[3] = {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
            P << cx + r * n[0] << " " << cy + r * n[1] << " " << cz + r * n[2] << " ";
            double s = inward ? -1 : 1;
            N << s * n[0] << " " << s * n[1] << " " << s * n[2] << " ";
            UV << double(i) / nu << " " << double(j) / nv << " ";
        }
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            // Two triangles per cell, leaving out the degenerate ones at the poles
            int a = j * (nu + 1) + i, b = a + 1, c = a + nu + 1, d = c + 1;
            if (j > 0) {
                if (inward)
                    I << a << " " << b << " " << c << " ";
                else
                    I << a << " " << c << " " << b << " ";
            }
            if (j < nv - 1) {
                if (inward)
                    I << b << " " << d << " " << c << " ";
                else
                    I << b << " " << c << " " << d << " ";
            }
        }
    return "Shape \"trianglemesh\" \"integer indices\" [" + I.str() + "] \"point3 P\" [" + P.str() +
           "] \"normal N\" [" + N.str() + "] \"point2 uv\" [" + UV.str() + "]\n";
}

// Names of cavity tests parameterised by (case with a name, meshes): the case's letters and
// digits, and the geometry.
template <typename Case>
std::string CavityCaseName(const ::testing::TestParamInfo<std::tuple<Case, bool>>& info) {
    std::string id;
    for (char ch : std::string(std::get<0>(info.param).name))
        if (std::isalnum(static_cast<unsigned char>(ch))) id += ch;
    return id + (std::get<1>(info.param) ? "_Meshes" : "_Spheres");
}

// Each case once, in spheres and meshes by turns (the first case in spheres): every case and
// both geometries are rendered, at half the cost of every case in both.
template <typename Case>
std::vector<std::tuple<Case, bool>> AlternatingGeometry(std::vector<Case> cases) {
    std::vector<std::tuple<Case, bool>> params;
    for (size_t i = 0; i < cases.size(); ++i) params.emplace_back(cases[i], i % 2 == 1);
    return params;
}

// Luminance Y of a film pixel (colour space of the film).
inline Float PixelY(const Scene& scene, Point2i p) {
    RGB rgb = scene.job->film->GetPixelRGB(p);
    return scene.job->film->ColorSpace()->ToXYZ(rgb).Y;
}

// The blocks of about 4 x 4 pixels (4 to 7 on a side) that BlockStats averages over bounds:
// their indices along an axis for a pixel's offset from the bounds' start.
inline int BlockIndex(int offset, int extent, int nBlocks) {
    return int(int64_t(offset) * nBlocks / extent);
}
inline int BlocksAlong(int extent) { return std::max(1, extent / 4); }

// A per-pixel value (value(Point2i)) over pixel bounds b, for the image's mean and its
// standard error: the statistics of the means of blocks of about 4 x 4 pixels. A spread film
// (RGBFilm::SpreadSample) counts each sample for the pixels within the filter's radius, so
// neighbouring pixels' noise is correlated and per-pixel statistics would understate the
// mean's standard error; blocks several filter radii wide are nearly independent (4 pixels:
// for filters up to pbrt-v4's default Gaussian, radius 1.5). Mean() is the
// mean of the block means (the pixel mean when the blocks are equal).
template <typename PixelValue>
RunningStats BlockStats(Bounds2i b, PixelValue value) {
    const int w = b.pMax.x - b.pMin.x, h = b.pMax.y - b.pMin.y;
    const int nx = BlocksAlong(w), ny = BlocksAlong(h);
    std::vector<double> sum(size_t(nx) * ny, 0.0), count(size_t(nx) * ny, 0.0);
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) {
            size_t k = size_t(BlockIndex(y - b.pMin.y, h, ny)) * nx +
                       size_t(BlockIndex(x - b.pMin.x, w, nx));
            sum[k] += double(value(Point2i(x, y)));
            count[k] += 1;
        }
    RunningStats s;
    for (size_t k = 0; k < sum.size(); ++k) s.Add(sum[k] / count[k]);
    return s;
}

// The mean of a thermal film's channel ("L", "T") over its pixels, with its standard error
// (BlockStats)
inline RunningStats ThermalChannelStats(const RenderedScene& r, const char* channel) {
    Image img = r.scene->job->film->GetImage(nullptr);
    int c = img.ChannelIndex(channel);
    EXPECT_GE(c, 0) << channel;
    return BlockStats(Bounds2i{{0, 0}, img.Resolution()},
                      [&](Point2i p) { return img.GetChannel(p, c); });
}

// An equilibrium cavity render at temperature T (label: what it holds): no warnings, and the
// image mean B(T) within 4 standard errors of the noise (plus 1e-3; BlockStats), the test able
// to see a 0.5 % error.
inline void ExpectBlackbodyImage(const RenderedScene& r, double T, const std::string& label) {
    for (const auto& w : r.warnings) ADD_FAILURE() << w.message;
    const double B = BlackbodyLuminance(T);
    RunningStats s = BlockStats(r.scene->job->film->PixelBounds(),
                                [&](Point2i p) { return PixelY(*r.scene, p) / B; });
    double se = s.StandardError();
    std::printf("%-38s %5.0f K: mean %.5f of B(T), standard error %.5f\n", label.c_str(), T,
                s.Mean(), se);
    EXPECT_LT(4 * se, 0.005);
    EXPECT_NEAR(s.Mean(), 1, 4 * se + 1e-3);
}

// A render's noise from two seeds: the image's mean luminance over both, its standard error
// (from the two renders' difference in blocks, as BlockStats), and the per-pixel variance (half
// the mean squared difference of the two renders). sceneText(seed) gives the scene; seeds seed
// and seed + 1.
struct TwoSeedNoise {
    double mean, se, variance;
};
template <typename SceneText>
TwoSeedNoise RenderTwoSeeds(SceneText sceneText, int seed) {
    std::vector<double> a, b;
    Bounds2i bounds;
    for (auto [image, s] : {std::pair{&a, seed}, std::pair{&b, seed + 1}}) {
        RenderedScene r = RenderText(sceneText(s));
        bounds = r.scene->job->film->PixelBounds();
        for (int y = bounds.pMin.y; y < bounds.pMax.y; ++y)
            for (int x = bounds.pMin.x; x < bounds.pMax.x; ++x)
                image->push_back(PixelY(*r.scene, {x, y}));
    }
    double sumA = 0, sumB = 0, sq = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        sumA += a[i];
        sumB += b[i];
        sq += (a[i] - b[i]) * (a[i] - b[i]);
    }
    double n = double(a.size()), variance = sq / (2 * n);
    // The mean over both images has a quarter of the variance of the difference's mean, which
    // the blocks of the difference (mean 0) estimate
    const int w = bounds.pMax.x - bounds.pMin.x;
    RunningStats d = BlockStats(Bounds2i{{0, 0}, {w, int(a.size()) / w}}, [&](Point2i p) {
        size_t i = size_t(p.y) * size_t(w) + size_t(p.x);
        return a[i] - b[i];
    });
    double meanSquare = d.Variance() * (d.Count() - 1) / d.Count() + Sqr(d.Mean());
    return {(sumA + sumB) / (2 * n), std::sqrt(meanSquare / d.Count()) / 2, variance};
}

// The scene rendered with `integrator` (the technique on) and with `pbrtWay`, each with seeds 1
// to 4: image means (on with seeds 1, 2 against off with seeds 3, 4, independent) within 5
// combined standard errors, and the technique's per-pixel variance, from both pairs of seeds,
// below maxRatio of the other's from the same seeds (a pixel's variance estimate from two
// renders is heavy-tailed where it sees small bright things: the same seeds both ways keep the
// luck of the draw out of the ratio).
template <typename SceneText>
void ExpectSameImageWithLessNoise(const char* what, SceneText scene, const std::string& pbrtWay,
                                  double maxRatio) {
    TwoSeedNoise on = RenderTwoSeeds([&](int s) { return scene("", s); }, 1);
    TwoSeedNoise off = RenderTwoSeeds([&](int s) { return scene(pbrtWay, s); }, 3);
    TwoSeedNoise onOtherSeeds = RenderTwoSeeds([&](int s) { return scene("", s); }, 3);
    TwoSeedNoise offOtherSeeds = RenderTwoSeeds([&](int s) { return scene(pbrtWay, s); }, 1);
    ASSERT_GT(on.mean, 0);
    double ratio = (on.variance + onOtherSeeds.variance) / (off.variance + offOtherSeeds.variance);
    std::printf(
        "%s: pbrt-v4's way's image mean %.5f of the technique's (standard errors %.5f "
        "and %.5f), per-pixel variance ratio %.4f\n",
        what, off.mean / on.mean, off.se / on.mean, on.se / on.mean, ratio);
    EXPECT_NEAR(off.mean, on.mean, 5 * std::hypot(on.se, off.se)) << what;
    EXPECT_LT(ratio, maxRatio) << what;
}

// On by default, off with the Integrator parameter `off` gives, and off where the command line's
// option (RenderOptions::*option) says so whatever the scene says.
template <typename SceneText>
void ExpectSwitch(SceneText scene, const std::string& off, bool SceneFeatures::*feature,
                  std::optional<bool> RenderOptions::*option) {
    EXPECT_TRUE(RenderText(scene("", 1)).scene->features.*feature);
    EXPECT_FALSE(RenderText(scene(off, 1)).scene->features.*feature);
    RenderOptions options;
    options.*option = false;
    EXPECT_FALSE(RenderText(scene("", 1), 0, options).scene->features.*feature);
}

}  // namespace kiln::testing
