// What the film refuses and what it writes at the limits: films too large for memory or for
// the samplers, exposure beyond range, half-float overflow (bright thermal radiance) and
// output names near the file-name limit.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "../temp_dir.h"
#include "core/film/film.h"
#include "film_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

std::string ErrorOf(FilmFixture& f, ParsedParameterVector params) {
    try {
        f.Make(std::move(params));
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

ParsedParameterVector Resolution(int x, int y) {
    return {Param("integer", "xresolution", {}, {x}), Param("integer", "yresolution", {}, {y})};
}

using test::TempDir;

TEST(FilmOutput, FilmsThatCannotBeRenderedAreErrorsBeforeAllocation) {
    FilmFixture f;
    // 46341^2 pixels overflow 32 bits (this used to crash) and need ~69 GB
    std::string huge = ErrorOf(f, Resolution(46341, 46341));
    EXPECT_NE(huge.find("film of 46341 x 46341 pixels needs"), std::string::npos) << huge;
    std::string wide = ErrorOf(f, Resolution(1 << 30, 2));
    EXPECT_NE(wide.find("exceeds 16777216 pixels on a side"), std::string::npos) << wide;
    // A huge frame is fine when only a few of its pixels are rendered
    ParsedParameterVector crop = Resolution(1 << 24, 1 << 24);
    crop.push_back(Param("integer", "pixelbounds", {}, {100, 102, 7, 8}));
    RGBFilm* film = f.Make(crop);
    EXPECT_EQ(film->PixelBounds().Area(), 2);
}

TEST(FilmOutput, ExposureBeyondRangeIsAnError) {
    FilmFixture f;
    for (Float ev : {65.f, -1000.f}) {
        ParsedParameterVector p = Resolution(4, 4);
        p.push_back(Param("float", "exposure", {ev}));
        EXPECT_NE(ErrorOf(f, p).find("must be within +-64 stops"), std::string::npos) << ev;
    }
    ParsedParameterVector ok = Resolution(4, 4);
    ok.push_back(Param("float", "exposure", {-64}));
    EXPECT_EQ(ErrorOf(f, ok), "no error");
}

TEST(FilmOutput, HalfFloatExrFallsBackToFloatWhenValuesWouldOverflow) {
    TempDir dir;
    for (Float radiance : {1e3f, 1e6f}) {
        FilmFixture f;
        RGBFilm* film = f.Make(SmallRes());
        for (int i = 0; i < 64; ++i)
            film->AddSample({2, 1}, SampledSpectrum(radiance),
                            film->SampleWavelengths((i + 0.5f) / 64), nullptr, 1);
        Diagnostics diag(nullptr);
        std::string exr = (dir.path / "bright.exr").string();
        film->WriteImage(exr, {}, "", &diag);
        Image image = Image::Read(exr);
        float largest = 0;
        for (int c = 0; c < 3; ++c) {
            float v = image.GetChannel({2, 1}, c);
            ASSERT_TRUE(std::isfinite(v)) << radiance;
            largest = std::max(largest, v);
        }
        if (radiance < 65504) {
            EXPECT_EQ(image.Format(), PixelFormat::Half);
            EXPECT_EQ(diag.WarningCount(), 0);
        } else {
            EXPECT_EQ(image.Format(), PixelFormat::Float);
            EXPECT_GT(largest, 65504);
            ASSERT_EQ(diag.WarningCount(), 1);
            EXPECT_NE(diag.Warnings()[0].message.find("writing 32-bit float"), std::string::npos);
        }
    }
    EXPECT_EQ(dir.Files(), 1);
}

// PFM and HDR files name no primaries: a film in another colour space writes them in sRGB's,
// as pbrt-v4 does; EXR keeps the film's colour space (and says so)
TEST(FilmOutput, PfmAndHdrAreWrittenInSRGBPrimaries) {
    TempDir dir;
    FilmFixture f;
    const RGBColorSpace& rec2020 = *RGBColorSpace::GetNamed("rec2020");
    RGBFilm* film = f.Make(SmallRes(), "rgb", 1, &rec2020);
    SampledSpectrum s(0.f);
    for (int i = 0; i < NSpectrumSamples; ++i) s[i] = 0.2f + 0.3f * i;
    for (int i = 0; i < 64; ++i)
        film->AddSample({2, 1}, s, film->SampleWavelengths((i + 0.5f) / 64), nullptr, 1);
    std::string exr = (dir.path / "a.exr").string(), pfm = (dir.path / "a.pfm").string();
    film->WriteImage(exr, {}, "", nullptr);
    film->WriteImage(pfm, {}, "", nullptr);
    Image e = Image::Read(exr), p = Image::Read(pfm);
    RGB inRec2020(e.GetChannel({2, 1}, 0), e.GetChannel({2, 1}, 1), e.GetChannel({2, 1}, 2));
    RGB expected = Mul(rec2020.ConvertTo(RGBColorSpace::sRGB()), inRec2020);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(p.GetChannel({2, 1}, c), expected[c], 2e-3f * std::abs(expected[c]) + 1e-5f);
    EXPECT_GT(std::abs(expected[0] - inRec2020[0]), 0.01f * std::abs(inRec2020[0]));
}

TEST(FilmOutput, NamesNearTheFileNameLimitAreWritten) {
    // The temporary name is longer than the final one unless it is shortened to fit
    TempDir dir;
    FilmFixture f;
    RGBFilm* film = f.Make(SmallRes());
    for (size_t length : {size_t(200), size_t(255)}) {
        std::string name(length - 4, 'n');
        name += ".exr";
        film->WriteImage((dir.path / name).string(), {});
        EXPECT_TRUE(fs::exists(dir.path / name)) << length;
    }
    EXPECT_EQ(dir.Files(), 2);  // no temporaries left
}

}  // namespace
}  // namespace kiln
