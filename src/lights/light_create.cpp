// Light creation from scene parameters (pbrt-v4's Light::Create and Light::CreateArea), with
// pbrt-v4's parameter names, defaults and photometric normalisation (see light.h).
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "base/sphere_mappings.h"
#include "core/geometry/shape.h"
#include "core/image/image.h"
#include "core/parser/diagnostics.h"
#include "core/parser/parameter_dictionary.h"
#include "core/parser/suggestions.h"
#include "lights/light.h"
#include "spectral/color.h"
#include "spectral/planck.h"

namespace kiln {

namespace {

const RGBColorSpace& ColorSpaceOf(const ParameterDictionary& params) {
    const RGBColorSpace* cs = params.ColorSpace();
    return cs ? *cs : RGBColorSpace::sRGB();
}

// scale / luminance(s): "scale" then sets the luminance (left alone for a spectrum with no
// luminance, which emits nothing visible anyway).
Float PhotometricScale(Float scale, const Spectrum& s) {
    Float lum = EmissionLuminance(s);
    return lum > 0 ? scale / lum : scale;
}

// A light's brightest emission: its final scale (after "power" or "illuminance") times the
// largest values of its spectrum and of its image. Above kMaxEmission (spectral/planck.h), or
// not a number (an RGB beyond float's range), it is a SceneError at the first of the
// parameters that set it.
void CheckPeakEmission(double peak, const ParameterDictionary& params, const FileLoc& loc) {
    if (peak <= kMaxEmission) return;
    FileLoc at = loc;
    std::string token = "scale";
    for (const char* name : {"power", "illuminance", "scale", "L", "I", "filename"})
        if (params.Has(name)) {
            at = params.Loc(name);
            token = name;
            break;
        }
    char value[32] = "not a finite number";
    if (std::isfinite(peak)) std::snprintf(value, sizeof(value), "%g", peak);
    throw SceneError(at,
                     std::string("this light is too bright: its scale times the largest values "
                                 "of its spectrum and image is ") +
                         value +
                         ", beyond the 1e30 W m^-2 sr^-1 nm^-1 (W sr^-1 nm^-1 for point-like "
                         "lights) that kiln renders in single precision",
                     token);
}

// The largest value of an image's channels
double ImageMax(const Image& image) {
    double m = 0;
    Point2i res = image.Resolution();
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < image.NChannels(); ++c)
                m = std::max(m, double(image.GetChannel({x, y}, c)));
    return m;
}

// The transform taking local coordinates in frame f to the frame's space.
Transform FromFrame(const Frame& f) {
    SquareMatrix4 m;
    for (int i = 0; i < 3; ++i) {
        m.m[i][0] = f.x[i];
        m.m[i][1] = f.y[i];
        m.m[i][2] = f.z[i];
    }
    return Transform(m, m.Transposed());
}

// A pixel of an emission image: finite and at most kMaxEmission (with "power", the image's
// scale would not matter, but kiln's light scale would underflow), else a SceneError.
void CheckEmissionPixel(Float value, const FileLoc& loc, const std::string& filename) {
    if (!std::isfinite(value))
        throw SceneError(loc,
                         "image has infinite or not-a-number pixels and so is not suitable as a "
                         "light source",
                         filename);
    if (value > kMaxEmission)
        throw SceneError(loc,
                         "image has pixels above 1e30, beyond what kiln renders in single "
                         "precision; scale the image down (\"power\" or \"scale\" set the "
                         "light's brightness)",
                         filename);
}

// Reads an emission image, keeping its R, G, B channels, and the colour space its file names
// (sRGB if none, as pbrt-v4); SceneError if that fails. Negative values emit nothing (the
// lights clamp them), with a warning.
Image ReadEmissionImage(const std::string& filename, const FileLoc& loc,
                        const RGBColorSpace** colorSpace, MemoryBudget& budget, Diagnostics& diag) {
    Image image;
    ImageMetadata metadata;
    try {
        // 8-bit and 16-bit data as sRGB whatever a PNG's gAMA chunk says, as pbrt-v4 reads them
        image = Image::Read(filename, &metadata, ColorEncoding::SRGB(), &budget);
    } catch (const std::exception& e) {
        throw SceneError(loc, e.what(), filename);
    }
    if (image.ChannelIndex("R") < 0 || image.ChannelIndex("G") < 0 || image.ChannelIndex("B") < 0)
        throw SceneError(loc, "image used as a light source must have R, G and B channels",
                         filename);
    image = image.SelectChannels({"R", "G", "B"});
    Point2i res = image.Resolution();
    bool negative = false;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < 3; ++c) {
                CheckEmissionPixel(image.GetChannel({x, y}, c), loc, filename);
                negative |= image.GetChannel({x, y}, c) < 0;
            }
    if (negative) diag.Warn(loc, "a light's image has negative values; they emit nothing");
    *colorSpace = metadata.colorSpace ? metadata.colorSpace : &RGBColorSpace::sRGB();
    return image;
}

