// The film: pixel sensor, accumulation of filtered radiance samples into RGB pixels, auxiliary
// (AOV) layers and image output (pbrt-v4's PixelSensor and RGBFilm).
//
// Radiometric convention (pbrt-v4): with the default sensor ("cie1931", iso 100, exposure time
// 1, whitebalance 0) and exposure 0 EV, an output pixel's luminance Y equals
//   integral(L(l) ybar(l) dl) / integral(ybar(l) dl),
// L the spectral radiance reaching the pixel in W m^-2 sr^-1 nm^-1; so a constant L = 1 gives
// Y = 1, and the colour space's illuminant spectrum (normalised to Y = 1) gives RGB (1, 1, 1).
// Pixel RGB values are linear in the film's output colour space.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/object_arena.h"
#include "base/vecmath.h"
#include "core/film/filter.h"
#include "core/film/gbuffer_layers.h"
#include "core/film/spectral_buckets.h"
#include "core/film/thermal_sensor.h"
#include "core/film/visible_surface.h"
#include "core/image/display.h"
#include "core/image/image.h"
#include "core/parser/diagnostics.h"
#include "core/parser/file_loc.h"
#include "spectral/color.h"
#include "spectral/polarization.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/wavelength_distribution.h"

namespace kiln {

class ParameterDictionary;

// PixelSensor Definition
// pbrt-v4's PixelSensor. "cie1931": the sensor responds with the CIE 1931 matching functions,
// so its "RGB" is XYZ scaled by imagingRatio = exposureTime (s) * iso / 100; with
// whitebalance T > 0 (K) a von Kries (Bradford) adaptation maps the chromaticity of
// CIEDaylightSpectrum(T) (pbrt-v4's daylight: a blackbody below 4000 K) to the output colour
// space's white. A named camera sensor (measured curves
// <name>_r, _g, _b among the named spectra) responds with its curves, imagingRatio *
// integral(curve L) / CIE_Y_integral, and XYZFromSensorRGB is fitted over the ColorChecker
// swatches lit by pbrt-v4's daylight of the white-balance temperature (6500 K by default):
// see sensor_fit.h. pbrt-v4's sensor names whose curves kiln lacks warn and use cie1931.
class PixelSensor {
  public:
    PixelSensor() = default;
    // cie1931; whiteBalanceTemp: K, 0 = no white balance.
    PixelSensor(const RGBColorSpace* outputColorSpace, Float whiteBalanceTemp, Float imagingRatio);
    // Camera sensor with curves r, g, b (which must outlive the sensor), fitted under
    // sensorIllum. Throws std::runtime_error if the fit is singular.
    PixelSensor(const Spectrum* r, const Spectrum* g, const Spectrum* b,
                const RGBColorSpace* outputColorSpace, const Spectrum& sensorIllum,
                Float imagingRatio);
    static PixelSensor Create(const ParameterDictionary& params, const RGBColorSpace* colorSpace,
                              Float exposureTime, const FileLoc& loc, Diagnostics& diag);

    // Sensor response to the path's radiance samples (Monte Carlo estimate over lambda).
    RGB ToSensorRGB(const SampledSpectrum& L, const SampledWavelengths& lambda) const;

