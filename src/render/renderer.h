// The render loop: pixel samples in parallel over image tiles (TBB), in waves of increasing
// sample counts so that an interrupted render still has every pixel sampled alike.
//
// Determinism: every sample value comes from the sampler seeded by (pixel, sample index,
// dimension), and each pixel is written by one task at a time, so the image is bit-identical
// for any number of threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "render/scene.h"

namespace kiln {

// Follows a render's progress (the kiln command's progress bar is one). Advanced() is called
// from the worker threads, concurrently.
class RenderObserver {
  public:
    virtual ~RenderObserver() = default;
    // totalWork: pixel samples to trace.
    virtual void Started(int64_t totalWork, const std::string& title) = 0;
    virtual void Advanced(int64_t work) = 0;
    virtual void Finished() = 0;
};

struct RenderSettings {
    int threads = 0;                            // 0: all hardware threads
    const std::atomic<bool>* cancel = nullptr;  // set (e.g. by Ctrl-C) to stop after the tile
    RenderObserver* observer = nullptr;         // progress reports; nullptr = none
    // Resuming from a checkpoint: the film already holds samples [0, startSample) of every
    // pixel. Each pixel's samples are added in index order whatever the waves and threads, so
    // a resumed render ends bit-identical to an uninterrupted one.
    int startSample = 0;
    // Called between waves (the film then holds samples [0, completed) of every pixel) once
    // checkpointSeconds have passed since the start or the last call; waves are kept short
    // enough (measured) that one takes at most a quarter of that.
    std::function<void(int completed)> checkpoint;
    double checkpointSeconds = 0;
    // Called after every wave, the last included (the film then holds samples [0, completed)
    // of every pixel): kiln --write-partial-images and --mse-reference-image
    std::function<void(int completed)> afterWave;
    // The largest wave, samples per pixel (64, as pbrt-v4; 1 for an error per sample count)
    int maxWaveSize = 64;
    // When > 0, waves are kept short enough (measured on the previous wave) that one takes about
    // this long, but never below one sample per pixel: kiln --display-server's update interval
    double waveSeconds = 0;
};

struct RenderStats {
    Point2i resolution;        // of the rendered (cropped) region
    int samplesPerPixel = 0;   // requested
    int completedSamples = 0;  // per pixel in fully finished waves
    double seconds = 0;        // wall time of the render loop
    int64_t cameraPaths = 0;   // pixel samples traced
    bool cancelled = false;
};

RenderStats Render(Scene& scene, const RenderSettings& settings);

}  // namespace kiln