// Luminance of an RGB in colour space cs (the Y row of its RGB -> XYZ matrix), in double so
// that it does not overflow for RGBs near float's largest value.
double RGBLuminance(const RGBColorSpace& cs, Float r, Float g, Float b) {
    const ColorMatrix& m = cs.XYZFromRGB();
    return m[1][0] * double(r) + m[1][1] * double(g) + m[1][2] * double(b);
}

// Individual light kinds
Light CreatePoint(const ParameterDictionary& params, const Transform& renderFromLight,
                  const FileLoc& loc, ObjectArena& arena) {
    const RGBColorSpace& cs = ColorSpaceOf(params);
    Spectrum I = *params.GetOneSpectrum("I", Spectrum(cs.Illuminant()), SpectrumType::Illuminant);
    Float sc = PhotometricScale(params.GetOneFloat("scale", 1), I);
    Float phi_v = params.GetOneFloat("power", -1);
    if (phi_v > 0) sc *= phi_v / (4 * Pi);
    Point3f from = params.GetOnePoint3f("from", Point3f(0, 0, 0));
    Transform t = renderFromLight * Translate(Vector3f(from));
    CheckPeakEmission(double(sc) * I.MaxValue(), params, loc);
    return arena.New<PointLight>(t, std::move(I), sc);
}

Light CreateSpot(const ParameterDictionary& params, const Transform& renderFromLight,
                 const FileLoc& loc, ObjectArena& arena) {
    const RGBColorSpace& cs = ColorSpaceOf(params);
    Spectrum I = *params.GetOneSpectrum("I", Spectrum(cs.Illuminant()), SpectrumType::Illuminant);
    Float sc = PhotometricScale(params.GetOneFloat("scale", 1), I);
    Float coneangle = params.GetOneFloat("coneangle", 30);
    Float conedelta = params.GetOneFloat("conedeltaangle", 5);
    Point3f from = params.GetOnePoint3f("from", Point3f(0, 0, 0));
    Point3f to = params.GetOnePoint3f("to", Point3f(0, 0, 1));
    if (from == to)
        throw SceneError(params.Loc("to").line ? params.Loc("to") : params.Loc("from"),
                         "spot light: \"from\" and \"to\" must differ (they give its direction)",
                         "to");
    // Light space: origin at `from`, +z towards `to`
    Transform t =
        renderFromLight * Translate(Vector3f(from)) * FromFrame(Frame::FromZ(Normalize(to - from)));
    Float phi_v = params.GetOneFloat("power", -1);
    if (phi_v > 0) {
        Float k_e = SpotLight::ConeSolidAngle(std::cos(Radians(coneangle - conedelta)),
                                              std::cos(Radians(coneangle)));
        if (k_e > 0) sc *= phi_v / k_e;
    }
    CheckPeakEmission(double(sc) * I.MaxValue(), params, loc);
    return arena.New<SpotLight>(t, std::move(I), sc, coneangle, coneangle - conedelta);
}

