// RGBFilm: creation from scene parameters, sample accumulation and output.
#include "core/film/film.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "base/system_memory.h"
#include "core/film/thermal_colormap.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {

// RGBFilm Creation
RGBFilm* RGBFilm::Create(const std::string& type, const ParameterDictionary& params,
                         Float exposureTime, const Filter& filter, const RGBColorSpace* colorSpace,
                         const FileLoc& loc, ObjectArena& arena, Diagnostics& diag,
                         const Request& request) {
    if (!colorSpace) colorSpace = &RGBColorSpace::sRGB();
    Options o;
    if (type != "rgb" && type != "gbuffer" && type != "spectral" && type != "thermal")
        diag.Warn(loc, "film \"" + type + "\" is not supported; using \"rgb\"");
    o.filename = params.GetOneString("filename", "pbrt.exr");
    if (type == "thermal") {
        o.thermal = ThermalSensor::Create(params, loc);
        if (std::string why = ThermalOutputFormatProblem(o.filename); !why.empty())
            throw SceneError(params.Loc("filename", loc), why, o.filename);
        if (params.GetOneBool("writeaovs", false))
            throw SceneError(params.Loc("writeaovs"),
                             "the thermal film does not record \"writeaovs\"", "writeaovs");
        if (params.GetOneFloat("exposure", 0) != 0)
            throw SceneError(params.Loc("exposure"),
                             "the thermal film records radiance and temperature, without "
                             "\"exposure\"",
                             "exposure");
    }
    if (type == "spectral") {
        o.spectralBuckets = params.GetOneInt("nbuckets", 16);
        o.lambdaMin = params.GetOneFloat("lambdamin", Lambda_min);
        o.lambdaMax = params.GetOneFloat("lambdamax", Lambda_max);
        if (o.spectralBuckets < 1 || o.spectralBuckets > 4096)
            throw SceneError(params.Loc("nbuckets", loc),
                             "the spectral film's \"nbuckets\" must be 1 to 4096",
                             std::to_string(o.spectralBuckets));
        if (!(o.lambdaMin >= Lambda_min && o.lambdaMax <= Lambda_max && o.lambdaMin < o.lambdaMax))
            throw SceneError(params.Loc("lambdamin", params.Loc("lambdamax", loc)),
                             "the spectral film's wavelengths must satisfy 360 <= \"lambdamin\" "
                             "< \"lambdamax\" <= 830 (nm)",
                             "lambdamin");
        if (FileExtension(o.filename) != "exr")
            throw SceneError(params.Loc("filename", loc),
                             "EXR is the only output format of the spectral film", o.filename);
    }
    o.fullResolution =
        Point2i(params.GetOneInt("xresolution", 1280), params.GetOneInt("yresolution", 720));
    FileLoc resolutionLoc = params.Has("xresolution")   ? params.Loc("xresolution")
                            : params.Has("yresolution") ? params.Loc("yresolution")
                                                        : loc;
    if (o.fullResolution.x <= 0 || o.fullResolution.y <= 0)
        throw SceneError(resolutionLoc, "film resolution must be positive", "xresolution");
    // Sample indices and sampler hierarchies (zsobol's Morton codes) need each side to fit in
    // 2^24 pixels, far beyond any camera
    if (std::max(o.fullResolution.x, o.fullResolution.y) > RGBFilm::kMaxFilmSide)
        throw SceneError(resolutionLoc,
                         "film resolution " + std::to_string(o.fullResolution.x) + " x " +
                             std::to_string(o.fullResolution.y) + " exceeds " +
                             std::to_string(RGBFilm::kMaxFilmSide) + " pixels on a side",
                         "xresolution");
    Point2i full = o.fullResolution;
    Bounds2i bounds{{0, 0}, full};
    auto clampToFull = [&](Bounds2i b, const FileLoc& at) {
        Bounds2i c{{std::max(b.pMin.x, 0), std::max(b.pMin.y, 0)},
                   {std::min(b.pMax.x, full.x), std::min(b.pMax.y, full.y)}};
        if (c.pMin != b.pMin || c.pMax != b.pMax)
            diag.Warn(at, "Supplied pixel bounds extend beyond image resolution. Clamping.");
        return c;
    };

    // Pixel bounds: the request's pixel bounds (which replace the scene's crop window and pixel
    // bounds), else "pixelbounds", then the request's or the scene's crop window (which wins,
    // as in pbrt-v4).
    std::vector<int> pb = params.GetIntArray("pixelbounds");
    std::vector<Float> cr = params.GetFloatArray("cropwindow");
    if (request.pixelBounds) {
        const Bounds2i& b = *request.pixelBounds;
        pb = {b.pMin.x, b.pMax.x, b.pMin.y, b.pMax.y};
        cr.clear();
    } else if (request.cropWindow) {
        const Bounds2f& c = *request.cropWindow;
        cr = {c.pMin.x, c.pMax.x, c.pMin.y, c.pMax.y};
    }
    // Where a bad value is reported: the scene's parameter, or the film for a request
    auto where = [&](const char* name, bool requested) {
        return !requested && params.Has(name) ? params.Loc(name) : loc;
    };
    FileLoc pbLoc = where("pixelbounds", request.pixelBounds.has_value());
    FileLoc crLoc = where("cropwindow", request.cropWindow.has_value());
    if (!pb.empty()) {
        if (pb.size() != 4)
            throw SceneError(
                pbLoc,
                std::to_string(pb.size()) + " values supplied for \"pixelbounds\". Expected 4.",
                "pixelbounds");
        bounds = clampToFull(Bounds2i{{pb[0], pb[2]}, {pb[1], pb[3]}}, pbLoc);
    }
    if (!cr.empty()) {
        FileLoc at = crLoc;
        if (cr.size() != 4)
            throw SceneError(
                at, std::to_string(cr.size()) + " values supplied for \"cropwindow\". Expected 4.",
                "cropwindow");
        if (!pb.empty())
            diag.Warn(at,
                      "Both pixel bounds and crop window were specified. Using the crop "
                      "window.");
        Float x0 = std::min(cr[0], cr[1]), x1 = std::max(cr[0], cr[1]);
        Float y0 = std::min(cr[2], cr[3]), y1 = std::max(cr[2], cr[3]);
        if (x0 < 0 || y0 < 0 || x1 > 1 || y1 > 1) {
            diag.Warn(at,
                      "Film crop window is not in [0,1] range; did you mean to use "
                      "\"pixelbounds\"? Clamping to valid range.");
            x0 = Clamp(x0, 0, 1), x1 = Clamp(x1, 0, 1), y0 = Clamp(y0, 0, 1), y1 = Clamp(y1, 0, 1);
        }
        bounds = Bounds2i{{int(std::ceil(full.x * x0)), int(std::ceil(full.y * y0))},
                          {int(std::ceil(full.x * x1)), int(std::ceil(full.y * y1))}};
    }
    if (bounds.IsEmpty())
        throw SceneError(!cr.empty()   ? crLoc
                         : !pb.empty() ? pbLoc
                                       : loc,
                         "Degenerate pixel bounds provided to film",
                         !cr.empty() ? "cropwindow" : "pixelbounds");
    o.pixelBounds = bounds;
    // The pixels rendered must fit in memory (checked before anything is allocated)
    const bool aovs = params.GetOneBool("writeaovs", type == "gbuffer");
    const bool stokes = request.stokes.value_or(params.GetOneBool("stokes", false));
    const double bytes =
        double(bounds.Area()) * RGBFilm::BytesPerPixel(aovs, stokes, o.spectralBuckets);
    const std::string what = "a film of " + std::to_string(bounds.pMax.x - bounds.pMin.x) + " x " +
                             std::to_string(bounds.pMax.y - bounds.pMin.y) + " pixels";
    if (bounds.Area() > std::numeric_limits<int32_t>::max())
        throw SceneError(resolutionLoc,
                         what + " needs " + FormatBytes(bytes) +
                             " and has more than the 2^31 pixels kiln renders at once",
                         "xresolution");
    try {
        arena.Budget().Charge(bytes, what);
    } catch (const MemoryLimitError& e) {
        throw SceneError(resolutionLoc, e.what(), "xresolution");
    }

    // Half floats would round a temperature near 300 K to 0.25 K and near 3000 K to 2 K: a
    // thermal film writes 32-bit floats unless told otherwise
    o.savefp16 = params.GetOneBool("savefp16", !o.thermal);
    o.maxComponentValue = params.GetOneFloat("maxcomponentvalue", Infinity);
    o.diagonal = params.GetOneFloat("diagonal", 35) * 0.001f;
    if (!(o.diagonal > 0 && std::isfinite(o.diagonal)))
        throw SceneError(params.Loc("diagonal"),
                         "film \"diagonal\" must be positive and finite (mm)", "diagonal");
    o.exposureEV = params.GetOneFloat("exposure", 0);
    if (!(std::abs(o.exposureEV) <= kMaxExposureEV))
        throw SceneError(
            params.Loc("exposure"),
            "film \"exposure\" must be within +-" + std::to_string(int(kMaxExposureEV)) + " stops",
            "exposure");
    o.view = params.GetOneString("view", "Standard");
    if (o.view != "Standard" && o.view != "Filmic" && o.view != "ACES" && o.view != "Glow" &&
        o.view != "Raw")
        throw SceneError(
            params.Loc("view"),
            "unknown view \"" + o.view +
                "\" (expected \"Standard\", \"Filmic\", \"ACES\", \"Glow\" or \"Raw\")",
            o.view);
    o.writeAOVs = aovs;
    Transform outputFromRender;
    if (aovs) {
        std::string space = params.GetOneString("coordinatesystem", "camera");
        if (space == "camera") {
            o.aovSpace = GBufferLayers::Space::Camera;
            outputFromRender = request.cameraFromRender;
        } else if (space == "world") {
            o.aovSpace = GBufferLayers::Space::World;
            outputFromRender = request.worldFromRender;
        } else {
            throw SceneError(params.Loc("coordinatesystem"),
                             "unknown coordinate system \"" + space +
                                 "\" for the gbuffer film (expected \"camera\" or \"world\")",
                             space);
        }
    }
    o.stokes = stokes;
    // Pixel reconstruction: spread, except on a film with AOV layers (their per-pixel
    // statistics, Variance and RelativeVariance, are of the pixel's own samples in pbrt-v4),
    // without jitter (every sample at its pixel's centre), or with a filter wider than
    // kMaxSpreadRadius or narrower than its pixel (radius below 1/2: most samples spread
    // uniformly over the pixel would reach no pixel centre)
    std::string reconstruction =
        params.GetOneString("reconstruction", aovs ? "importance" : "spread");
    if (reconstruction != "spread" && reconstruction != "importance")
        throw SceneError(params.Loc("reconstruction"),
                         "unknown reconstruction \"" + reconstruction +
                             "\" (expected \"spread\" or \"importance\")",
                         reconstruction);
    Vector2f radius = filter.Radius();
    o.reconstruction = request.reconstruction.value_or(reconstruction == "spread"
                                                           ? PixelReconstruction::Spread
                                                           : PixelReconstruction::FilterImportance);
    if (!request.pixelJitter.value_or(true) || radius.x > kMaxSpreadRadius ||
        radius.y > kMaxSpreadRadius || radius.x < 0.5f || radius.y < 0.5f)
        o.reconstruction = PixelReconstruction::FilterImportance;
    // A thermal film's "sensor" is its band (ThermalSensor); its pixel sensor is not used
    PixelSensor sensor = o.thermal
                             ? PixelSensor(colorSpace, 0, 1)
                             : PixelSensor::Create(params, colorSpace, exposureTime, loc, diag);
    return arena.New<RGBFilm>(o, sensor, filter, colorSpace, outputFromRender);
}

