#include "render/renderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/camera/camera_sample.h"
#include "render/ambient_occlusion_integrator.h"
#include "render/bdpt_integrator.h"
#include "render/path_integrator.h"
#include "render/visible_surface_footprint.h"
#include "render/volpath_integrator.h"

namespace kiln {

namespace {

// What the pixel loop does differently per scene, fixed for the whole render: each
// combination is its own instantiation of the loop, so a render pays for none of the options
// it does not use (no per-sample tests).
struct PixelFeatures {
    bool aovs;              // the film writes albedo/normal/depth layers (first-hit data)
    bool singleWavelength;  // one wavelength per path (comparisons) instead of 4
    bool fixedPixelCenter;  // Option "disablepixeljitter"
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
template <typename Integrator, bool AOVs, bool SingleWavelength, bool FixedPixelCenter>
void RenderPixelSample(const Scene& scene, const Integrator& integrator, kiln::Sampler& sampler,
                       Point2i pPixel, int sampleIndex) {
    using Radiance = typename Integrator::Radiance;
    sampler.StartPixelSample(pPixel, sampleIndex);
    // Wavelengths first, then the camera sample (pbrt-v4's order)
    Float lu = sampler.Get1D();
    SampledWavelengths lambda = scene.job->film->SampleWavelengths(lu);
    if constexpr (SingleWavelength) lambda.TerminateSecondary();
    CameraSample cs = GetCameraSample(sampler, pPixel, *scene.filter);
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
    scene.job->film->AddSample(pPixel, L, lambda, pVisible, cs.filterWeight);
}

template <typename Integrator>
using PixelSampleFunction = void (*)(const Scene&, const Integrator&, kiln::Sampler&, Point2i, int);

// The instantiation for the scene's features, chosen once per render.
template <typename Integrator>
PixelSampleFunction<Integrator> PixelSampleFor(PixelFeatures f) {
    static constexpr PixelSampleFunction<Integrator> table[8] = {
        RenderPixelSample<Integrator, false, false, false>,
        RenderPixelSample<Integrator, false, false, true>,
        RenderPixelSample<Integrator, false, true, false>,
        RenderPixelSample<Integrator, false, true, true>,
        RenderPixelSample<Integrator, true, false, false>,
        RenderPixelSample<Integrator, true, false, true>,
        RenderPixelSample<Integrator, true, true, false>,
        RenderPixelSample<Integrator, true, true, true>};
    return table[(f.aovs ? 4 : 0) + (f.singleWavelength ? 2 : 0) + (f.fixedPixelCenter ? 1 : 0)];
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
    const PixelSampleFunction<Integrator> renderPixelSample =
        PixelSampleFor<Integrator>({f.aovs, f.singleWavelength, f.fixedPixelCenter});
    tbb::enumerable_thread_specific<kiln::Sampler> samplers(
        [&] { return scene.job->sampler->Clone(); });

    std::ostringstream title;
    title << "Rendering " << res.x << "x" << res.y << " @ " << spp << " spp";
    RenderObserver* observer = settings.observer;
    if (observer) observer->Started(int64_t(res.x) * res.y * spp, title.str());
    std::atomic<int64_t> pathsTraced{0};
    const auto start = std::chrono::steady_clock::now();

    // Waves of 1, 2, 4, ... samples per pixel (at most settings.maxWaveSize, 64 by default), as
    // pbrt-v4; with checkpoints, small enough that a wave takes at most a quarter of the
    // checkpoint interval, and with settings.waveSeconds at most that
    constexpr int tileSize = 16;
    int waveStart = std::clamp(settings.startSample, 0, spp), waveSize = 1;
    if (observer && waveStart > 0) observer->Advanced(int64_t(res.x) * res.y * waveStart);
    // Splats (light tracing) are the sums of all samples so far: 1 / their count on output
    RGBFilm& film = *scene.job->film;
    if (waveStart > 0) film.SetSplatScale(1.0 / waveStart);
    stats.completedSamples = waveStart;
    auto lastCheckpoint = start;
    while (waveStart < spp) {
        int waveEnd = std::min(spp, waveStart + waveSize);
        const auto waveBegan = std::chrono::steady_clock::now();
        tbb::parallel_for(
            tbb::blocked_range2d<int>(pixelBounds.pMin.y, pixelBounds.pMax.y, tileSize,
                                      pixelBounds.pMin.x, pixelBounds.pMax.x, tileSize),
            [&](const tbb::blocked_range2d<int>& tile) {
                if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) return;
                kiln::Sampler& sampler = samplers.local();
                for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
                    for (int x = tile.cols().begin(); x != tile.cols().end(); ++x)
                        for (int s = waveStart; s < waveEnd; ++s)
                            renderPixelSample(scene, integrator, sampler, Point2i(x, y), s);
                int64_t paths =
                    int64_t(tile.rows().size()) * tile.cols().size() * (waveEnd - waveStart);
                pathsTraced.fetch_add(paths, std::memory_order_relaxed);
                if (observer) observer->Advanced(paths);
            });
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
