// RGBFilm and PixelSensor: radiometric convention, pixel bounds, exposure, non-finite samples,
// AOV output.
#include "core/film/film.h"

#include <gtest/gtest.h>

#include <array>

#include <filesystem>
#include <random>

#include "base/statistics.h"
#include "core/parser/parameter_dictionary.h"
#include "film_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

Float Luminance(RGB rgb) { return RGBColorSpace::sRGB().ToXYZ(rgb).Y; }

TEST(RGBFilm, Defaults) {
    FilmFixture f;
    RGBFilm* film = f.Make({});
    EXPECT_EQ(film->FullResolution(), Point2i(1280, 720));
    EXPECT_EQ(film->PixelBounds().pMax, Point2i(1280, 720));
    EXPECT_EQ(film->Filename(), "pbrt.exr");
    EXPECT_FLOAT_EQ(film->Diagonal(), 0.035f);
    EXPECT_EQ(film->ColorSpace(), &RGBColorSpace::sRGB());
    Bounds2f sb = film->SampleBounds();  // box radius 0.5: exactly the pixels
    EXPECT_FLOAT_EQ(sb.pMin.x, 0);
    EXPECT_FLOAT_EQ(sb.pMax.y, 720);
    f.Make({}, "spectral");  // pbrt-v4's SpectralFilm: no warning
    EXPECT_EQ(f.diag.WarningCount(), 0);
    f.Make({}, "photographic");  // not a pbrt-v4 film: a warning, rendered as rgb
    EXPECT_EQ(f.diag.WarningCount(), 1);
}

TEST(RGBFilm, ConstantRadianceGivesUnitLuminance) {
    // Radiometric convention: L = 1 W m^-2 sr^-1 nm^-1 at every wavelength gives Y = 1.
    FilmFixture f;
    RGBFilm* film = f.Make(SmallRes());
    RunningStats stats;
    const int n = 4096;
    for (int i = 0; i < n; ++i) {
        SampledWavelengths lambda = film->SampleWavelengths((i + 0.5f) / n);
        SampledSpectrum L(1.f);
        film->AddSample({2, 1}, L, lambda, nullptr, 1);
        stats.Add(SpectrumToXYZ(L, lambda).Y);
    }
    double tol = 4 * std::sqrt(stats.Variance() / n) + 1e-3;
    EXPECT_NEAR(Luminance(film->GetPixelRGB({2, 1})), 1.0, tol);
    // The colour space's illuminant is its white, RGB (1, 1, 1).
    RGBFilm* film2 = f.Make(SmallRes());
    for (int i = 0; i < n; ++i) {
        SampledWavelengths lambda = film2->SampleWavelengths((i + 0.5f) / n);
        film2->AddSample({0, 0}, RGBColorSpace::sRGB().Illuminant().Sample(lambda), lambda, nullptr,
                         1);
    }
    RGB w = film2->GetPixelRGB({0, 0});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], 1, 0.01) << c;
    EXPECT_EQ(film2->GetPixelRGB({1, 0}).r, 0);  // untouched pixel
}

TEST(RGBFilm, SensorImagingRatio) {
    // iso 200 and a 0.25 s shutter: imaging ratio 0.5.
    FilmFixture f;
    ParsedParameterVector p = SmallRes();
    p.push_back(Param("float", "iso", {200}));
    RGBFilm* film = f.Make(p, "rgb", 0.25f);
    EXPECT_FLOAT_EQ(film->Sensor().imagingRatio, 0.5f);
    p.push_back(Param("string", "sensor", {}, {}, {"canon_eos_100d"}));
    f.Make(p);
    EXPECT_EQ(f.diag.WarningCount(), 1);
    // White balancing to D65 from the daylight illuminant at 6504 K is nearly the identity.
    ColorMatrix wb = WhiteBalance(DaylightChromaticity(6504), RGBColorSpace::sRGB().w);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(wb[i][j], i == j ? 1 : 0, 2e-3);
}