// RGBFilm Method Definitions
RGBFilm::RGBFilm(const Options& options, const PixelSensor& sensor, const Filter& filter,
                 const RGBColorSpace* cs, const Transform& outputFromRender)
    : opts(options), sensor(sensor), filter(filter), colorSpace(cs ? cs : &RGBColorSpace::sRGB()) {
    outputRGBFromSensorRGB = opts.thermal ? ColorMatrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}
                                          : Mul(colorSpace->RGBFromXYZ(), sensor.XYZFromSensorRGB);
    size_t n = size_t(std::max<int64_t>(0, opts.pixelBounds.Area()));
    pixels.resize(n);
    if (opts.writeAOVs) aovs = GBufferLayers(n, outputFromRender);
    if (opts.stokes) stokesPixels.resize(n);
    if (opts.spectralBuckets > 0)
        buckets = SpectralBuckets(n, opts.spectralBuckets, opts.lambdaMin, opts.lambdaMax);
}

Bounds2f RGBFilm::SampleBounds() const {
    Vector2f r = filter.Radius();
    const Bounds2i& b = opts.pixelBounds;
    return Bounds2f{Point2f(b.pMin.x - r.x + 0.5f, b.pMin.y - r.y + 0.5f),
                    Point2f(b.pMax.x + r.x - 0.5f, b.pMax.y + r.y - 0.5f)};
}