Light CreateDistant(const ParameterDictionary& params, const Transform& renderFromLight,
                    const FileLoc& loc, ObjectArena& arena) {
    const RGBColorSpace& cs = ColorSpaceOf(params);
    Spectrum L = *params.GetOneSpectrum("L", Spectrum(cs.Illuminant()), SpectrumType::Illuminant);
    Float sc = PhotometricScale(params.GetOneFloat("scale", 1), L);
    Point3f from = params.GetOnePoint3f("from", Point3f(0, 0, 0));
    Point3f to = params.GetOnePoint3f("to", Point3f(0, 0, 1));
    if (from == to)
        throw SceneError(params.Loc("to").line ? params.Loc("to") : params.Loc("from"),
                         "distant light: \"from\" and \"to\" must differ (they give its "
                         "direction)",
                         "to");
    // Light space: +z points from `to` towards `from` (towards the light)
    Transform t = renderFromLight * FromFrame(Frame::FromZ(Normalize(from - to)));
    // Illuminance on a surface facing the light is scale * luminance(L)
    Float E_v = params.GetOneFloat("illuminance", -1);
    if (E_v > 0) sc *= E_v;
    CheckPeakEmission(double(sc) * L.MaxValue(), params, loc);
    return arena.New<DistantLight>(t, std::move(L), sc);
}

// "goniometric": a square equal-area map, one channel ("Y", or the mean of "R", "G", "B"),
// finite; negative values are clamped to 0 (warning). Without "filename", nullopt (warning,
// as pbrt-v4, whose light then emits nothing).
std::optional<Light> CreateGoniometric(const ParameterDictionary& params,
                                       const Transform& renderFromLight, const FileLoc& loc,
                                       ObjectArena& arena, Diagnostics& diag) {
    const RGBColorSpace& cs = ColorSpaceOf(params);
    Spectrum I = *params.GetOneSpectrum("I", Spectrum(cs.Illuminant()), SpectrumType::Illuminant);
    Float sc = PhotometricScale(params.GetOneFloat("scale", 1), I);
    Float phi_v = params.GetOneFloat("power", -1);
    std::string filename = params.GetOneFilename("filename", "");
    if (filename.empty()) {
        diag.Warn(loc, "a goniometric light without \"filename\" emits nothing; light ignored");
        return std::nullopt;
    }
    FileLoc at = params.Loc("filename", loc);
    Image file;
    ImageMetadata metadata;
    try {
        file = Image::Read(filename, &metadata, ColorEncoding::SRGB(), &arena.Budget());
    } catch (const std::exception& e) {
        throw SceneError(at, e.what(), filename);
    }
    Point2i res = file.Resolution();
    if (res.x != res.y)
        throw SceneError(at,
                         "a goniometric light's image must be a square equal-area map, not " +
                             std::to_string(res.x) + " x " + std::to_string(res.y) + " pixels",
                         filename);
    bool rgb =
        file.ChannelIndex("R") >= 0 && file.ChannelIndex("G") >= 0 && file.ChannelIndex("B") >= 0;
    int yChannel = file.ChannelIndex("Y");
    if (rgb == (yChannel >= 0))
        throw SceneError(at,
                         rgb ? "a goniometric light's image has both R, G, B and Y channels"
                             : "a goniometric light's image has neither R, G, B nor Y channels",
                         filename);
    std::vector<int> channels =
        rgb ? std::vector<int>{file.ChannelIndex("R"), file.ChannelIndex("G"),
                               file.ChannelIndex("B")}
            : std::vector<int>{yChannel};
    Image image(PixelFormat::Float, res, {"Y"});
    bool negative = false;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            double sum = 0;
            for (int c : channels) sum += file.GetChannel({x, y}, c);
            Float value = Float(sum / double(channels.size()));
            CheckEmissionPixel(value, at, filename);
            negative |= value < 0;
            image.SetChannel({x, y}, 0, std::max<Float>(0, value));
        }
    if (negative)
        diag.Warn(at, "a goniometric light's image has negative values; they emit nothing");
    if (phi_v > 0) {
        double k_e = 4 * Pi * double(image.Average(0));
        if (k_e > 0)
            sc = Float(sc * (phi_v / k_e));
        else
            diag.Warn(params.Loc("power", loc),
                      "\"power\" given for a goniometric light whose image is black; ignored");
    }
    CheckPeakEmission(double(sc) * I.MaxValue() * ImageMax(image), params, loc);
    return arena.New<GoniometricLight>(renderFromLight, std::move(I), sc, std::move(image));
}

