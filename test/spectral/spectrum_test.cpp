// Spectrum kinds: evaluation, reading spectrum files, normalisation and the integrals.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"

using namespace kiln;

TEST(Spectrum, ConstantAndDense) {
    Spectrum c = ConstantSpectrum(0.25f);
    EXPECT_EQ(c(400), 0.25f);
    EXPECT_TRUE(c.Is<ConstantSpectrum>());
    XYZ xyz = SpectrumToXYZ(c);
    EXPECT_NEAR(xyz.Y, 0.25, 1e-6);
    DenselySampledSpectrum d(Spectrum(BlackbodySpectrum(3000)));
    EXPECT_NEAR(d(500.5f), 0.5f * (d(500) + d(501)), 1e-6);
    EXPECT_EQ(d(300), 0);
    Spectrum copy = c;  // copies, not wrapping a Spectrum in a Spectrum
    EXPECT_TRUE(copy.Is<ConstantSpectrum>());
}

TEST(Spectrum, PiecewiseLinear) {
    const Float l[] = {400, 500, 600}, v[] = {1, 3, 2};
    PiecewiseLinearSpectrum s(l, v);
    EXPECT_FLOAT_EQ(s(450), 2);
    EXPECT_FLOAT_EQ(s(600), 2);
    EXPECT_EQ(s(399), 0);
    EXPECT_EQ(s(601), 0);
    EXPECT_EQ(s.MaxValue(), 3);
    const Float bad[] = {400, 400, 600};
    EXPECT_THROW(PiecewiseLinearSpectrum(bad, v), std::invalid_argument);

    // FromInterleaved extends the ends and normalises to Y = 1
    const Float inter[] = {400, 1, 700, 1};
    PiecewiseLinearSpectrum n = PiecewiseLinearSpectrum::FromInterleaved(inter, true);
    EXPECT_NEAR(SpectrumToXYZ(Spectrum(n)).Y, 1, 1e-5);
    EXPECT_NEAR(n(380), n(500), 1e-6);
}

TEST(Spectrum, PiecewiseLinearLookupMatchesAScan) {
    // Irregular nodes, several within one nanometre, and a wide sparse stretch
    std::vector<Float> l = {300.2f, 300.5f, 300.9f, 301.f, 355.5f, 400.f, 400.25f, 612.7f, 900.f};
    std::vector<Float> v = {1, 3, 2, 5, 4, 0, 7, 2, 9};
    PiecewiseLinearSpectrum s(l, v);
    auto reference = [&](Float x) -> Float {
        if (!(x >= l.front()) || x > l.back()) return 0;
        size_t o = 0;
        while (o + 2 < l.size() && l[o + 1] <= x) ++o;
        Float t = (x - l[o]) / (l[o + 1] - l[o]);
        return (1 - t) * v[o] + t * v[o + 1];
    };
    for (int k = 0; k <= 70000; ++k) {
        Float x = 299.f + k * 0.01f;
        EXPECT_FLOAT_EQ(s(x), reference(x)) << x;
    }
    for (Float x : l) EXPECT_FLOAT_EQ(s(x), reference(x)) << x;
}

TEST(Spectrum, ParseRejectsNonFiniteValues) {
    for (const char* text :
         {"400 nan\n500 1\n", "400 1\n500 inf\n", "400 1e999\n500 1\n", "4e40 1\n5e40 1\n"}) {
        std::string error;
        EXPECT_FALSE(PiecewiseLinearSpectrum::Parse(text, "bad.spd", &error)) << text;
        EXPECT_NE(error.find("bad.spd: line"), std::string::npos) << error;
        EXPECT_NE(error.find("not a finite number"), std::string::npos) << error;
    }
    EXPECT_TRUE(PiecewiseLinearSpectrum::Parse("400 1, 500 2 # ok\n", "ok.spd"));
}

TEST(Spectrum, ReadFile) {
    const std::string path = testing::TempDir() + "kiln_spectrum_test.spd";
    {
        std::ofstream f(path);
        f << "# a comment\n400 0.5, 500 1.0 # trailing\n600 0.25\n";
    }
    std::string error;
    auto s = PiecewiseLinearSpectrum::Read(path, &error);
    ASSERT_TRUE(s.has_value()) << error;
    EXPECT_FLOAT_EQ((*s)(450), 0.75f);
    {
        std::ofstream f(path);
        f << "400 0.5 300 1\n";
    }
    EXPECT_FALSE(PiecewiseLinearSpectrum::Read(path, &error).has_value());
    EXPECT_NE(error.find("increasing"), std::string::npos);
    {
        std::ofstream f(path);
        f << "400 abc\n";
    }
    EXPECT_FALSE(PiecewiseLinearSpectrum::Read(path, &error).has_value());
    EXPECT_FALSE(PiecewiseLinearSpectrum::Read(path + ".missing", &error).has_value());
    std::remove(path.c_str());
}

// InnerProduct and SpectrumToPhotometric are the 1 nm sums; an RGB illuminant's photometric
// value is its colour space illuminant's (pbrt-v4).
TEST(Spectrum, Integrals) {
    EXPECT_NEAR(InnerProduct(spectra::Y(), ConstantSpectrum(1)), CIE_Y_integral, 1e-3);
    const Spectrum& d65 = *GetNamedSpectrum("stdillum-D65");
    EXPECT_NEAR(SpectrumToPhotometric(d65), CIE_Y_integral, 1e-2);
    Spectrum e = RGBIlluminantSpectrum(RGBColorSpace::sRGB(), RGB(5, 1, 1));
    EXPECT_NEAR(SpectrumToPhotometric(e),
                SpectrumToPhotometric(Spectrum(RGBColorSpace::sRGB().Illuminant())), 1e-3);
    SampledWavelengths swl = SampledWavelengths::SampleUniform(0.1f);
    SampledSpectrum ss = e.Sample(swl);
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_FLOAT_EQ(ss[i], e(swl[i]));
}