    ColorMatrix XYZFromSensorRGB;  // cie1931: identity unless white balancing
    Float imagingRatio = 1;
    // The camera's curves (named spectra); null for cie1931.
    const Spectrum *r_bar = nullptr, *g_bar = nullptr, *b_bar = nullptr;
};

// Chromaticity (CIE 1931 xy) of CIE daylight at correlated colour temperature T in K,
// 4000 K <= T <= 25000 K (CIE 015:2018, eq. 4.1-4.3; T is clamped to that range).
Point2f DaylightChromaticity(Float T);
// Bradford von Kries chromatic adaptation matrix (XYZ -> XYZ) from white srcW to white dstW.
ColorMatrix WhiteBalance(Point2f srcW, Point2f dstW);

// How pixel samples become pixel values (Film "string reconstruction"). Both estimate the
// same filtered image, sum(f L) / sum(f) over the samples near a pixel centre:
//   FilterImportance ("importance", pbrt-v4): a sample's position is drawn from the filter
//     around its pixel's centre and it counts for that pixel alone, with weight f / pdf.
//   Spread ("spread", kiln's default, as pbrt-v3's film tiles and Mitsuba 3's image blocks): a
//     sample is drawn uniformly over its pixel and counts for every pixel whose centre lies
//     within the filter's radius, with weight f. Each pixel then averages the samples of its
//     neighbours as well: with pbrt-v4's default Gaussian (radius 1.5, sigma 0.5) about a third
//     of the per-pixel variance for the same samples, the noise correlated over the filter's
//     footprint instead of independent per pixel.
enum class PixelReconstruction { FilterImportance, Spread };

// RGBFilm Definition
class RGBFilm {
  public:
    // pbrt-v4 RGBFilm parameters: "integer xresolution" (1280), "yresolution" (720),
    // "float cropwindow" [x0 x1 y0 y1] (NDC; pixel bounds = ceil(NDC * resolution)),
    // "integer pixelbounds" [x0 x1 y0 y1], "string filename" ("pbrt.exr"), "bool savefp16"
    // (true), "float iso" (100), "float whitebalance" (0 = none, K), "string sensor"
    // ("cie1931"), "float maxcomponentvalue" (infinity), "float diagonal" (35 mm).
    // kiln additions: "float exposure" (EV stops, default 0: pixel values times 2^exposure),
    // "string view" ("Standard" | "Filmic" | "ACES" | "Raw", for display formats), "bool writeaovs"
    // (false; film type "gbuffer" sets it: the EXR gains pbrt-v4's GBufferFilm channels, see
    // GBufferLayers), "string coordinatesystem" (with AOVs: "camera", the default, or "world":
    // the space of P, N, Ns, dzdx and dzdy, as pbrt-v4's gbuffer film),
    // "bool stokes" (false; the EXR gains S0.{R,G,B} ... S3.{R,G,B}, the Stokes components
    // with reference axis the image's horizontal, S2 > 0 for light polarised along the
    // diagonal from lower left to upper right; S0 is the RGB image; a scene with it renders
    // polarised light).
    // type "spectral" (pbrt-v4's SpectralFilm): "integer nbuckets" (16), "float lambdamin"
    // (360), "float lambdamax" (830) within 360-830 nm; the EXR gains the buckets' mean
    // spectral radiance (SpectralBuckets; not scaled by the sensor or "exposure"); the scene's
    // "filename" must be an EXR, as in pbrt-v4.
    // type "thermal" (kiln; "savefp16" defaults to false): an infrared camera or pyrometer
    // (ThermalSensor: "string sensor", "float emissivity", "float reflectedtemperature"); the scene
    // renders the sensor's band (Range), each pixel the in-band radiance (W m^-2 sr^-1), and the
    // EXR has channels L (that radiance) and T (the apparent temperature the sensor reports, K);
    // other picture formats (PNG, JPEG, ...) get T colour-mapped with a scale bar
    // (thermal_colormap.h); not PFM or HDR. With "stokes" the EXR also has S0 (= L), S1, S2,
    // S3, the in-band Stokes components (W m^-2 sr^-1). No AOVs or "exposure". type: "rgb" |
    // "gbuffer" | "spectral" | "thermal"; others warn and use "rgb". exposureTime: camera shutter
    // interval, s. colorSpace: output colour space (nullptr: sRGB). Throws SceneError. request:
    // what the render asks besides the scene's parameters (RenderOptions): pixel bounds that
    // replace the scene's crop window and pixel bounds, a crop window that replaces the scene's,
    // whether to record Stokes layers, and the camera's placement (the "camera" and "world" spaces
    // of the AOV layers; identity: render space).
    struct Request {
        std::optional<Bounds2f> cropWindow;
        std::optional<Bounds2i> pixelBounds;
        std::optional<bool> stokes;
        std::optional<PixelReconstruction> reconstruction;  // replaces "reconstruction"
        // false (Option "disablepixeljitter"): samples at pixel centres, never spread
        std::optional<bool> pixelJitter;
        Transform cameraFromRender, worldFromRender;
    };
    static RGBFilm* Create(const std::string& type, const ParameterDictionary& params,
                           Float exposureTime, const Filter& filter,
                           const RGBColorSpace* colorSpace, const FileLoc& loc, ObjectArena& arena,
                           Diagnostics& diag, const Request& request = {});

