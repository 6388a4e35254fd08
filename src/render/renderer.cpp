#include "render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "core/camera/camera_sample.h"
#include "render/ambient_occlusion_integrator.h"
#include "render/bdpt_integrator.h"
#include "render/path_integrator.h"
#include "render/visible_surface_footprint.h"
#include "render/volpath_integrator.h"

namespace kiln {

namespace {

// Where a pixel's samples lie and which pixels they count for
enum class PixelPlacement {
    FilterImportance,  // drawn from the filter around the pixel's centre; that pixel alone
    Centre,            // Option "disablepixeljitter": at the centre, that pixel alone
    Spread             // uniform over the pixel; every pixel within the filter's radius
};

// What the pixel loop does differently per scene, fixed for the whole render: each
// combination is its own instantiation of the loop, so a render pays for none of the options
// it does not use (no per-sample tests).
struct PixelFeatures {
    bool aovs;              // the film writes albedo/normal/depth layers (first-hit data)
    bool singleWavelength;  // one wavelength per path (comparisons) instead of 4
    PixelPlacement placement;
};

// Polarised radiance arriving at the camera along -d (Stokes in the implicit frame of d, the
// direction of travel) in the film's frame: reference axis the image's horizontal, S2 > 0 along
// the diagonal towards the image's upper right, whatever the handedness of the camera
// transform; then through the camera's polariser, if any.
Stokes ToFilmFrame(const Scene& scene, Stokes S, Vector3f d) {
    const Transform& renderFromCamera = scene.camera->GetCameraTransform().RenderFromCamera();
    Vector3f right = renderFromCamera(Vector3f(1, 0, 0)), up = renderFromCamera(Vector3f(0, 1, 0));
    Vector3f x = GramSchmidt(Normalize(right), d);
    if (LengthSquared(x) < 1e-8f) return Stokes(S[0]);  // the ray runs along the horizontal
    x = Normalize(x);
    S = RotateStokesBasis(S, d, StokesBasis(d), x);
    // The frame (x, d x x, d) shows the image mirrored when d x x points down
    if (Dot(Cross(d, x), up) < 0) {
        S[2] = -S[2];
        S[3] = -S[3];
    }
    if (scene.cameraPolarizer) S = LinearPolarizer(*scene.cameraPolarizer) * S;
    return S;
}

// One pixel sample: camera ray, radiance along it, film update.
// pPixel in raster coordinates (Spread: possibly in the margin around the pixel bounds);
// samplerPixel, the pixel the sampler knows it as.
template <typename Integrator, bool AOVs, bool SingleWavelength, PixelPlacement Placement>
void RenderPixelSample(const Scene& scene, const Integrator& integrator, kiln::Sampler& sampler,
                       Point2i pPixel, Point2i samplerPixel, int sampleIndex) {
    using Radiance = typename Integrator::Radiance;
    constexpr bool FixedPixelCenter = Placement == PixelPlacement::Centre;
    sampler.StartPixelSample(samplerPixel, sampleIndex);
    // Wavelengths first, then the camera sample (pbrt-v4's order)
    Float lu = sampler.Get1D();
    SampledWavelengths lambda = scene.job->film->SampleWavelengths(lu);
    if constexpr (SingleWavelength) lambda.TerminateSecondary();
    CameraSample cs = Placement == PixelPlacement::Spread
                          ? GetUniformCameraSample(sampler, pPixel)
                          : GetCameraSample(sampler, pPixel, *scene.filter);
    if constexpr (FixedPixelCenter) {
        cs.pFilm = Point2f(pPixel.x + 0.5f, pPixel.y + 0.5f);
        cs.filterWeight = 1;
    }
    std::optional<CameraRay> cameraRay = scene.camera->GenerateRay(cs, lambda);
    typename Radiance::Spectrum L;
    // The first hit's albedo etc. only when the film writes AOV layers (it costs a BSDF
    // albedo estimate per camera ray)
    VisibleSurface visible;
    VisibleSurface* pVisible = AOVs ? &visible : nullptr;
    if (cameraRay) {
        L = cameraRay->weight * integrator.Li(cameraRay->ray, lambda, sampler, pVisible);
        if constexpr (Radiance::Polarized) L = ToFilmFrame(scene, L, -cameraRay->ray.d);
        if constexpr (AOVs) {
            // The visible surface's footprint from the ray's differentials, scaled to the
            // sampling rate as pbrt-v4 does (not without pixel jitter)
            if (visible.set) {
                const int spp = scene.job->sampler->SamplesPerPixel();
                Float scale = FixedPixelCenter ? Float(1)
                                               : std::max<Float>(0.125f, 1 / std::sqrt(Float(spp)));
                SetCameraDifferentials(*scene.camera, cs, cameraRay->ray, lambda, scale, spp,
                                       &visible);
            }
        }
    }
    if constexpr (Placement == PixelPlacement::Spread)
        scene.job->film->SpreadSample(cs.pFilm, L, lambda, pVisible);
    else
        scene.job->film->AddSample(pPixel, L, lambda, pVisible, cs.filterWeight);
}

template <typename Integrator>
using PixelSampleFunction = void (*)(const Scene&, const Integrator&, kiln::Sampler&, Point2i,
                                     Point2i, int);

template <typename Integrator, bool AOVs, bool SingleWavelength>
PixelSampleFunction<Integrator> PixelSampleFor(PixelPlacement placement) {
    switch (placement) {
        case PixelPlacement::FilterImportance:
            return RenderPixelSample<Integrator, AOVs, SingleWavelength,
                                     PixelPlacement::FilterImportance>;
        case PixelPlacement::Centre:
            return RenderPixelSample<Integrator, AOVs, SingleWavelength, PixelPlacement::Centre>;
        case PixelPlacement::Spread:
            break;
    }
    return RenderPixelSample<Integrator, AOVs, SingleWavelength, PixelPlacement::Spread>;
}

// The instantiation for the scene's features, chosen once per render.
template <typename Integrator>
PixelSampleFunction<Integrator> PixelSampleFor(PixelFeatures f) {
    if (f.aovs)
        return f.singleWavelength ? PixelSampleFor<Integrator, true, true>(f.placement)
                                  : PixelSampleFor<Integrator, true, false>(f.placement);
    return f.singleWavelength ? PixelSampleFor<Integrator, false, true>(f.placement)
                              : PixelSampleFor<Integrator, false, false>(f.placement);
}

// The tiles of the pixels sampled, in the order rendered: all at once, or with Spread
// reconstruction in four phases of tiles no two of which are neighbours (tiles at least twice
// the film's spread margin wide), so that no two threads add to the same pixel.
struct TileSchedule {
    std::vector<Bounds2i> tiles;
    std::vector<size_t> phaseEnd;  // tiles[phaseEnd[k - 1], phaseEnd[k]) make phase k
};

TileSchedule ScheduleTiles(Bounds2i sampled, Vector2i margin, bool phases) {
    constexpr int kTileSize = 16;
    const int size = std::max({kTileSize, 2 * margin.x, 2 * margin.y});
    const int nx = (sampled.pMax.x - sampled.pMin.x + size - 1) / size;
    const int ny = (sampled.pMax.y - sampled.pMin.y + size - 1) / size;
    TileSchedule schedule;
    for (int phase = 0; phase < (phases ? 4 : 1); ++phase) {
        for (int ty = 0; ty < ny; ++ty)
            for (int tx = 0; tx < nx; ++tx) {
                if (phases && (tx % 2) + 2 * (ty % 2) != phase) continue;
                Point2i p0(sampled.pMin.x + tx * size, sampled.pMin.y + ty * size);
                Point2i p1(std::min(p0.x + size, sampled.pMax.x),
                           std::min(p0.y + size, sampled.pMax.y));
                schedule.tiles.push_back(Bounds2i{p0, p1});
            }
        schedule.phaseEnd.push_back(schedule.tiles.size());
    }
    return schedule;
}

}  // namespace

namespace {

template <typename Integrator>
RenderStats RenderVariant(Scene& scene, const RenderSettings& settings) {
    RenderStats stats;
    Bounds2i pixelBounds = scene.job->film->PixelBounds();
    Point2i res(pixelBounds.pMax.x - pixelBounds.pMin.x, pixelBounds.pMax.y - pixelBounds.pMin.y);
    stats.resolution = res;
    const int spp = scene.job->sampler->SamplesPerPixel();
    stats.samplesPerPixel = spp;
    if (res.x <= 0 || res.y <= 0 || spp <= 0) return stats;

    std::unique_ptr<tbb::global_control> threadLimit;
    if (settings.threads > 0)
        threadLimit = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, size_t(settings.threads));