size_t RGBFilm::PixelIndex(Point2i p) const {
    const Bounds2i& b = opts.pixelBounds;
    return size_t(p.y - b.pMin.y) * size_t(b.pMax.x - b.pMin.x) + size_t(p.x - b.pMin.x);
}

void RGBFilm::EnableSplats() {
    if (splats.empty()) splats = std::vector<std::atomic<double>>(3 * pixels.size());
    if (!buckets.Empty()) buckets.EnableSplats();
}

void RGBFilm::AddSplat(Point2f pFilm, const SampledSpectrum& L, const SampledWavelengths& lambda) {
    auto reject = [&] { nonFiniteCount.fetch_add(1, std::memory_order_relaxed); };
    if (!L.IsFinite() || !std::isfinite(pFilm.x) || !std::isfinite(pFilm.y)) return reject();
    RGB rgb = Response(L, lambda);
    if (!std::isfinite(rgb.r) || !std::isfinite(rgb.g) || !std::isfinite(rgb.b)) return reject();
    Float m = std::max({rgb.r, rgb.g, rgb.b});
    if (m > opts.maxComponentValue) rgb = rgb * (opts.maxComponentValue / m);
    Float lm = L.MaxComponentValue();
    SampledSpectrum Lb = lm > opts.maxComponentValue ? L * (opts.maxComponentValue / lm) : L;
    // Pixels whose centres lie within the filter's radius of pFilm, inside the pixel bounds
    Vector2f r = filter.Radius();
    Point2f pd(pFilm.x + 0.5f, pFilm.y + 0.5f);
    const Bounds2i& b = opts.pixelBounds;
    int x0 = std::max(b.pMin.x, int(std::floor(pd.x - r.x)));
    int x1 = std::min(b.pMax.x, int(std::floor(pd.x + r.x)) + 1);
    int y0 = std::max(b.pMin.y, int(std::floor(pd.y - r.y)));
    int y1 = std::min(b.pMax.y, int(std::floor(pd.y + r.y)) + 1);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            Float wt = filter.Evaluate(Point2f(pFilm.x - x - 0.5f, pFilm.y - y - 0.5f));
            if (wt == 0) continue;
            size_t i = 3 * PixelIndex({x, y});
            for (int c = 0; c < 3; ++c) {
                std::atomic<double>& a = splats[i + size_t(c)];
                double v = a.load(std::memory_order_relaxed);
                while (
                    !a.compare_exchange_weak(v, v + double(wt) * rgb[c], std::memory_order_relaxed))
                    ;
            }
            if (!buckets.Empty()) buckets.AddSplat(PixelIndex({x, y}), Lb, lambda, wt);
        }
}