    struct Options {
        Point2i fullResolution{1280, 720};
        Bounds2i pixelBounds{{0, 0}, {1280, 720}};
        std::string filename = "pbrt.exr";
        bool savefp16 = true;
        Float maxComponentValue = Infinity;
        Float diagonal = 0.035f;  // m
        Float exposureEV = 0;
        std::string view = "Standard";
        bool writeAOVs = false;
        GBufferLayers::Space aovSpace = GBufferLayers::Space::Camera;
        bool stokes = false;
        int spectralBuckets = 0;  // 0: no spectral layer
        Float lambdaMin = Lambda_min, lambdaMax = Lambda_max;
        std::optional<ThermalSensor> thermal;  // film "thermal"
        PixelReconstruction reconstruction = PixelReconstruction::FilterImportance;
    };
    // outputFromRender: render space to the AOV layers' space (opts.aovSpace).
    RGBFilm(const Options& options, const PixelSensor& sensor, const Filter& filter,
            const RGBColorSpace* colorSpace, const Transform& outputFromRender = Transform());

    // Limits checked by Create: pixels on a side of the full image, and the memory a pixel
    // of the rendered bounds takes (with or without AOVs).
    static constexpr int kMaxFilmSide = 1 << 24;
    // Exposure (film "exposure", kiln --exposure) in stops: 2^64 keeps any radiance finite in
    // float. Half floats end at kMaxHalf.
    static constexpr Float kMaxExposureEV = 64;
    static constexpr float kMaxHalf = 65504;
    static size_t BytesPerPixel(bool aovs, bool stokes, int spectralBuckets = 0) {
        return sizeof(Pixel) + (aovs ? sizeof(GBufferLayers::Pixel) : 0) +
               (stokes ? sizeof(StokesPixel) : 0) + size_t(spectralBuckets) * sizeof(double);
    }

    Point2i FullResolution() const { return opts.fullResolution; }
    Bounds2i PixelBounds() const { return opts.pixelBounds; }

    // Pixel reconstruction (PixelReconstruction). With Spread, the pixels whose samples reach
    // the pixel bounds: the bounds grown by SpreadMargin() on each side (pixels up to the
    // filter's radius beyond the edge, as pbrt-v4's filter offsets reach), and the resolution
    // a sampler must cover to give each of them its own samples when pixel p is passed to it
    // as p + SpreadMargin().
    PixelReconstruction Reconstruction() const { return opts.reconstruction; }
    Vector2i SpreadMargin() const;
    Bounds2i SpreadPixelBounds() const;
    Point2i SamplerResolution() const;
    // Filters whose radius exceeds this (pixels, either axis) are importance-sampled whatever
    // "reconstruction" says: a spread sample costs (2 radius)^2 pixel updates. So are filters
    // narrower than a pixel (radius below 1/2, either axis).
    static constexpr Float kMaxSpreadRadius = 4;
    // Raster-space area over which samples contribute (pixel bounds grown by the filter
    // radius minus half a pixel, pbrt-v4).
    Bounds2f SampleBounds() const;
    const std::string& Filename() const { return opts.filename; }
    const Filter& GetFilter() const { return filter; }
    const RGBColorSpace* ColorSpace() const { return colorSpace; }
    // Length of the film diagonal, m.
    Float Diagonal() const { return opts.diagonal; }
    const PixelSensor& Sensor() const { return sensor; }
    const Options& GetOptions() const { return opts; }
    // Whether AddSample uses its VisibleSurface (AOV layers); when false, callers may pass
    // nullptr and skip computing it (pbrt-v4's Film::UsesVisibleSurface).
    bool UsesVisibleSurface() const { return opts.writeAOVs; }
    // Whether the film records the Stokes components (film "stokes").
    bool WritesStokes() const { return opts.stokes; }

