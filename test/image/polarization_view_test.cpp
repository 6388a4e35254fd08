// Degree and angle of polarisation pictures from Stokes layers (core/image/polarization_view.h).
#include "core/image/polarization_view.h"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(PolarizationView, DegreeAndAngle) {
    Image s = StokesImage({{1, 1, 0, 0},          // horizontal, fully polarised
                           {1, 0, 0.5f, 0},       // half polarised at 45 degrees
                           {1, 0, 0, -0.6f},      // left circular, 0.6
                           {1, 0, 0, 0},          // unpolarised
                           {1e-6f, 1e-6f, 0, 0},  // too dark to say
                           {2, 0, -1, 0}});       // half polarised at 135 degrees
    PolarizationPictures p = PolarizationViews(s, RGBColorSpace::sRGB());
    ExpectRGB(Displayed(p.degree, 0), 1, 0, 0);
    ExpectRGB(Displayed(p.angle, 0), 1, 0, 0);  // hue 0: red
    ExpectRGB(Displayed(p.degree, 1), 0.5f, 0, 0);
    ExpectRGB(Displayed(p.angle, 1), 0.25f, 0.5f, 0);  // hue 1/4 at value 0.5
    ExpectRGB(Displayed(p.degree, 2), 0, 0, 0.6f);
    ExpectRGB(Displayed(p.angle, 2), 0, 0, 0);  // no linear polarisation
    ExpectRGB(Displayed(p.degree, 3), 0, 0, 0);
    ExpectRGB(Displayed(p.degree, 4), 0, 0, 0);
    ExpectRGB(Displayed(p.angle, 4), 0, 0, 0);
    ExpectRGB(Displayed(p.degree, 5), 0.5f, 0, 0);
    ExpectRGB(Displayed(p.angle, 5), 0.25f, 0, 0.5f);  // hue 3/4 at value 0.5
}

TEST(PolarizationView, NeedsStokesLayers) {
    Image rgb(PixelFormat::Float, Point2i(2, 2), {"R", "G", "B"});
    EXPECT_THROW(PolarizationViews(rgb, RGBColorSpace::sRGB()), std::runtime_error);
}