RGB RGBFilm::GetPixelRGB(Point2i p) const {
    const Pixel& px = pixels[PixelIndex(p)];
    RGB rgb(0, 0, 0);
    if (px.weightSum != 0)
        rgb = RGB(Float(px.rgbSum[0] / px.weightSum), Float(px.rgbSum[1] / px.weightSum),
                  Float(px.rgbSum[2] / px.weightSum));
    if (!splats.empty()) {
        size_t i = 3 * PixelIndex(p);
        double s = splatScale / double(filter.Integral());
        for (int c = 0; c < 3; ++c) rgb[c] += Float(s * splats[i + size_t(c)].load());
    }
    if (opts.thermal) return rgb;  // in-band radiance, unscaled
    return Mul(outputRGBFromSensorRGB, rgb) * std::exp2(opts.exposureEV);
}

RGB RGBFilm::GetPixelStokes(Point2i p, int k) const {
    if (k == 0) return GetPixelRGB(p);
    const Pixel& px = pixels[PixelIndex(p)];
    if (px.weightSum == 0 || stokesPixels.empty()) return RGB(0, 0, 0);
    const double* sum = stokesPixels[PixelIndex(p)].rgbSum[k - 1];
    RGB rgb(Float(sum[0] / px.weightSum), Float(sum[1] / px.weightSum),
            Float(sum[2] / px.weightSum));
    return Mul(outputRGBFromSensorRGB, rgb) * std::exp2(opts.exposureEV);
}