// "projection": an R, G, B image in the colour space its file names (sRGB if none)
Light CreateProjection(const ParameterDictionary& params, const Transform& renderFromLight,
                       const FileLoc& loc, ObjectArena& arena, Diagnostics& diag) {
    Float scale = params.GetOneFloat("scale", 1);
    Float phi_v = params.GetOneFloat("power", -1);
    Float fov = params.GetOneFloat("fov", 90);
    std::string filename = params.GetOneFilename("filename", "");
    if (filename.empty())
        throw SceneError(loc, "a projection light needs an image: \"string filename\"",
                         "projection");
    // (Below 0.01 degrees the image's solid angle underflows single precision)
    if (!(fov >= 0.01f && fov < 180))
        throw SceneError(params.Loc("fov", loc),
                         "a projection light's \"fov\" must lie between 0.01 and 180 degrees",
                         std::to_string(fov));
    const RGBColorSpace* imageCS = &RGBColorSpace::sRGB();
    Image image =
        ReadEmissionImage(filename, params.Loc("filename", loc), &imageCS, arena.Budget(), diag);
    scale = PhotometricScale(scale, Spectrum(imageCS->Illuminant()));
    if (phi_v > 0) {
        double k_e = ProjectionLight::LuminousIntegral(image, *imageCS, fov);
        if (k_e > 0)
            scale = Float(scale * (phi_v / k_e));
        else
            diag.Warn(params.Loc("power", loc),
                      "\"power\" given for a projection light whose image is black; ignored");
    }
    CheckPeakEmission(double(scale) * imageCS->Illuminant().MaxValue() * ImageMax(image), params,
                      loc);
    return arena.New<ProjectionLight>(renderFromLight, std::move(image), imageCS, scale, fov);
}

// "portal": four corners in world space (as pbrt-v4, not in the light's space), in render
// space; a SceneError unless there are four of them, a warning unless they form a rectangle.
std::optional<std::array<Point3f, 4>> ReadPortal(const ParameterDictionary& params,
                                                 const Transform& renderFromWorld,
                                                 Diagnostics& diag) {
    std::vector<Point3f> p = params.GetPoint3fArray("portal");
    if (p.empty()) return std::nullopt;
    if (p.size() != 4)
        throw SceneError(
            params.Loc("portal"),
            "an infinite light's \"portal\" needs 4 corners, not " + std::to_string(p.size()),
            "portal");
    std::array<Point3f, 4> portal;
    for (int i = 0; i < 4; ++i) portal[size_t(i)] = renderFromWorld(p[size_t(i)]);
    auto dir = [&](int a, int b) {
        Vector3f d = portal[size_t(b)] - portal[size_t(a)];
        Float l = Length(d);
        return l > 0 ? d / l : Vector3f(0, 0, 0);
    };
    Vector3f p01 = dir(0, 1), p12 = dir(1, 2), p32 = dir(3, 2), p03 = dir(0, 3);
    if (std::abs(Dot(p01, p32) - 1) > .001f || std::abs(Dot(p12, p03) - 1) > .001f ||
        std::abs(Dot(p01, p12)) > .001f || std::abs(Dot(p12, p32)) > .001f ||
        std::abs(Dot(p32, p03)) > .001f || std::abs(Dot(p03, p01)) > .001f)
        diag.Warn(params.Loc("portal"),
                  "the infinite light's portal is not a planar rectangle (pbrt-v4 reports an "
                  "error and renders on)");
    return portal;
}