    Integrator integrator(scene, scene.integrator);
    const SceneFeatures& f = scene.features;
    RGBFilm& film = *scene.job->film;
    const bool spread = film.Reconstruction() == PixelReconstruction::Spread;
    const PixelPlacement placement = f.fixedPixelCenter ? PixelPlacement::Centre
                                     : spread           ? PixelPlacement::Spread
                                                        : PixelPlacement::FilterImportance;
    const PixelSampleFunction<Integrator> renderPixelSample =
        PixelSampleFor<Integrator>({f.aovs, f.singleWavelength, placement});
    // The pixels sampled (with Spread, also those in the margin whose samples reach the
    // bounds) and the offset that makes them the sampler's pixels
    const Vector2i margin = film.SpreadMargin();
    const Bounds2i sampled = film.SpreadPixelBounds();
    const TileSchedule schedule = ScheduleTiles(sampled, margin, spread);
    const int64_t pixelsSampled = int64_t(sampled.Area());
    tbb::enumerable_thread_specific<kiln::Sampler> samplers(
        [&] { return scene.job->sampler->Clone(); });

    std::ostringstream title;
    title << "Rendering " << res.x << "x" << res.y << " @ " << spp << " spp";
    RenderObserver* observer = settings.observer;
    if (observer) observer->Started(pixelsSampled * spp, title.str());
    std::atomic<int64_t> pathsTraced{0};
    const auto start = std::chrono::steady_clock::now();