std::optional<Point2i> RGBFilm::FirstNonFinitePixel() const {
    int64_t i = firstNonFinite.load();
    if (i < 0) return std::nullopt;
    int w = opts.pixelBounds.pMax.x - opts.pixelBounds.pMin.x;
    return Point2i(opts.pixelBounds.pMin.x + int(i % w), opts.pixelBounds.pMin.y + int(i / w));
}

Image RGBFilm::GetImage(ImageMetadata* metadata) const {
    const Bounds2i& b = opts.pixelBounds;
    Point2i res(b.pMax.x - b.pMin.x, b.pMax.y - b.pMin.y);
    if (opts.thermal) {
        // In-band radiance and the temperature the sensor reports; with "stokes" the in-band
        // Stokes components S0 (= L) ... S3
        std::vector<std::string> names = {"L", "T"};
        if (!stokesPixels.empty()) names.insert(names.end(), {"S0", "S1", "S2", "S3"});
        Image image(PixelFormat::Float, res, names);
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                Point2i p(x + b.pMin.x, y + b.pMin.y);
                Float L = GetPixelRGB(p).r;
                image.SetChannel({x, y}, 0, L);
                image.SetChannel({x, y}, 1, Float(opts.thermal->ApparentTemperature(L)));
                if (stokesPixels.empty()) continue;
                image.SetChannel({x, y}, 2, L);
                for (int k = 1; k < 4; ++k) image.SetChannel({x, y}, 2 + k, GetPixelStokes(p, k).r);
            }
        if (metadata) {
            metadata->pixelBounds = b;
            metadata->fullResolution = opts.fullResolution;
            metadata->colorSpace = colorSpace;
        }
        return image;
    }
    std::vector<std::string> names = {"R", "G", "B"};
    if (!aovs.Empty())
        names.insert(names.end(), GBufferLayers::ChannelNames().begin(),
                     GBufferLayers::ChannelNames().end());
    const int stokesChannel = int(names.size());
    if (!stokesPixels.empty())
        names.insert(names.end(), {"S0.R", "S0.G", "S0.B", "S1.R", "S1.G", "S1.B", "S2.R", "S2.G",
                                   "S2.B", "S3.R", "S3.G", "S3.B"});
    const int bucketChannel = int(names.size());
    if (!buckets.Empty()) {
        std::vector<std::string> b = buckets.ChannelNames();
        names.insert(names.end(), b.begin(), b.end());
    }
    const double splatFactor = splatScale / double(filter.Integral());
    Image image(PixelFormat::Float, res, names);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            Point2i p(x + b.pMin.x, y + b.pMin.y);
            RGB rgb = GetPixelRGB(p);
            for (int c = 0; c < 3; ++c) image.SetChannel({x, y}, c, rgb[c]);
            if (!stokesPixels.empty())
                for (int k = 0; k < 4; ++k) {
                    RGB s = k == 0 ? rgb : GetPixelStokes(p, k);
                    for (int c = 0; c < 3; ++c)
                        image.SetChannel({x, y}, stokesChannel + 3 * k + c, s[c]);
                }
            size_t i = PixelIndex(p);
            for (int k = 0; k < buckets.NBuckets(); ++k)
                image.SetChannel({x, y}, bucketChannel + k,
                                 buckets.Value(i, k, pixels[i].weightSum, splatFactor));
            if (aovs.Empty()) continue;
            aovs.WritePixel(image, {x, y}, 3, i, pixels[i].weightSum);
        }
    if (metadata) {
        metadata->pixelBounds = b;
        metadata->fullResolution = opts.fullResolution;
        metadata->colorSpace = colorSpace;
    }
    return image;
}

