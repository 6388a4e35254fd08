#include "spectral/measured_media.h"

#include <string_view>

#include "spectral/color.h"

namespace kiln {

namespace {

struct MeasuredMedium {
    std::string_view name;
    RGB sigma_a, sigma_s;  // mm^-1, sRGB
};

// Measured absorption and (reduced) scattering coefficients, mm^-1, in sRGB, under the names
// pbrt-v4 gives them (its GetMediumScatteringProperties, with the same values so that scenes
// render alike). Sources: H. W. Jensen, S. R. Marschner, M. Levoy, P. Hanrahan, "A Practical
// Model for Subsurface Light Transport", SIGGRAPH 2001, Table 2 (Apple to Wholemilk); S. G.
// Narasimhan, M. Gupta, C. Donner, R. Ramamoorthi, S. K. Nayar, H. W. Jensen, "Acquiring
// Scattering Properties of Participating Media by Dilution", SIGGRAPH 2006, Table 1 (Lowfat
// Milk onwards).
// clang-format off
const MeasuredMedium kMeasuredMedia[] = {
    {"Apple", {0.0030, 0.0034, 0.046}, {2.29, 2.39, 1.97}},
    {"Chicken1", {0.015, 0.077, 0.19}, {0.15, 0.21, 0.38}},
    {"Chicken2", {0.018, 0.088, 0.20}, {0.19, 0.25, 0.32}},
    {"Cream", {0.0002, 0.0028, 0.0163}, {7.38, 5.47, 3.15}},
    {"Ketchup", {0.061, 0.97, 1.45}, {0.18, 0.07, 0.03}},
    {"Marble", {0.0021, 0.0041, 0.0071}, {2.19, 2.62, 3.00}},
    {"Potato", {0.0024, 0.0090, 0.12}, {0.68, 0.70, 0.55}},
    {"Skimmilk", {0.0014, 0.0025, 0.0142}, {0.70, 1.22, 1.90}},
    {"Skin1", {0.032, 0.17, 0.48}, {0.74, 0.88, 1.01}},
    {"Skin2", {0.013, 0.070, 0.145}, {1.09, 1.59, 1.79}},
    {"Spectralon", {0.00, 0.00, 0.00}, {11.6, 20.4, 14.9}},
    {"Wholemilk", {0.0011, 0.0024, 0.014}, {2.55, 3.21, 3.77}},
    {"Lowfat Milk", {0.002875, 0.00575, 0.0115}, {0.89187, 1.5136, 2.532}},
    {"Reduced Milk", {0.0025556, 0.0051111, 0.012778}, {2.4858, 3.1669, 4.5214}},
    {"Regular Milk", {0.0015333, 0.0046, 0.019933}, {4.5513, 5.8294, 7.136}},
    {"Espresso", {4.7984, 6.5751, 8.8493}, {0.72378, 0.84557, 1.0247}},
    {"Mint Mocha Coffee", {3.772, 5.8228, 7.82}, {0.31602, 0.38538, 0.48131}},
    {"Lowfat Soy Milk", {0.0014375, 0.0071875, 0.035937}, {0.30576, 0.34233, 0.61664}},
    {"Regular Soy Milk", {0.0019167, 0.0095833, 0.065167}, {0.59223, 0.73866, 1.4693}},
    {"Lowfat Chocolate Milk", {0.0115, 0.0368, 0.1564}, {0.64925, 0.83916, 1.1057}},
    {"Regular Chocolate Milk", {0.010063, 0.043125, 0.14375}, {1.4585, 2.1289, 2.9527}},
    {"Coke", {0.10014, 0.16503, 0.2468}, {8.9053e-05, 8.372e-05, 0}},
    {"Pepsi", {0.091641, 0.14158, 0.20729}, {6.1697e-05, 4.2564e-05, 0}},
    {"Sprite", {0.001886, 0.0018308, 0.0020025}, {6.0306e-06, 6.4139e-06, 6.5504e-06}},
    {"Gatorade", {0.024794, 0.019289, 0.008878}, {0.0024574, 0.003007, 0.0037325}},
    {"Chardonnay", {0.010782, 0.011855, 0.023997}, {1.7982e-05, 1.3758e-05, 1.2023e-05}},
    {"White Zinfandel", {0.012072, 0.016184, 0.019843}, {1.7501e-05, 1.9069e-05, 1.288e-05}},
    {"Merlot", {0.11632, 0.25191, 0.29434}, {2.1129e-05, 0, 0}},
    {"Budweiser Beer", {0.011492, 0.024911, 0.057786}, {2.4356e-05, 2.4079e-05, 1.0564e-05}},
    {"Coors Light Beer", {0.006164, 0.013984, 0.034983}, {5.0922e-05, 4.301e-05, 0}},
    {"Clorox", {0.0033542, 0.014892, 0.026297}, {0.0024035, 0.0031373, 0.003991}},
    {"Apple Juice", {0.012957, 0.023741, 0.052184}, {0.00013612, 0.00015836, 0.000227}},
    {"Cranberry Juice", {0.039437, 0.094223, 0.12426}, {0.00010402, 0.00011646, 7.8139e-05}},
    {"Grape Juice", {0.10404, 0.23958, 0.29325}, {5.382e-05, 0, 0}},
    {"Ruby Grapefruit Juice", {0.085867, 0.18314, 0.25262}, {0.011002, 0.010927, 0.011036}},
    {"White Grapefruit Juice", {0.0138, 0.018831, 0.056781}, {0.22826, 0.23998, 0.32748}},
    {"Shampoo", {0.014107, 0.045693, 0.061717}, {0.0007176, 0.0008303, 0.0009016}},
    {"Strawberry Shampoo", {0.01449, 0.05796, 0.075823}, {0.00015671, 0.00015947, 1.518e-05}},
    {"Head & Shoulders Shampoo", {0.084621, 0.15688, 0.20365}, {0.023805, 0.028804, 0.034306}},
    {"Lemon Tea Powder", {2.4288, 4.5757, 7.2127}, {0.040224, 0.045264, 0.051081}},
    {"Orange Powder", {0.001449, 0.003441, 0.007863}, {0.00015617, 0.00017482, 0.0001762}},
    {"Pink Lemonade Powder", {0.001165, 0.002366, 0.003195}, {0.00012103, 0.00013073, 0.00012528}},
    {"Cappuccino Powder", {35.844, 49.547, 61.084}, {1.8436, 2.5851, 2.1662}},
    {"Salt Powder", {0.28415, 0.3257, 0.34148}, {0.027333, 0.032451, 0.031979}},
    {"Sugar Powder", {0.012638, 0.031051, 0.050124}, {0.00022272, 0.00025513, 0.000271}},
    {"Suisse Mocha Powder", {17.502, 27.004, 35.433}, {2.7979, 3.5452, 4.3365}},
    {"Pacific Ocean Surface Water", {0.031845, 0.031324, 0.030147}, {0.0001764, 0.00032095, 0.00019617}},
};
// clang-format on

}  // namespace

std::optional<std::pair<Spectrum, Spectrum>> MeasuredMediumCoefficients(const std::string& name) {
    for (const MeasuredMedium& m : kMeasuredMedia)
        if (m.name == name)
            return std::make_pair(Spectrum(RGBUnboundedSpectrum(RGBColorSpace::sRGB(), m.sigma_a)),
                                  Spectrum(RGBUnboundedSpectrum(RGBColorSpace::sRGB(), m.sigma_s)));
    return std::nullopt;
}

}  // namespace kiln