    // Waves of 1, 2, 4, ... samples per pixel (at most settings.maxWaveSize, 64 by default), as
    // pbrt-v4; with checkpoints, small enough that a wave takes at most a quarter of the
    // checkpoint interval, and with settings.waveSeconds at most that
    int waveStart = std::clamp(settings.startSample, 0, spp), waveSize = 1;
    if (observer && waveStart > 0) observer->Advanced(pixelsSampled * waveStart);
    // Splats (light tracing) are the sums of all samples so far: 1 / their count on output
    // (BDPTIntegrator scales them by the full image's area over the area sampled)
    if (waveStart > 0) film.SetSplatScale(1.0 / waveStart);
    stats.completedSamples = waveStart;
    auto lastCheckpoint = start;
    while (waveStart < spp) {
        int waveEnd = std::min(spp, waveStart + waveSize);
        const auto waveBegan = std::chrono::steady_clock::now();
        for (size_t phase = 0; phase < schedule.phaseEnd.size(); ++phase) {
            const size_t first = phase == 0 ? 0 : schedule.phaseEnd[phase - 1];
            tbb::parallel_for(
                tbb::blocked_range<size_t>(first, schedule.phaseEnd[phase], 1),
                [&](const tbb::blocked_range<size_t>& range) {
                    kiln::Sampler& sampler = samplers.local();
                    for (size_t t = range.begin(); t != range.end(); ++t) {
                        if (settings.cancel && settings.cancel->load(std::memory_order_relaxed))
                            return;
                        const Bounds2i& tile = schedule.tiles[t];
                        for (int y = tile.pMin.y; y < tile.pMax.y; ++y)
                            for (int x = tile.pMin.x; x < tile.pMax.x; ++x)
                                for (int s = waveStart; s < waveEnd; ++s)
                                    renderPixelSample(scene, integrator, sampler, Point2i(x, y),
                                                      Point2i(x + margin.x, y + margin.y), s);
                        int64_t paths = int64_t(tile.Area()) * (waveEnd - waveStart);
                        pathsTraced.fetch_add(paths, std::memory_order_relaxed);
                        if (observer) observer->Advanced(paths);
                    }
                });
        }
        if (settings.cancel && settings.cancel->load()) {
            stats.cancelled = true;
            break;
        }
        stats.completedSamples = waveEnd;
        film.SetSplatScale(1.0 / waveEnd);
        const auto now = std::chrono::steady_clock::now();
        if (settings.checkpoint && waveEnd < spp &&
            std::chrono::duration<double>(now - lastCheckpoint).count() >=
                settings.checkpointSeconds) {
            settings.checkpoint(waveEnd);
            lastCheckpoint = std::chrono::steady_clock::now();
        }
        if (settings.afterWave) settings.afterWave(waveEnd);
        int next = std::clamp(2 * waveSize, 1, std::max(1, settings.maxWaveSize));
        double waveLimit = settings.waveSeconds > 0 ? settings.waveSeconds : Infinity;
        if (settings.checkpoint) waveLimit = std::min(waveLimit, 0.25 * settings.checkpointSeconds);
        if (waveLimit < Infinity) {
            double perSample = std::chrono::duration<double>(now - waveBegan).count() /
                               double(waveEnd - waveStart);
            if (perSample > 0) next = int(std::clamp<double>(waveLimit / perSample, 1, next));
        }
        waveStart = waveEnd;
        waveSize = next;
    }
    if (observer) observer->Finished();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.cameraPaths = pathsTraced.load();
    return stats;
}

}  // namespace

RenderStats Render(Scene& scene, const RenderSettings& settings) {
    // The radiance variant (radiance.h) and integrator the scene needs, chosen once
    if (scene.features.ambientOcclusion)
        return RenderVariant<AmbientOcclusionIntegrator>(scene, settings);
    if (scene.features.bidirectional) return RenderVariant<BDPTIntegrator>(scene, settings);
    if (scene.features.volumetric) {
        if (scene.features.polarized)
            return RenderVariant<VolPathIntegrator<PolarizedRadiance>>(scene, settings);
        return RenderVariant<VolPathIntegrator<UnpolarizedRadiance>>(scene, settings);
    }
    if (scene.features.polarized)
        return RenderVariant<PathIntegrator<PolarizedRadiance>>(scene, settings);
    return RenderVariant<PathIntegrator<UnpolarizedRadiance>>(scene, settings);
}

}  // namespace kiln