    // The wavelengths the film's sensor responds to: the visible range, or a thermal sensor's
    // band.
    SpectralRange Range() const { return opts.thermal ? opts.thermal->Band() : SpectralRange{}; }
    const ThermalSensor* Thermal() const { return opts.thermal ? &*opts.thermal : nullptr; }
    // Why this film cannot write an image named filename, "" if it can (a thermal film writes
    // EXR or a picture of T, not PFM or HDR); checked before rendering (kiln -o).
    std::string OutputFormatProblem(const std::string& filename) const {
        return opts.thermal ? ThermalOutputFormatProblem(filename) : std::string();
    }
    static std::string ThermalOutputFormatProblem(const std::string& filename);

    // The wavelengths of one path sample, drawn by the distribution scene creation chose
    // (the visible density unless set).
    SampledWavelengths SampleWavelengths(Float u) const { return wavelengths.Sample(u); }
    void SetWavelengths(WavelengthDistribution d) { wavelengths = std::move(d); }

    // Adds a radiance sample L (W m^-2 sr^-1 nm^-1 at lambda) to pixel pPixel (inside the
    // pixel bounds) with filter weight `weight` (f / pdf of the importance-sampled filter).
    // The sensor RGB is scaled down to maxComponentValue if brighter. Non-finite L (NaN/Inf)
    // is counted and dropped. visibleSurface (may be null) feeds the AOV layers.
    // Thread-safe as long as one pixel is only written by one thread at a time (tiles).
    void AddSample(Point2i pPixel, const SampledSpectrum& L, const SampledWavelengths& lambda,
                   const VisibleSurface* visibleSurface, Float weight) {
        AddSample(pPixel, L, nullptr, lambda, visibleSurface, weight);
    }
    // A polarised sample: S in the film's frame (see "stokes"); S0 goes where L goes above,
    // S1..S3 to the Stokes layers (if the film has them) with the same sensor response and
    // the same maxComponentValue scale.
    void AddSample(Point2i pPixel, const Stokes& S, const SampledWavelengths& lambda,
                   const VisibleSurface* visibleSurface, Float weight) {
        AddSample(pPixel, S[0], &S, lambda, visibleSurface, weight);
    }

    // A sample taken uniformly over its pixel at raster position pFilm (Spread
    // reconstruction): added, like AddSample, to every pixel of the bounds whose centre lies
    // within the filter's radius of pFilm, with weight f(pFilm - centre). Thread-safe as long
    // as no other thread writes those pixels (renderer.cpp: tiles in four phases).
    void SpreadSample(Point2f pFilm, const SampledSpectrum& L, const SampledWavelengths& lambda,
                      const VisibleSurface* visibleSurface) {
        SpreadSample(pFilm, L, nullptr, lambda, visibleSurface);
    }
    void SpreadSample(Point2f pFilm, const Stokes& S, const SampledWavelengths& lambda,
                      const VisibleSurface* visibleSurface) {
        SpreadSample(pFilm, S[0], &S, lambda, visibleSurface);
    }

    // Splats (pbrt-v4's RGBFilm::AddSplat, for light tracing): radiance arriving at raster
    // position pFilm, spread over the pixels within the filter's radius with the filter's
    // value there (unnormalised; divided by the filter's integral on output) and scaled on
    // output by SetSplatScale's factor (1 / samples per pixel). Thread-safe (atomic adds:
    // the sums' rounding depends on the order threads add in). Needs EnableSplats first.
    // Sensor response and maxComponentValue as AddSample; non-finite L is counted and dropped.
    void EnableSplats();
    bool HasSplats() const { return !splats.empty(); }
    void AddSplat(Point2f pFilm, const SampledSpectrum& L, const SampledWavelengths& lambda);
    void SetSplatScale(double scale) { splatScale = scale; }

    // Pixel value in the output colour space with exposure applied (black if no weight).
    RGB GetPixelRGB(Point2i p) const;
    // Stokes component k (0..3) of a pixel, like GetPixelRGB (k = 0 is GetPixelRGB; 1..3 are
    // black without "stokes").
    RGB GetPixelStokes(Point2i p, int k) const;

    int64_t NonFiniteSampleCount() const { return nonFiniteCount.load(); }
    std::optional<Point2i> FirstNonFinitePixel() const;

