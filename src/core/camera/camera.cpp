// Camera creation from scene parameters (pbrt-v4 names and defaults).
#include "core/camera/camera.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/parser/parameter_dictionary.h"
#include "core/parser/suggestions.h"

namespace kiln {

namespace {

// Default screen window: [-1,1] along the shorter image axis, the aspect ratio along the other.
Bounds2f ScreenWindow(const ParameterDictionary& params, Point2i fullResolution) {
    Float frame =
        params.GetOneFloat("frameaspectratio", Float(fullResolution.x) / Float(fullResolution.y));
    if (!(frame > 0))
        throw SceneError(params.Loc("frameaspectratio"), "\"frameaspectratio\" must be positive");
    Bounds2f screen;
    if (frame > 1) {
        screen.pMin = Point2f(-frame, -1);
        screen.pMax = Point2f(frame, 1);
    } else {
        screen.pMin = Point2f(-1, -1 / frame);
        screen.pMax = Point2f(1, 1 / frame);
    }
    std::vector<Float> sw = params.GetFloatArray("screenwindow");
    if (!sw.empty()) {
        if (sw.size() != 4)
            throw SceneError(params.Loc("screenwindow"),
                             "\"screenwindow\" should have four values");
        screen.pMin = Point2f(sw[0], sw[2]);
        screen.pMax = Point2f(sw[1], sw[3]);
        // Raster coordinates divide by the window's width and height
        Float w = std::abs(screen.pMax.x - screen.pMin.x),
              h = std::abs(screen.pMax.y - screen.pMin.y);
        if (!(std::isfinite(w) && std::isfinite(h) && std::isfinite(1 / w) && std::isfinite(1 / h)))
            throw SceneError(params.Loc("screenwindow"),
                             "\"screenwindow\" is degenerate or not finite");
    }
    return screen;
}

}  // namespace

Camera Camera::Create(const std::string& name, const ParameterDictionary& params,
                      const CameraTransform& cameraTransform, Point2i fullResolution,
                      const FileLoc& loc, ObjectArena& arena, Diagnostics& diag) {
    std::string type = name;
    if (type == "realistic" || type == "spherical") {
        diag.Warn(loc, "\"" + name + "\" camera is not supported; using \"perspective\"");
        type = "perspective";
    }
    if (type != "perspective" && type != "orthographic")
        throw SceneError(
            loc,
            "unknown camera type \"" + name + "\"" +
                DidYouMean(name,
                           std::initializer_list<std::string_view>{"perspective", "orthographic",
                                                                   "realistic", "spherical"}),
            name);
    if (fullResolution.x <= 0 || fullResolution.y <= 0)
        throw SceneError(loc, "film resolution must be positive");

    // Common parameters
    Float shutterOpen = params.GetOneFloat("shutteropen", 0.f);
    Float shutterClose = params.GetOneFloat("shutterclose", 1.f);
    if (shutterClose < shutterOpen) {
        diag.Warn(loc, "shutter close time " + std::to_string(shutterClose) + " < shutter open " +
                           std::to_string(shutterOpen) + ". Swapping them.");
        std::swap(shutterOpen, shutterClose);
    }
    Float lensRadius = params.GetOneFloat("lensradius", 0.f);
    Float focalDistance = params.GetOneFloat("focaldistance", 1e6f);
    if (!(lensRadius >= 0 && std::isfinite(lensRadius)))
        throw SceneError(params.Loc("lensradius"),
                         "\"lensradius\" must be finite and not negative");
    if (lensRadius > 0 && !(focalDistance > 0 && std::isfinite(focalDistance)))
        throw SceneError(params.Loc("focaldistance"),
                         "\"focaldistance\" must be finite and positive");
    Bounds2f screen = ScreenWindow(params, fullResolution);
    // Rays start on the lens around the camera (perspective) or on the screen window
    // (orthographic); they must start within the range kiln traces rays in
    Float reach = lensRadius;
    if (type == "orthographic")
        reach += std::max({std::abs(screen.pMin.x), std::abs(screen.pMax.x),
                           std::abs(screen.pMin.y), std::abs(screen.pMax.y)});
    Bounds3f start(Point3f(-reach, -reach, 0), Point3f(reach, reach, 0));
    if (!InRenderRange(cameraTransform.RenderFromCamera()(start))) {
        const char* cause = lensRadius > kMaxRenderCoordinate / 2 ? "lensradius"
                            : params.Has("screenwindow")          ? "screenwindow"
                                                                  : nullptr;
        throw SceneError(cause ? params.Loc(cause) : loc,
                         "camera rays would start beyond +-1e17 (render space), the range kiln "
                         "traces rays in",
                         cause ? cause : name);
    }

    if (type == "orthographic")
        return arena.New<OrthographicCamera>(cameraTransform, shutterOpen, shutterClose, screen,
                                             fullResolution, lensRadius, focalDistance);
    Float fov = params.GetOneFloat("fov", 90.f);
    if (!(fov > 0 && fov < 180))
        throw SceneError(params.Loc("fov"), "\"fov\" must be between 0 and 180 degrees");
    return arena.New<PerspectiveCamera>(cameraTransform, shutterOpen, shutterClose, fov, screen,
                                        fullResolution, lensRadius, focalDistance);
}

}  // namespace kiln
