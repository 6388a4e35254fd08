// Degree and angle of polarisation pictures from Stokes layers (core/image/polarization_view.h).
#include "core/image/polarization_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "core/image/color_encoding.h"
#include "spectral/color.h"

using namespace kiln;

namespace {

// One pixel per Stokes vector, grey in every layer (so each layer's luminance is its value).
Image StokesImage(const std::vector<std::array<Float, 4>>& pixels) {
    std::vector<std::string> names;
    for (const char* k : {"S0", "S1", "S2", "S3"})
        for (const char* c : {"R", "G", "B"}) names.push_back(std::string(k) + "." + c);
    Image image(PixelFormat::Float, Point2i(int(pixels.size()), 1), names);
    for (int x = 0; x < int(pixels.size()); ++x)
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c)
                image.SetChannel({x, 0}, 3 * k + c, pixels[size_t(x)][size_t(k)]);
    return image;
}

RGB Displayed(const Image& image, int x) {
    return RGB(LinearToSRGB(image.GetChannel({x, 0}, 0)), LinearToSRGB(image.GetChannel({x, 0}, 1)),
               LinearToSRGB(image.GetChannel({x, 0}, 2)));
}

void ExpectRGB(RGB a, Float r, Float g, Float b) {
    EXPECT_NEAR(a.r, r, 0.01f);
    EXPECT_NEAR(a.g, g, 0.01f);
    EXPECT_NEAR(a.b, b, 0.01f);
}

}  // namespace

TEST(PolarizationView, DegreeAngleTypeAndChirality) {
    Image s = StokesImage({{1, 1, 0, 0},          // horizontal, fully polarised
                           {1, 0, 0.5f, 0},       // half polarised at 45 degrees
                           {1, 0, 0, -0.6f},      // left circular, 0.6
                           {1, 0, 0, 0},          // unpolarised
                           {1e-6f, 1e-6f, 0, 0},  // too dark to say
                           {2, 0, -1, 0}});       // half polarised at 135 degrees
    auto views = PolarizationViews(s, RGBColorSpace::sRGB());
    ASSERT_EQ(views.size(), 6u);
    std::map<std::string, Image> v(views.begin(), views.end());
    const Image &dolp = v.at("dolp"), &aolp = v.at("aolp"), &dop = v.at("dop"), &aop = v.at("aop"),
                &type = v.at("type"), &chirality = v.at("chirality");
    const Float cyan[3] = {22 / 255.f, 247 / 255.f, 247 / 255.f};
    const Float yellow[3] = {252 / 255.f, 251 / 255.f, 10 / 255.f};
    // Horizontal
    ExpectRGB(Displayed(dolp, 0), 1, 1, 1);
    ExpectRGB(Displayed(aolp, 0), 1, 0, 0);  // hue 0: red
    ExpectRGB(Displayed(dop, 0), 1, 0, 0);
    ExpectRGB(Displayed(aop, 0), 0, 1, 0);  // horizontal: green
    ExpectRGB(Displayed(type, 0), cyan[0], cyan[1], cyan[2]);
    ExpectRGB(Displayed(chirality, 0), 0, 0, 0);
    // 45 degrees, half
    ExpectRGB(Displayed(dolp, 1), 0.5f, 0.5f, 0.5f);
    ExpectRGB(Displayed(aolp, 1), 0.25f, 0.5f, 0);  // hue 1/4 at value 0.5
    ExpectRGB(Displayed(dop, 1), 0.5f, 0, 0);
    ExpectRGB(Displayed(aop, 1), 0.5f, 0.5f, 0);  // +45: yellow
    ExpectRGB(Displayed(type, 1), cyan[0] / 2, cyan[1] / 2, cyan[2] / 2);
    // Left circular
    ExpectRGB(Displayed(dolp, 2), 0, 0, 0);
    ExpectRGB(Displayed(aolp, 2), 0, 0, 0);
    ExpectRGB(Displayed(dop, 2), 0.6f, 0, 0);
    ExpectRGB(Displayed(aop, 2), 0, 0, 0);
    ExpectRGB(Displayed(type, 2), 0.6f * yellow[0], 0.6f * yellow[1], 0.6f * yellow[2]);
    ExpectRGB(Displayed(chirality, 2), 0, 0, 0.36f);  // left: blue
    // Unpolarised, and too dark: black everywhere
    for (int x : {3, 4})
        for (const auto& [name, image] : views) ExpectRGB(Displayed(image, x), 0, 0, 0);
    // 135 degrees, half
    ExpectRGB(Displayed(aolp, 5), 0.25f, 0, 0.5f);  // hue 3/4 at value 0.5
    ExpectRGB(Displayed(aop, 5), 0, 0, 0.5f);       // -45: blue
}

TEST(PolarizationView, NeedsStokesLayers) {
    Image rgb(PixelFormat::Float, Point2i(2, 2), {"R", "G", "B"});
    EXPECT_THROW(PolarizationViews(rgb, RGBColorSpace::sRGB()), std::runtime_error);
}