Light CreateInfinite(const ParameterDictionary& params, const Transform& renderFromLight,
                     const Transform& renderFromWorld, const FileLoc& loc, ObjectArena& arena,
                     Diagnostics& diag) {
    const RGBColorSpace& cs = ColorSpaceOf(params);
    std::optional<Spectrum> L = params.GetOneSpectrum("L", std::nullopt, SpectrumType::Illuminant);
    Float scale = params.GetOneFloat("scale", 1);
    std::string filename = params.GetOneFilename("filename", "");
    Float E_v = params.GetOneFloat("illuminance", -1);
    std::optional<std::array<Point3f, 4>> portal = ReadPortal(params, renderFromWorld, diag);
    if (L && !filename.empty())
        throw SceneError(loc,
                         "can't specify both emission \"L\" and \"filename\" for an "
                         "infinite light",
                         "infinite");

    // kiln: a sky at a temperature (kelvin), uniform blackbody radiance in absolute units:
    // B(lambda, T) times "scale", in W m^-2 sr^-1 nm^-1 as thermal emission
    if (params.Has("temperature")) {
        Float T = params.GetOneFloat("temperature", 0);
        FileLoc at = params.Loc("temperature", loc);
        if (!(T >= 0) || !(T <= kMaxRenderTemperature))
            throw SceneError(at,
                             "an infinite light's \"temperature\" must be kelvin from 0 to 1e27",
                             FormatKelvin(T));
        if (L || !filename.empty() || portal || E_v > 0)
            throw SceneError(at,
                             "an infinite light at a \"temperature\" takes no \"L\", \"filename\", "
                             "\"portal\" or \"illuminance\"",
                             "temperature");
        if (!(scale >= 0))
            throw SceneError(params.Loc("scale", at),
                             "an infinite light at a \"temperature\" needs \"scale\" >= 0",
                             std::to_string(scale));
        double peak = T > 0 ? planck_radiance(planck_peak_wavelength_nm(T), T) : 0;
        double skyScale = double(scale) * peak;
        if (!(skyScale < double(std::numeric_limits<Float>::max())))
            throw SceneError(at, "an infinite light this hot overflows single precision",
                             FormatKelvin(T));
        return arena.New<UniformInfiniteLight>(renderFromLight, Spectrum(BlackbodySpectrum(T)),
                                               Float(skyScale));
    }
    if (filename.empty() && !portal) {
        // Uniform: the given spectrum or the colour space's illuminant, luminance 1 * scale;
        // a uniform radiance L_v gives illuminance pi L_v on any surface
        Spectrum Le = L ? *L : Spectrum(cs.Illuminant());
        scale = PhotometricScale(scale, Le);
        if (E_v > 0) scale *= E_v / Pi;
        CheckPeakEmission(double(scale) * Le.MaxValue(), params, loc);
        return arena.New<UniformInfiniteLight>(renderFromLight, std::move(Le), scale);
    }

    // Environment map, in the colour space its file names; a uniform one behind a portal is a
    // one-pixel map of L's sRGB (as pbrt-v4, which warns for spectra other than RGB)
    const RGBColorSpace* imageCSp = &RGBColorSpace::sRGB();
    Image image;
    if (!filename.empty()) {
        image = ReadEmissionImage(filename, params.Loc("filename", loc), &imageCSp, arena.Budget(),
                                  diag);
    } else {
        Spectrum Le = L ? *L : Spectrum(cs.Illuminant());
        if (L && params.TypeOf("L") != "rgb")
            diag.Warn(params.Loc("L"),
                      "a portal light's \"L\" is converted to sRGB (as pbrt-v4 does): its "
                      "spectrum is approximated");
        RGB rgb = RGBColorSpace::sRGB().ToRGB(SpectrumToXYZ(Le));
        image = Image(PixelFormat::Float, {1, 1}, {"R", "G", "B"});
        for (int c = 0; c < 3; ++c) image.SetChannel({0, 0}, c, std::max<Float>(0, rgb[c]));
    }
    const RGBColorSpace& imageCS = *imageCSp;
    scale = PhotometricScale(scale, Spectrum(imageCS.Illuminant()));
    if (E_v > 0) {
        // Illuminance on an upward-facing (+z in light space) patch: sum of luminance cos theta
        // times each pixel's solid angle. (pbrt-v4 weights pixels with 2 pi / (w h) here
        // instead of their solid angle 4 pi / (w h), which doubles the illuminance it gives;
        // kiln gives the requested illuminance.)
        ImageInfiniteLight map(Transform(), image, &imageCS, 1, filename);
        Point2i res = image.Resolution();
        double k_e = 0;
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                Point2f st((x + 0.5f) / res.x, (y + 0.5f) / res.y);
                Vector3f w = map.DirectionFromST(st);
                if (w.z <= 0) continue;
                double lum = RGBLuminance(imageCS, image.GetChannel({x, y}, 0),
                                          image.GetChannel({x, y}, 1), image.GetChannel({x, y}, 2));
                k_e += lum * w.z * map.SolidAnglePerUnitST(w);
            }
        k_e /= double(res.x) * res.y;
        if (k_e > 0) scale *= Float(E_v / k_e);
    }
    CheckPeakEmission(double(scale) * imageCS.Illuminant().MaxValue() * ImageMax(image), params,
                      loc);
    try {
        if (portal)
            return arena.New<PortalInfiniteLight>(renderFromLight, image, &imageCS, scale, *portal);
        return arena.New<ImageInfiniteLight>(renderFromLight, image, &imageCS, scale, filename);
    } catch (const std::invalid_argument& e) {
        throw SceneError(loc, e.what(), filename);
    }
}

}  // namespace