TEST(RGBFilm, CropWindowAndPixelBounds) {
    FilmFixture f;
    ParsedParameterVector p = {Param("integer", "xresolution", {}, {100}),
                               Param("integer", "yresolution", {}, {50}),
                               Param("float", "cropwindow", {0.55f, 0.1f, 0.333f, 0.9f})};
    RGBFilm* film = f.Make(p);
    // pbrt-v4: ceil(NDC * resolution) for both corners.
    EXPECT_EQ(film->PixelBounds().pMin, Point2i(10, 17));
    EXPECT_EQ(film->PixelBounds().pMax, Point2i(55, 45));
    EXPECT_EQ(film->FullResolution(), Point2i(100, 50));
    ImageMetadata md;
    Image im = film->GetImage(&md);
    EXPECT_EQ(im.Resolution(), Point2i(45, 28));
    EXPECT_EQ(md.pixelBounds->pMin, Point2i(10, 17));

    ParsedParameterVector q = {Param("integer", "xresolution", {}, {100}),
                               Param("integer", "yresolution", {}, {50}),
                               Param("integer", "pixelbounds", {}, {5, 20, 0, 60})};
    RGBFilm* film2 = f.Make(q);
    EXPECT_EQ(film2->PixelBounds().pMin, Point2i(5, 0));
    EXPECT_EQ(film2->PixelBounds().pMax, Point2i(20, 50));  // clamped, with a warning
    EXPECT_EQ(f.diag.WarningCount(), 1);

    ParsedParameterVector bad = {Param("float", "cropwindow", {0.5f, 0.5f, 0, 1})};
    EXPECT_THROW(f.Make(bad), SceneError);
    ParsedParameterVector three = {Param("float", "cropwindow", {0, 1, 0})};
    EXPECT_THROW(f.Make(three), SceneError);
}

TEST(RGBFilm, ExposureAndMaxComponent) {
    FilmFixture f;
    RGBFilm* a = f.Make(SmallRes());
    ParsedParameterVector p = SmallRes();
    p.push_back(Param("float", "exposure", {1}));
    RGBFilm* b = f.Make(p);
    ParsedParameterVector q = SmallRes();
    q.push_back(Param("float", "maxcomponentvalue", {2}));
    RGBFilm* c = f.Make(q);
    SampledWavelengths lambda = a->SampleWavelengths(0.3f);
    SampledSpectrum L(0.7f);
    L[2] = 0.2f;
    for (RGBFilm* film : {a, b}) film->AddSample({3, 3}, L, lambda, nullptr, 0.8f);
    RGB ra = a->GetPixelRGB({3, 3}), rb = b->GetPixelRGB({3, 3});
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(rb[k], 2 * ra[k]);
    // Bright samples are scaled down to maxcomponentvalue in sensor (XYZ) space.
    SampledSpectrum bright(100.f);
    c->AddSample({0, 0}, bright, lambda, nullptr, 1);
    XYZ xyz = RGBColorSpace::sRGB().ToXYZ(c->GetPixelRGB({0, 0}));
    EXPECT_NEAR(std::max({xyz.X, xyz.Y, xyz.Z}), 2, 1e-3);
}

// Issue 23: a silver sphere at 1e38 K gave finite spectra whose sensor response overflowed:
// S0 was written 0 and S1, S2 infinite. Such a sample is rejected whole, in every layer.
TEST(RGBFilm, SamplesWhoseSensorResponseOverflowsAreRejectedInEveryLayer) {
    FilmFixture f;
    ParsedParameterVector params = SmallRes();
    params.push_back(Param("bool", "stokes", {}, {}, {}, {1}));
    RGBFilm* film = f.Make(std::move(params));
    ASSERT_TRUE(film->WritesStokes());
    SampledWavelengths lambda = film->SampleWavelengths(0.5f);
    film->AddSample({3, 2},
                    Stokes(SampledSpectrum(0.5f), SampledSpectrum(0.1f), SampledSpectrum(-0.1f),
                           SampledSpectrum(0.f)),
                    lambda, nullptr, 1);
    std::array<RGB, 4> before;
    for (int k = 0; k < 4; ++k) before[k] = film->GetPixelStokes({3, 2}, k);
    SampledSpectrum huge(3e38f);
    for (const Stokes& S : {Stokes(huge, SampledSpectrum(1.f), SampledSpectrum(1.f), {}),
                            Stokes(SampledSpectrum(1.f), huge, -huge, {})})
        film->AddSample({3, 2}, S, lambda, nullptr, 1);
    EXPECT_EQ(film->NonFiniteSampleCount(), 2);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(film->GetPixelStokes({3, 2}, k), before[k]) << k;
}