void RGBFilm::WriteImage(const std::string& filename, ImageMetadata metadata,
                         const std::string& viewOverride, Diagnostics* diag) const {
    Image image = GetImage(&metadata);
    std::string ext = FileExtension(filename);
    // A part of the frame (crop window, pixel bounds: a tile for kiln merge) is written in
    // 32-bit float, so that merging loses nothing; the film's choice goes with it, for the merge
    // to apply to the whole frame
    const Bounds2i& b = opts.pixelBounds;
    const bool part = b.pMin.x != 0 || b.pMin.y != 0 || b.pMax.x != opts.fullResolution.x ||
                      b.pMax.y != opts.fullResolution.y;
    metadata.strings["kiln:savefp16"] = opts.savefp16 ? "true" : "false";
    if (opts.thermal) metadata.strings["kiln:thermal"] = opts.thermal->Settings();
    if (opts.thermal && opts.thermal->PictureScale())
        metadata.strings["kiln:thermalscale"] =
            ThermalSensor::ScaleSettings(*opts.thermal->PictureScale());
    // The display view the film asks for (kiln convert uses it unless told otherwise)
    metadata.strings["kiln:view"] = viewOverride.empty() ? opts.view : viewOverride;
    if (opts.thermal && ext != "exr") {
        // The picture of the temperature channel, with its scale bar
        if (std::string why = ThermalOutputFormatProblem(filename); !why.empty())
            throw std::runtime_error(filename + ": " + why);
        ThermalPicture(image, image.ChannelIndex("T"), opts.thermal->PictureScale())
            .Write(filename, metadata);
        return;
    }
    if (ext == "exr") {
        if (opts.savefp16 && !part) {
            // Half floats end at 65504, which absolute thermal radiance passes near 6000 K:
            // keep 32-bit floats rather than write infinities
            float largest = 0;
            for (int y = 0; y < image.Resolution().y; ++y)
                for (int x = 0; x < image.Resolution().x; ++x)
                    for (int c = 0; c < image.NChannels(); ++c)
                        largest = std::max(largest, std::abs(image.GetChannel({x, y}, c)));
            if (largest <= kMaxHalf)
                image = image.ConvertToFormat(PixelFormat::Half);
            else if (diag)
                diag->Warn(FileLoc(), filename + ": values up to " + std::to_string(largest) +
                                          " exceed half-float range (65504); writing 32-bit float");
        }
        image.Write(filename, metadata);
    } else if (ext == "pfm" || ext == "hdr") {
        // These formats carry no primaries: RGB in sRGB's, as pbrt-v4 writes them
        Image rgb = image.SelectChannels({"R", "G", "B"}).ConvertToFormat(PixelFormat::Float);
        if (colorSpace != &RGBColorSpace::sRGB()) {
            ColorMatrix m = colorSpace->ConvertTo(RGBColorSpace::sRGB());
            for (int y = 0; y < rgb.Resolution().y; ++y)
                for (int x = 0; x < rgb.Resolution().x; ++x) {
                    RGB v = Mul(m, RGB(rgb.GetChannel({x, y}, 0), rgb.GetChannel({x, y}, 1),
                                       rgb.GetChannel({x, y}, 2)));
                    for (int c = 0; c < 3; ++c) rgb.SetChannel({x, y}, c, v[c]);
                }
            ImageMetadata sRGBMetadata = metadata;
            sRGBMetadata.colorSpace = &RGBColorSpace::sRGB();
            rgb.Write(filename, sRGBMetadata);
        } else {
            rgb.Write(filename, metadata);
        }
    } else {
        DisplaySettings settings;
        settings.view = viewOverride.empty() ? opts.view : viewOverride;
        ToDisplayImage(image, *colorSpace, settings).Write(filename, metadata);
    }
}

std::string RGBFilm::ThermalOutputFormatProblem(const std::string& filename) {
    const std::string ext = FileExtension(filename);
    if (ext != "pfm" && ext != "hdr") return "";
    return "the thermal film writes EXR (L and T) or a picture of T (PNG, JPEG, ...), not ." + ext;
}

void RGBFilm::Clear() {
    std::fill(pixels.begin(), pixels.end(), Pixel());
    std::fill(aovs.Pixels().begin(), aovs.Pixels().end(), GBufferLayers::Pixel());
    std::fill(stokesPixels.begin(), stokesPixels.end(), StokesPixel());
    for (std::atomic<double>& s : splats) s.store(0);
    buckets.Clear();
    nonFiniteCount = 0;
    firstNonFinite = -1;
}

}  // namespace kiln
