// Camera creation from scene parameters (pbrt-v4 names and defaults).
#include "core/camera/camera.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/camera/aperture_mask.h"
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

// "spherical": the mapping; the projective parameters pbrt-v4 reads and ignores
Camera CreateSpherical(const ParameterDictionary& params, const CameraTransform& cameraTransform,
                       Float shutterOpen, Float shutterClose, Point2i fullResolution,
                       const FileLoc& loc, ObjectArena& arena, Diagnostics& diag) {
    for (const char* ignored : {"lensradius", "focaldistance", "frameaspectratio"})
        (void)params.GetOneFloat(ignored, 0);
    (void)params.GetFloatArray("screenwindow");
    std::string m = params.GetOneString("mapping", "equalarea");
    SphericalCamera::Mapping mapping;
    if (m == "equalarea")
        mapping = SphericalCamera::Mapping::EqualArea;
    else if (m == "equirectangular")
        mapping = SphericalCamera::Mapping::Equirectangular;
    else
        throw SceneError(
            params.Loc("mapping"),
            "unknown spherical camera mapping \"" + m +
                "\" (expected \"equalarea\" or \"equirectangular\")" +
                DidYouMean(m,
                           std::initializer_list<std::string_view>{"equalarea", "equirectangular"}),
            m);
    if (mapping == SphericalCamera::Mapping::EqualArea && fullResolution.x != fullResolution.y)
        diag.Warn(loc, "the \"equalarea\" mapping on a non-square film (" +
                           std::to_string(fullResolution.x) + "x" +
                           std::to_string(fullResolution.y) +
                           ") is stretched to the film: pixels no longer span equal solid angles "
                           "(as pbrt-v4)");
    return arena.New<SphericalCamera>(cameraTransform, shutterOpen, shutterClose, fullResolution,
                                      mapping);
}

// The realistic camera's stop mask: a built-in shape or an image file; empty if none
Image CreateApertureMask(const ParameterDictionary& params) {
    std::string name = params.GetOneString("aperture", "");
    if (name.empty()) return Image();
    std::optional<Image> mask = BuiltinApertureMask(name);
    if (!mask) {
        std::string filename = params.GetOneFilename("aperture", ""), error;
        Image image;
        try {
            image = Image::Read(filename, nullptr, ColorEncoding::SRGB());  // as pbrt-v4
        } catch (const std::exception& e) {
            throw SceneError(params.Loc("aperture"),
                             std::string(e.what()) +
                                 " (\"aperture\" names \"gaussian\", \"square\", "
                                 "\"pentagon\", \"star\" or an image file)",
                             name);
        }
        mask = ApertureMaskFromImage(image, &error);
        if (!mask) throw SceneError(params.Loc("aperture"), error, name);
    }
    if (!NormalizeApertureMask(&*mask))
        throw SceneError(params.Loc("aperture"), "aperture image must have a positive, finite mean",
                         name);
    return *mask;
}

// "realistic": the lens file, stop diameter, focus and aperture mask
Camera CreateRealistic(const ParameterDictionary& params, const CameraTransform& cameraTransform,
                       Float shutterOpen, Float shutterClose, Point2i fullResolution,
                       Float filmDiagonal, const FileLoc& loc, ObjectArena& arena,
                       Diagnostics& diag) {
    std::string lensFile = params.GetOneFilename("lensfile", "");
    Float apertureDiameter = params.GetOneFloat("aperturediameter", 1);
    Float focusDistance = params.GetOneFloat("focusdistance", 10);
    if (lensFile.empty())
        throw SceneError(loc, "the realistic camera needs a \"lensfile\"", "realistic");
    if (!(apertureDiameter > 0 && std::isfinite(apertureDiameter)))
        throw SceneError(params.Loc("aperturediameter"),
                         "\"aperturediameter\" must be positive and finite (mm)",
                         "aperturediameter");
    if (!(focusDistance > 0 && std::isfinite(focusDistance)))
        throw SceneError(params.Loc("focusdistance"),
                         "\"focusdistance\" must be positive and finite", "focusdistance");
    if (!(filmDiagonal > 0 && std::isfinite(filmDiagonal)))
        throw SceneError(loc, "the realistic camera needs a positive film \"diagonal\"",
                         "realistic");
    bool clamped = false;
    std::string error;
    std::optional<std::vector<LensInterface>> interfaces =
        ReadLensFile(lensFile, apertureDiameter, &clamped, &error);
    if (!interfaces) throw SceneError(params.Loc("lensfile"), error, lensFile);
    if (clamped)
        diag.Warn(params.Loc("aperturediameter"),
                  "\"aperturediameter\" " + std::to_string(apertureDiameter) +
                      " mm is larger than the lens's stop; using the stop's diameter");
    LensSystem lens(std::move(*interfaces), CreateApertureMask(params));
    if (!(lens.FrontZ() < kMaxRenderCoordinate / 2))
        throw SceneError(params.Loc("lensfile"),
                         "the lens would start rays beyond +-1e17 (render space), the range "
                         "kiln traces rays in",
                         lensFile);
    // Focus as pbrt-v4: paraxial rays at a thousandth of the film diagonal
    Float paraxialHeight = 0.001f * filmDiagonal;
    if (!lens.ThickLensApproximation(paraxialHeight))
        throw SceneError(params.Loc("lensfile"),
                         "a paraxial ray does not pass the lens system (is the stop extremely "
                         "small?)",
                         lensFile);
    std::optional<Float> rear = lens.FocusedRearThickness(focusDistance, paraxialHeight);
    if (!rear)
        throw SceneError(params.Loc("focusdistance", loc),
                         "\"focusdistance\" " + std::to_string(focusDistance) +
                             " is too short for this lens to focus",
                         "focusdistance");
    lens.SetRearThickness(*rear);
    return arena.New<RealisticCamera>(cameraTransform, shutterOpen, shutterClose, fullResolution,
                                      filmDiagonal, std::move(lens));
}

}  // namespace

Camera Camera::Create(const std::string& name, const ParameterDictionary& params,
                      const CameraTransform& cameraTransform, Point2i fullResolution,
                      Float filmDiagonal, const FileLoc& loc, ObjectArena& arena,
                      Diagnostics& diag) {
    const std::string& type = name;
    if (type != "perspective" && type != "orthographic" && type != "realistic" &&
        type != "spherical")
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
    if (type == "spherical")
        return CreateSpherical(params, cameraTransform, shutterOpen, shutterClose, fullResolution,
                               loc, arena, diag);
    if (type == "realistic")
        return CreateRealistic(params, cameraTransform, shutterOpen, shutterClose, fullResolution,
                               filmDiagonal, loc, arena, diag);

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
