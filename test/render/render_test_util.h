// Helpers for render tests: build and render a scene given as text or file, in process.
#pragma once

#include <memory>
#include <sstream>
#include <string>

#include "core/parser/parser.h"
#include "render/renderer.h"
#include "render/scene_builder.h"
#include "spectral/color.h"

namespace kiln::testing {

struct RenderedScene {
    std::unique_ptr<Scene> scene;
    RenderStats stats;
    std::vector<Diagnostics::Warning> warnings;
};

inline std::unique_ptr<Scene> BuildScene(const std::string& text, Diagnostics& diag,
                                         SceneOverrides overrides = {}) {
    SceneBuilder builder(diag);
    ParseString(builder, text, diag, "<test>");
    return Scene::Create(builder.Description(), overrides, diag);
}

inline RenderedScene RenderText(const std::string& text, int threads = 0,
                                SceneOverrides overrides = {}) {
    Diagnostics diag(nullptr);
    RenderedScene r;
    r.scene = BuildScene(text, diag, overrides);
    RenderSettings settings;
    settings.threads = threads;
    r.stats = Render(*r.scene, settings);
    r.warnings = diag.Warnings();
    return r;
}

inline RenderedScene RenderFile(const std::string& filename, SceneOverrides overrides = {}) {
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

// Luminance Y of a film pixel (colour space of the film).
inline Float PixelY(const Scene& scene, Point2i p) {
    RGB rgb = scene.film->GetPixelRGB(p);
    return scene.film->ColorSpace()->ToXYZ(rgb).Y;
}

}  // namespace kiln::testing
