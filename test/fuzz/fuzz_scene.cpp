// libFuzzer target: whole scenes from arbitrary text, created (materials, textures, lights,
// emissivity tables, aggregate) and rendered at one sample per pixel over a few pixels. Every
// input must end in a SceneError or in an image with only finite pixels (Stokes layers too).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/parser/parser.h"
#include "render/renderer.h"
#include "render/scene_builder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    kiln::Diagnostics diag(nullptr);
    try {
        kiln::SceneBuilder builder(diag);
        kiln::ParseString(builder, text, diag, "fuzz.pbrt", "/nonexistent-kiln-fuzz");
        kiln::RenderOptions overrides;
        overrides.samplesPerPixel = 1;
        overrides.cropWindow = kiln::Bounds2f{{0.5f, 0.5f}, {0.51f, 0.51f}};
        std::unique_ptr<kiln::Scene> scene =
            kiln::Scene::Create(builder.Description(), overrides, diag);
        kiln::RenderSettings settings;
        settings.threads = 1;
        kiln::Render(*scene, settings);
        kiln::Bounds2i b = scene->job->film->PixelBounds();
        for (int y = b.pMin.y; y < b.pMax.y; ++y)
            for (int x = b.pMin.x; x < b.pMax.x; ++x) {
                for (int k = 0; k < 4; ++k) {  // RGB (k = 0) and Stokes layers, if any
                    kiln::RGB rgb = scene->job->film->GetPixelStokes({x, y}, k);
                    if (!std::isfinite(rgb.r) || !std::isfinite(rgb.g) || !std::isfinite(rgb.b))
                        __builtin_trap();  // a non-finite pixel is a bug to find, not to clamp
                }
            }
    } catch (const kiln::SceneError&) {
    }
    return 0;
}
