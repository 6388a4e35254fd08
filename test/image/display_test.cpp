// Display transform: OCIO config, monotone ramps, hue-preserving gamut mapping, filmic curve.
#include "core/image/display.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include "spectral/cie.h"
#include "spectral/planck.h"

namespace kiln {
namespace {

// Hue angle (degrees) of a linear sRGB colour: the direction of its CIE xy chromaticity seen
// from the D65 white point.
double HueAngle(RGB c) {
    XYZ xyz = RGBColorSpace::sRGB().ToXYZ(c);
    Point2f xy = xyz.xy();
    return std::atan2(double(xy.y) - 0.3290, double(xy.x) - 0.3127) * 180 / M_PI;
}

Image Row(const std::vector<RGB>& colours) {
    Image im(PixelFormat::Float, {int(colours.size()), 1}, {"R", "G", "B"});
    for (size_t i = 0; i < colours.size(); ++i)
        for (int c = 0; c < 3; ++c) im.SetChannel({int(i), 0}, c, colours[i][c]);
    return im;
}

TEST(Display, ConfigHasTheViews) {
    std::vector<std::string> views = DisplayViews();
    for (const char* v : {"Standard", "Filmic", "ACES", "Glow", "Raw"})
        EXPECT_NE(std::find(views.begin(), views.end(), v), views.end()) << v;
}

TEST(Display, StandardIsTheSRGBEncoding) {
    Image out =
        ToDisplayImage(Row({RGB(0.18f, 0.5f, 0.f), RGB(1, 1, 1)}), RGBColorSpace::sRGB(), {});
    EXPECT_EQ(out.Format(), PixelFormat::U256);
    EXPECT_EQ(out.NChannels(), 3);
    EXPECT_NEAR(LinearToSRGB(out.GetChannel({0, 0}, 0)), LinearToSRGB(0.18f), 0.5f / 255 + 1e-5f);
    EXPECT_NEAR(LinearToSRGB(out.GetChannel({0, 0}, 1)), LinearToSRGB(0.5f), 0.5f / 255 + 1e-5f);
    EXPECT_FLOAT_EQ(out.GetChannel({1, 0}, 2), 1);
    // Exposure +1 EV doubles the linear values.
    Image e = ToDisplayImage(Row({RGB(0.1f, 0.1f, 0.1f)}), RGBColorSpace::sRGB(), {"Standard", 1});
    EXPECT_NEAR(LinearToSRGB(e.GetChannel({0, 0}, 0)), LinearToSRGB(0.2f), 0.5f / 255 + 1e-5f);
}

TEST(Display, GreyRampsAreMonotone) {
    std::vector<RGB> ramp;
    for (int i = 0; i <= 200; ++i) {
        Float v = std::pow(10.f, -4 + 7 * i / 200.f);  // 1e-4 .. 1e3
        ramp.push_back(RGB(v, v, v));
    }
    for (const char* view : {"Standard", "Filmic", "ACES"}) {
        Image out = ToDisplayImage(Row(ramp), RGBColorSpace::sRGB(), {view, 0});
        for (int i = 1; i <= 200; ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_GE(out.GetChannel({i, 0}, c), out.GetChannel({i - 1, 0}, c)) << view << i;
        // Grey stays grey.
        EXPECT_EQ(out.GetChannel({100, 0}, 0), out.GetChannel({100, 0}, 2)) << view;
    }
}

TEST(Display, FilmicCompressesHighlights) {
    std::vector<RGB> ramp;
    for (int i = 0; i <= 100; ++i) {
        Float v = std::pow(10.f, -3 + 6 * i / 100.f);  // 1e-3 .. 1e3
        ramp.push_back(RGB(v, v, v));
    }
    Image f = ToDisplayEncodedFloat(Row(ramp), RGBColorSpace::sRGB(), {"Filmic", 0});
    for (int i = 1; i <= 100; ++i) EXPECT_GT(f.GetChannel({i, 0}, 1), f.GetChannel({i - 1, 0}, 1));
    EXPECT_LT(f.GetChannel({100, 0}, 0), 1.f);  // 1e3
    EXPECT_GT(f.GetChannel({100, 0}, 0), 0.99f);
    // Still distinguishable from white in 8 bits at 100x mid grey... well above 1.
    Image q = ToDisplayImage(Row({RGB(50, 50, 50)}), RGBColorSpace::sRGB(), {"Filmic", 0});
    EXPECT_LT(q.GetChannel({0, 0}, 0), 1.f);
    // Mid grey lands mid-range.
    Image m = ToDisplayEncodedFloat(Row({RGB(0.18f, 0.18f, 0.18f)}), RGBColorSpace::sRGB(),
                                    {"Filmic", 0});
    EXPECT_NEAR(m.GetChannel({0, 0}, 0), 0.4f, 0.05f);
}

TEST(Display, GamutMappingKeepsHueAndLuminance) {
    RGB red(1, -0.05f, -0.1f);
    RGB mapped = MapToDisplayGamut(red, false);
    for (int c = 0; c < 3; ++c) EXPECT_GE(mapped[c], 0);
    auto lum = [](RGB c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
    EXPECT_NEAR(lum(mapped), lum(red), 1e-5f);
    EXPECT_NEAR(HueAngle(mapped), HueAngle(red), 0.1);
    // Above 1 (Standard): ratios kept.
    RGB bright = MapToDisplayGamut(RGB(4, 2, 1), true);
    EXPECT_FLOAT_EQ(bright.r, 1);
    EXPECT_FLOAT_EQ(bright.g, 0.5f);
    EXPECT_FLOAT_EQ(bright.b, 0.25f);
    EXPECT_EQ(MapToDisplayGamut(RGB(-1, -1, 2), true).r, 0);  // negative luminance: black
}

TEST(Display, OutOfGamutRedKeepsItsHue) {
    // Saturated out-of-gamut reds (negative G/B, as deep-red glow produces) and a bright
    // orange glow far above 1.
    std::vector<RGB> in = {RGB(1, -0.05f, -0.1f), RGB(3, -0.4f, -0.2f), RGB(20, 2, -0.5f)};
    for (const char* view : {"Standard", "Filmic"}) {
        Image out = ToDisplayImage(Row(in), RGBColorSpace::sRGB(), {view, 0});
        for (int i = 0; i < int(in.size()); ++i) {
            RGB shown(out.GetChannel({i, 0}, 0), out.GetChannel({i, 0}, 1),
                      out.GetChannel({i, 0}, 2));
            double tol = std::string(view) == "Standard" ? 1 : 3;
            EXPECT_NEAR(HueAngle(shown), HueAngle(in[i]), tol) << view << " " << i;
            // Not pink/magenta (blue above green) nor yellow (green near red).
            if (i < 2) {
                EXPECT_GT(shown.r, 5 * std::max(shown.g, shown.b)) << view << " " << i;
            }
            EXPECT_GE(shown.g, shown.b * (i == 1 ? 0.f : 1.f)) << view << " " << i;
        }
    }
    // A per-channel clip would shift the hue of the deep red by far more.
    EXPECT_GT(std::abs(HueAngle(RGB(1, 0, 0)) - HueAngle(in[1])), 4.0);
}

TEST(Display, FilmicHuePreservingStep) {
    RGB grey = FilmicHuePreserving(RGB(2, 2, 2), 0.7f);
    EXPECT_FLOAT_EQ(grey.r, 0.7f);
    EXPECT_FLOAT_EQ(grey.b, 0.7f);
    // Below the knee: a pure scaling (ratios kept); above it: mixed towards white, max kept.
    RGB low = FilmicHuePreserving(RGB(0.5f, 0.25f, 0.f), 0.4f);
    EXPECT_FLOAT_EQ(low.r, 0.4f);
    EXPECT_FLOAT_EQ(low.g, 0.2f);
    EXPECT_FLOAT_EQ(low.b, 0.f);
    RGB high = FilmicHuePreserving(RGB(40, 20, 0), 0.99f);
    EXPECT_FLOAT_EQ(high.r, 0.99f);
    EXPECT_GT(high.b, 0.5f);
    EXPECT_LT(high.b, high.g);
    EXPECT_NEAR(HueAngle(high), HueAngle(RGB(40, 20, 0)), 0.5);
}

TEST(Display, OtherColourSpacesAreConverted) {
    // Rec.2020 white is sRGB white (same D65 white).
    Image out = ToDisplayImage(Row({RGB(0.5f, 0.5f, 0.5f)}), RGBColorSpace::Rec2020(), {});
    EXPECT_NEAR(out.GetChannel({0, 0}, 0), out.GetChannel({0, 0}, 2), 0.01f);
    EXPECT_THROW(ToDisplayImage(Row({RGB()}), RGBColorSpace::sRGB(), {"Vivid", 0}),
                 std::runtime_error);
}

}  // namespace
}  // namespace kiln

namespace kiln {
namespace {

// Linear sRGB of a blackbody's spectral radiance at T (W m^-2 sr^-1 nm^-1 units).
RGB BlackbodyRGB(double T) {
    double X = 0, Y = 0, Z = 0;
    for (int l = 360; l <= 830; ++l) {
        double B = planck_radiance(l, T);
        X += B * CIE_X(Float(l));
        Y += B * CIE_Y(Float(l));
        Z += B * CIE_Z(Float(l));
    }
    return RGBColorSpace::sRGB().ToRGB(XYZ(Float(X), Float(Y), Float(Z)) / CIE_Y_integral);
}

// In one frame exposed so that 1600 K is at display white, 800 K (21 stops dimmer) must still
// read as a dim red glow in the Glow view, and 1600 K as bright orange.
TEST(Display, GlowViewShows800KAnd1600KInOneFrame) {
    RGB hot = BlackbodyRGB(1600), cool = BlackbodyRGB(800);
    Float ev = -std::log2(std::max({hot.r, hot.g, hot.b}));
    Image out = ToDisplayEncodedFloat(Row({hot, cool}), RGBColorSpace::sRGB(), {"Glow", ev});
    RGB h(out.GetChannel({0, 0}, 0), out.GetChannel({0, 0}, 1), out.GetChannel({0, 0}, 2));
    RGB c(out.GetChannel({1, 0}, 0), out.GetChannel({1, 0}, 1), out.GetChannel({1, 0}, 2));
    // Bright orange: red at full, green well below it, little blue.
    EXPECT_GT(h.r, 0.95f);
    EXPECT_GT(h.g, 0.2f);
    EXPECT_LT(h.g, 0.9f * h.r);
    EXPECT_LT(h.b, h.g);
    // Dim red: visible (encoded red well above black), much darker than the hot one, and
    // redder (less green relative to red) than 1600 K.
    EXPECT_GT(c.r, 0.2f);
    EXPECT_LT(c.r, 0.8f * h.r);
    EXPECT_LT(c.g / c.r, h.g / h.r);
    // The Standard view with the same exposure shows 800 K as black (why Glow exists).
    Image std8 = ToDisplayImage(Row({hot, cool}), RGBColorSpace::sRGB(), {"Standard", ev});
    EXPECT_EQ(std8.GetChannel({1, 0}, 0), 0);
}

}  // namespace
}  // namespace kiln
