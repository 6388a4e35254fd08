// Helpers for the stress and hostile-input tests: render a scene given as text and count what
// is not finite.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "../render/render_test_util.h"

namespace kiln::testing {

struct ImageStats {
    int64_t nonFinite = 0;    // radiance samples the film rejected
    int nonFinitePixels = 0;  // pixels whose luminance is not finite
    double meanY = 0;         // mean luminance of the finite pixels over all pixels
    std::vector<std::string> warnings;
};

inline ImageStats RenderStats(const std::string& text, int seed = 1, int spp = 16) {
    RenderOptions o;
    o.seed = seed;
    o.samplesPerPixel = spp;
    RenderedScene r = RenderText(text, 0, o);
    ImageStats s;
    s.nonFinite = r.scene->job->film->NonFiniteSampleCount();
    Bounds2i b = r.scene->job->film->PixelBounds();
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
        for (int x = b.pMin.x; x < b.pMax.x; ++x) {
            Float Y = PixelY(*r.scene, {x, y});
            if (!std::isfinite(Y))
                ++s.nonFinitePixels;
            else
                s.meanY += Y;
        }
    s.meanY /= double(b.Area());
    for (const auto& w : r.warnings) s.warnings.push_back(w.message);
    return s;
}

// An environment light and a diffuse floor at y = 0, 10 x 10 around the origin.
inline const char* kEnvAndFloor = R"(
LightSource "infinite" "rgb L" [0.4 0.45 0.5]
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
  "point3 P" [-5 0 -5  5 0 -5  5 0 5  -5 0 5]
)";

}  // namespace kiln::testing