// Light::Create
std::optional<Light> Light::Create(const std::string& name, const ParameterDictionary& params,
                                   const Transform& renderFromLight, const FileLoc& loc,
                                   ObjectArena& arena, Diagnostics& diag,
                                   const Transform& renderFromWorld) {
    std::optional<Light> light;
    if (name == "point")
        light = CreatePoint(params, renderFromLight, loc, arena);
    else if (name == "spot")
        light = CreateSpot(params, renderFromLight, loc, arena);
    else if (name == "distant")
        light = CreateDistant(params, renderFromLight, loc, arena);
    else if (name == "infinite")
        light = CreateInfinite(params, renderFromLight, renderFromWorld, loc, arena, diag);
    else if (name == "goniometric")
        light = CreateGoniometric(params, renderFromLight, loc, arena, diag);
    else if (name == "projection")
        light = CreateProjection(params, renderFromLight, loc, arena, diag);
    else
        throw SceneError(
            loc,
            "unknown light type \"" + name + "\"" +
                DidYouMean(name, std::initializer_list<std::string_view>{"point", "spot", "distant",
                                                                         "infinite", "goniometric",
                                                                         "projection"}),
            name);
    params.ReportUnused(diag);
    return light;
}

// Light::CreateArea
Light Light::CreateArea(const std::string& name, const ParameterDictionary& params,
                        const Transform& renderFromLight, const Shape& shape, const FileLoc& loc,
                        ObjectArena& arena, Diagnostics& diag, const AlphaMask* alpha) {
    if (name != "diffuse") throw SceneError(loc, "unknown area light type", name);

    const RGBColorSpace& cs = ColorSpaceOf(params);
    std::optional<Spectrum> L = params.GetOneSpectrum("L", std::nullopt, SpectrumType::Illuminant);
    Float scale = params.GetOneFloat("scale", 1);
    bool twoSided = params.GetOneBool("twosided", false);
    std::string filename = params.GetOneFilename("filename", "");

    // Emission from an image over (u, v), or a spectrum (default: the colour space's white)
    Image image;
    const RGBColorSpace* imageCS = nullptr;
    if (!filename.empty()) {
        if (L)
            throw SceneError(loc, "both \"L\" and \"filename\" specified for a diffuse area light",
                             filename);
        image = ReadEmissionImage(filename, loc, &imageCS, arena.Budget(), diag);
    }
    Spectrum Le = L ? *L : Spectrum(cs.Illuminant());
    scale = PhotometricScale(scale, image ? Spectrum(imageCS->Illuminant()) : Le);

    // "power": the luminous power of the emission over the whole shape, per pbrt-v4
    Float phi_v = params.GetOneFloat("power", -1);
    if (phi_v > 0) {
        double k_e = 1;
        if (image) {
            Point2i res = image.Resolution();
            double sum = 0;
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x)
                    sum += RGBLuminance(*imageCS, image.GetChannel({x, y}, 0),
                                        image.GetChannel({x, y}, 1), image.GetChannel({x, y}, 2));
            k_e = sum / (double(res.x) * res.y);
        }
        k_e *= (twoSided ? 2 : 1) * double(shape.Area()) * Pi;
        if (k_e > 0)
            scale = Float(scale * (phi_v / k_e));
        else
            diag.Warn(loc,
                      "\"power\" given for an area light that emits nothing (zero area or "
                      "black emission); ignored");
    }

    CheckPeakEmission(double(scale) * (image ? imageCS->Illuminant().MaxValue() * ImageMax(image)
                                             : Le.MaxValue()),
                      params, loc);
    const Shape* s = arena.New<Shape>(shape);
    Light light = arena.New<DiffuseAreaLight>(renderFromLight, std::move(Le), scale, s, twoSided,
                                              std::move(image), imageCS, alpha);
    params.ReportUnused(diag);
    return light;
}

}  // namespace kiln