TEST(RGBFilm, NonFiniteSamplesAreCountedAndRejected) {
    FilmFixture f;
    RGBFilm* film = f.Make(SmallRes());
    SampledWavelengths lambda = film->SampleWavelengths(0.5f);
    film->AddSample({3, 2}, SampledSpectrum(0.5f), lambda, nullptr, 1);
    RGB before = film->GetPixelRGB({3, 2});
    SampledSpectrum nan(0.5f), inf(0.5f);
    nan[1] = std::nanf("");
    inf[3] = Infinity;
    film->AddSample({3, 2}, nan, lambda, nullptr, 1);
    film->AddSample({1, 1}, inf, lambda, nullptr, 1);
    EXPECT_EQ(film->NonFiniteSampleCount(), 2);
    ASSERT_TRUE(film->FirstNonFinitePixel());
    EXPECT_EQ(*film->FirstNonFinitePixel(), Point2i(3, 2));
    EXPECT_EQ(film->GetPixelRGB({3, 2}), before);
    EXPECT_EQ(film->GetPixelRGB({1, 1}), RGB(0, 0, 0));
    film->Clear();
    EXPECT_EQ(film->NonFiniteSampleCount(), 0);
    EXPECT_FALSE(film->FirstNonFinitePixel());
    EXPECT_EQ(film->GetPixelRGB({3, 2}), RGB(0, 0, 0));
}

TEST(RGBFilm, GBufferExrHasAOVs) {
    FilmFixture f;
    fs::path dir =
        fs::temp_directory_path() / ("kiln_film_test_" + std::to_string(std::random_device()()));
    fs::create_directories(dir);
    RGBFilm* film = f.Make(SmallRes(), "gbuffer");
    VisibleSurface vs;
    vs.set = true;
    vs.n = vs.ns = Normal3f(0, 0, 1);
    vs.p = Point3f(0, 0, 3.5f);  // render space, which is the film's camera space here
    vs.albedo = SampledSpectrum(0.5f);
    const int n = 512;
    for (int i = 0; i < n; ++i) {
        SampledWavelengths lambda = film->SampleWavelengths((i + 0.5f) / n);
        film->AddSample({1, 2}, SampledSpectrum(1.f), lambda, &vs, 1);
    }
    std::string exr = (dir / "g.exr").string();
    ImageMetadata md;
    md.samplesPerPixel = n;
    film->WriteImage(exr, md);
    ImageMetadata rd;
    Image im = Image::Read(exr, &rd);
    EXPECT_EQ(im.Format(), PixelFormat::Half);  // savefp16 default
    for (const char* ch :
         {"R", "G", "B", "Albedo.R", "Albedo.G", "Albedo.B", "N.X", "N.Y", "N.Z", "P.Z"})
        EXPECT_GE(im.ChannelIndex(ch), 0) << ch;
    EXPECT_NEAR(im.GetChannel({1, 2}, im.ChannelIndex("P.Z")), 3.5f, 1e-3f);
    EXPECT_NEAR(im.GetChannel({1, 2}, im.ChannelIndex("N.Z")), 1, 1e-3f);
    for (const char* ch : {"Albedo.R", "Albedo.G", "Albedo.B"})
        EXPECT_NEAR(im.GetChannel({1, 2}, im.ChannelIndex(ch)), 0.5f, 0.01f) << ch;
    EXPECT_EQ(rd.samplesPerPixel, n);
    EXPECT_EQ(rd.colorSpace, &RGBColorSpace::sRGB());
    // The plain RGB film has no AOV channels; a display format goes through the view.
    RGBFilm* plain = f.Make(SmallRes());
    plain->AddSample({0, 0}, SampledSpectrum(0.18f), plain->SampleWavelengths(0.5f), &vs, 1);
    std::string png = (dir / "p.png").string();
    plain->WriteImage(png, {});
    Image p = Image::Read(png);
    EXPECT_EQ(p.NChannels(), 3);
    EXPECT_EQ(p.Format(), PixelFormat::U256);
    EXPECT_EQ(plain->GetImage(nullptr).NChannels(), 3);
    // savefp16 false writes float; the Filmic view is accepted, unknown views are errors.
    ParsedParameterVector p32 = SmallRes();
    p32.push_back(Param("bool", "savefp16", {}, {}, {}, {0}));
    p32.push_back(Param("string", "view", {}, {}, {"Filmic"}));
    RGBFilm* full = f.Make(p32);
    EXPECT_EQ(full->GetOptions().view, "Filmic");
    full->WriteImage((dir / "f.exr").string(), {});
    EXPECT_EQ(Image::Read((dir / "f.exr").string()).Format(), PixelFormat::Float);
    full->WriteImage((dir / "f.jpg").string(), {});
    EXPECT_EQ(Image::Read((dir / "f.jpg").string()).NChannels(), 3);
    ParsedParameterVector badView = SmallRes();
    badView.push_back(Param("string", "view", {}, {}, {"Vivid"}));
    EXPECT_THROW(f.Make(badView), SceneError);
    int files = 0;
    for ([[maybe_unused]] auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 4);  // g.exr, p.png, f.exr, f.jpg: no temporaries
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kiln