    // Linear image of the pixel bounds: channels R, G, B (+ GBufferLayers::ChannelNames() with
    // AOVs, + S0.R ... S3.B with "stokes", + the spectral buckets' channels), PixelFormat::Float.
    // Fills *metadata (if not null) with pixel bounds, full resolution and colour space.
    Image GetImage(ImageMetadata* metadata) const;
    // By extension: .exr (linear; half when savefp16, with the AOV layers), .pfm/.hdr (linear
    // float), any other OIIO format through ToDisplayImage with the "view" parameter (or
    // viewOverride if not empty). Atomic (see Image::Write). Throws std::runtime_error.
    // A half-float EXR whose values would overflow binary16 is written as 32-bit float, with a
    // warning to diag (if given).
    void WriteImage(const std::string& filename, ImageMetadata metadata,
                    const std::string& viewOverride = "", Diagnostics* diag = nullptr) const;

    // Exposure in EV stops (film "exposure"): pixel values are scaled by 2^ev.
    void SetExposureEV(Float ev) { opts.exposureEV = ev; }

    // Resets all pixels to black and the non-finite counters to zero.
    void Clear();

    // The accumulated state (pixel sums, AOV and Stokes sums, non-finite counters) as bytes,
    // for checkpoints; LoadState takes what SaveState of a film with the same pixel bounds and
    // layers wrote, and returns false (the film unchanged) for anything else.
    std::string SaveState() const;
    bool LoadState(std::string_view state);

  private:
    WavelengthDistribution wavelengths;
    // RGBFilm Private Members
    struct Pixel {
        double rgbSum[3] = {0, 0, 0};  // sensor RGB, weighted
        double weightSum = 0;
    };
    struct StokesPixel {
        double rgbSum[3][3] = {};  // sensor RGB of S1, S2, S3, weighted
    };
    size_t PixelIndex(Point2i p) const;
    // The sensor's response to a path sample: sensor RGB, or for a thermal film the in-band
    // radiance in all three components
    RGB Response(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
        if (opts.thermal) {
            Float v = opts.thermal->InBandRadiance(L, lambda);
            return RGB(v, v, v);
        }
        return sensor.ToSensorRGB(L, lambda);
    }
    // A sample's contribution as every layer records it (clamped to maxComponentValue)
    struct SampleResponse {
        RGB rgb;
        std::array<RGB, 3> stokes;  // S1..S3 (withStokes)
        bool withStokes = false;
        SampledSpectrum L;  // for the spectral buckets
        RGB albedo;         // for the AOV layers (visibleSurface set)
    };
    // The response, or nullopt for a sample that must be rejected (non-finite)
    std::optional<SampleResponse> Respond(const SampledSpectrum& L, const Stokes* S,
                                          const SampledWavelengths& lambda,
                                          const VisibleSurface* visibleSurface) const;
    void Accumulate(size_t index, const SampleResponse& r, const SampledWavelengths& lambda,
                    const VisibleSurface* visibleSurface, Float weight);
    void Reject(size_t index);
    void AddSample(Point2i pPixel, const SampledSpectrum& L, const Stokes* S,
                   const SampledWavelengths& lambda, const VisibleSurface* visibleSurface,
                   Float weight);
    void SpreadSample(Point2f pFilm, const SampledSpectrum& L, const Stokes* S,
                      const SampledWavelengths& lambda, const VisibleSurface* visibleSurface);

    Options opts;
    PixelSensor sensor;
    Filter filter;
    const RGBColorSpace* colorSpace;
    ColorMatrix outputRGBFromSensorRGB;
    std::vector<Pixel> pixels;
    GBufferLayers aovs;                     // empty unless writeAOVs
    std::vector<StokesPixel> stokesPixels;  // empty unless stokes
    SpectralBuckets buckets;                // empty unless spectral
    // Splatted sensor RGB, 3 per pixel (empty unless EnableSplats), and its output scale
    std::vector<std::atomic<double>> splats;
    double splatScale = 1;
    std::atomic<int64_t> nonFiniteCount{0};
    std::atomic<int64_t> firstNonFinite{-1};  // pixel index
};

}  // namespace kiln
