// CIE tables, D65 white point and RGB colour-space matrices.
#include <gtest/gtest.h>

#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"

using namespace kiln;

// The 1 nm CIE tables: ybar peaks at 1 at 555 nm, and its sum is CIE_Y_integral.
TEST(CIE, YIntegral) {
    double sum = 0;
    for (int l = 360; l <= 830; ++l) sum += CIE_Y(Float(l));
    EXPECT_NEAR(sum, CIE_Y_integral, 1e-4);
    EXPECT_FLOAT_EQ(CIE_Y(555), 1.0f);
    EXPECT_EQ(CIE_Y(359), 0);
    EXPECT_EQ(CIE_X(831), 0);
    // Linear interpolation between the 1 nm samples
    EXPECT_FLOAT_EQ(CIE_X(600.5f), 0.5f * (CIE_X(600) + CIE_X(601)));
}

// stdillum-D65 (pbrt-v4's 5 nm table, normalised to Y = 1) gives the D65 white.
TEST(CIE, D65WhitePoint) {
    const Spectrum* d65 = GetNamedSpectrum("stdillum-D65");
    ASSERT_NE(d65, nullptr);
    XYZ xyz = SpectrumToXYZ(*d65);
    EXPECT_NEAR(xyz.Y, 1.0, 1e-3);
    EXPECT_NEAR(xyz.X / xyz.Y, 0.9505, 1e-3);
    EXPECT_NEAR(xyz.Z / xyz.Y, 1.089, 1e-3);
    // The CIE's 1 nm D65 table gives the same chromaticity (x 0.312727, y 0.329023 with these
    // colour-matching functions, /work/shared/data/README.md)
    double X = 0, Y = 0, Z = 0;
    for (int l = 360; l <= 830; ++l) {
        X += CIE_X(Float(l)) * CIE_D65(Float(l));
        Y += CIE_Y(Float(l)) * CIE_D65(Float(l));
        Z += CIE_Z(Float(l)) * CIE_D65(Float(l));
    }
    EXPECT_NEAR(X / (X + Y + Z), 0.312727, 2e-6);
    EXPECT_NEAR(Y / (X + Y + Z), 0.329023, 2e-6);
}

// Illuminant A is a Planckian radiator normalised to 100 at 560 nm.
TEST(CIE, IlluminantA) {
    EXPECT_NEAR(CIE_IlluminantA(560), 100, 1e-9);
    // CIE 015:2018 Table: S_A(380) = 9.7951, S_A(780) = 241.675
    EXPECT_NEAR(CIE_IlluminantA(380), 9.7951, 1e-3);
    EXPECT_NEAR(CIE_IlluminantA(780), 241.675, 1e-2);
}

// sRGB to XYZ (IEC 61966-2-1, D65): the standard matrix to about 4 decimals (ours uses the
// white of the tabulated D65 spectrum, which differs from the rounded xy in the 4th decimal).
TEST(ColorSpace, SRGBMatrices) {
    const RGBColorSpace& cs = RGBColorSpace::sRGB();
    const double ref[3][3] = {
        {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(cs.XYZFromRGB()[i][j], ref[i][j], 6e-4);
    // Inverse
    const double inv[3][3] = {
        {3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(cs.RGBFromXYZ()[i][j], inv[i][j], 3e-3);
    EXPECT_NEAR(cs.w.x, 0.3127, 1e-4);
    EXPECT_NEAR(cs.w.y, 0.3290, 1e-4);
}

// Every space: the illuminant maps to RGB (1, 1, 1); primaries map to the unit vectors'
// chromaticities; ToRGB inverts ToXYZ; ConvertTo composes.
TEST(ColorSpace, AllSpacesConsistent) {
    for (std::string_view name : RGBColorSpace::Names()) {
        SCOPED_TRACE(std::string(name));
        const RGBColorSpace* cs = RGBColorSpace::GetNamed(name);
        ASSERT_NE(cs, nullptr);
        RGB white = cs->ToRGB(SpectrumToXYZ(Spectrum(cs->Illuminant())));
        EXPECT_NEAR(white.r, 1, 1e-4);
        EXPECT_NEAR(white.g, 1, 1e-4);
        EXPECT_NEAR(white.b, 1, 1e-4);
        Point2f pr = cs->ToXYZ(RGB(1, 0, 0)).xy();
        EXPECT_NEAR(pr.x, cs->r.x, 1e-5);
        EXPECT_NEAR(pr.y, cs->r.y, 1e-5);
        Point2f pb = cs->ToXYZ(RGB(0, 0, 1)).xy();
        EXPECT_NEAR(pb.x, cs->b.x, 1e-5);
        EXPECT_NEAR(pb.y, cs->b.y, 1e-5);
        RGB c(0.2f, 0.7f, 0.4f);
        RGB back = cs->ToRGB(cs->ToXYZ(c));
        EXPECT_NEAR(back.r, c.r, 1e-5);
        EXPECT_NEAR(back.g, c.g, 1e-5);
        EXPECT_NEAR(back.b, c.b, 1e-5);
        RGB viaSRGB = Mul(RGBColorSpace::sRGB().ConvertTo(*cs), c);
        RGB direct = cs->ToRGB(RGBColorSpace::sRGB().ToXYZ(c));
        EXPECT_NEAR(viaSRGB.r, direct.r, 1e-5);
        EXPECT_NEAR(viaSRGB.g, direct.g, 1e-5);
        EXPECT_NEAR(viaSRGB.b, direct.b, 1e-5);
    }
    EXPECT_EQ(RGBColorSpace::GetNamed("no-such-space"), nullptr);
    // ACES2065-1's white is ACES D60 (x 0.32168, y 0.33767)
    EXPECT_NEAR(RGBColorSpace::ACES2065_1().w.x, 0.32168, 5e-4);
    EXPECT_NEAR(RGBColorSpace::ACES2065_1().w.y, 0.33767, 5e-4);
}
