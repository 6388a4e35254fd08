// The render loop: pixel samples in parallel over image tiles (TBB), in waves of increasing
// sample counts so that an interrupted render still has every pixel sampled alike.
//
// Determinism: every sample value comes from the sampler seeded by (pixel, sample index,
// dimension), and each pixel is written by one task at a time, so the image is bit-identical
// for any number of threads.
#pragma once

#include <atomic>
#include <cstdint>
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
