#include "spectral/infrared_metal_data.h"

#include <algorithm>
#include <span>

namespace kiln {

namespace {

struct Row {
    double lambda, n, k;  // nm, dimensionless
};

// Iron: M. A. Ordal, R. J. Bell, R. W. Alexander, L. A. Newquist, M. R. Querry, "Optical
// properties of Al, Fe, Ti, Ta, W, and Mo at submillimeter wavelengths", Appl. Opt. 27, 1203-1209
// (1988), doi:10.1364/AO.27.001203 (Kramers-Kronig analysis of measured absorptance and
// reflectance joined to earlier data), as tabulated by the refractiveindex.info database
// (database/data/main/Fe/nk/Ordal.yml, CC0 1.0, snapshot ff11b5897ef0); its points up to 25 um,
// wavelength converted from um, values rounded to 5 significant figures.
const Row kIron[] = {
    {667, 2.8735, 3.359},    {714, 2.9443, 3.4648},   {769, 2.9736, 3.5472},
    {833, 3.0343, 3.7486},   {909, 3.0937, 3.8974},   {1000, 3.1838, 4.1442},
    {1050, 3.2228, 4.2852},  {1110, 3.2751, 4.4419},  {1180, 3.3344, 4.6138},
    {1250, 3.399, 4.8033},   {1330, 3.4671, 5.0147},  {1430, 3.5376, 5.2542},
    {1540, 3.61, 5.5306},    {1670, 3.6846, 5.8553},  {1820, 3.7629, 6.2434},
    {2000, 3.8476, 6.7152},  {2110, 3.8935, 6.9908},  {2220, 3.9427, 7.2989},
    {2350, 3.996, 7.645},    {2500, 4.0543, 8.0361},  {2670, 4.119, 8.4808},
    {2860, 4.1916, 8.9905},  {3080, 4.2741, 9.5797},  {3330, 4.3692, 10.268},
    {3640, 4.4807, 11.081},  {4000, 4.614, 12.057},   {4440, 4.777, 13.247},
    {5000, 4.9822, 14.732},  {5710, 5.2507, 16.634},  {6670, 5.6203, 19.16},
    {8000, 6.1662, 22.672},  {10000, 7.0687, 27.902}, {11100, 7.6216, 30.807},
    {12500, 8.3468, 34.384}, {14300, 9.3533, 38.937}, {16700, 10.826, 44.922},
    {20000, 13.131, 53.124}, {22200, 14.82, 58.47},   {25000, 17.093, 65.004},
};

// Brass (70 % Cu, 30 % Zn): M. R. Querry, "Optical constants", Contractor Report
// CRDC-CR-85034 (1985), as tabulated by the refractiveindex.info database
// (database/data/other/alloys/Cu-Zn/nk/Querry-Cu70Zn30.yml, CC0 1.0, snapshot ff11b5897ef0);
// pbrt-v4's metal-CuZn is this file's 340-850 nm rows. 290 nm - 20.8 um, the file's own points
// thinned by gen/infrared_metal_tables.py (those dropped lie within 0.3 % of the lines between
// those kept).
const Row kBrass[] = {
    {290, 1.358, 1.688},      {310, 1.419, 1.764},      {330, 1.473, 1.807},
    {340, 1.494, 1.815},      {350, 1.504, 1.815},      {370, 1.497, 1.818},
    {390, 1.471, 1.813},      {400, 1.445, 1.805},      {410, 1.405, 1.794},
    {420, 1.35, 1.786},       {430, 1.278, 1.784},      {440, 1.191, 1.797},
    {450, 1.094, 1.829},      {460, 0.994, 1.883},      {470, 0.9, 1.957},
    {480, 0.816, 2.046},      {490, 0.745, 2.145},      {500, 0.686, 2.25},
    {510, 0.639, 2.358},      {520, 0.602, 2.464},      {530, 0.573, 2.568},
    {560, 0.505, 2.86},       {570, 0.484, 2.958},      {580, 0.468, 3.059},
    {600, 0.45, 3.253},       {610, 0.452, 3.345},      {630, 0.445, 3.522},
    {690, 0.445, 4.025},      {770, 0.46, 4.657},       {820, 0.481, 5.039},
    {860, 0.494, 5.346},      {900, 0.523, 5.65},       {1010, 0.61, 6.437},
    {1060, 0.642, 6.792},     {1160, 0.726, 7.487},     {1200, 0.761, 7.76},
    {1230, 0.775, 7.967},     {1300, 0.844, 8.459},     {1370, 0.917, 8.928},
    {1440, 0.978, 9.405},     {1610, 1.171, 10.552},    {1670, 1.252, 10.943},
    {1740, 1.335, 11.39},     {1780, 1.372, 11.662},    {1850, 1.468, 12.135},
    {1960, 1.633, 12.855},    {2000, 1.711, 13.101},    {2030, 1.748, 13.295},
    {2100, 1.878, 13.725},    {2240, 2.093, 14.57},     {2290, 2.171, 14.853},
    {2360, 2.248, 15.283},    {2410, 2.337, 15.578},    {2525.3, 2.497, 16.268},
    {2785.5, 2.861, 17.832},  {3076.9, 3.356, 19.517},  {3322.3, 3.812, 20.993},
    {3731.3, 4.564, 23.279},  {3745.3, 4.571, 23.356},  {3787.9, 4.672, 23.589},
    {4291.8, 5.646, 26.322},  {4950.5, 7.002, 29.654},  {6369.4, 9.825, 36.528},
    {7352.9, 12.118, 40.834}, {7936.5, 13.266, 43.088}, {8771.9, 14.652, 46.456},
    {8849.6, 14.912, 46.78},  {8928.6, 15.051, 47.114}, {9009, 15.051, 47.453},
    {10204, 17.276, 52.438},  {12820, 22.542, 62.357},  {17241, 30.915, 77.478},
    {20833, 37.298, 89.081},
};

// Magnesia (bulk crystalline MgO): R. A. Synowicki, T. E. Tiwald, "Optical properties of bulk
// c-ZrO2, c-MgO and a-As2S3 determined by variable angle spectroscopic ellipsometry", Thin
// Solid Films 455-456, 248-255 (2004), doi:10.1016/j.tsf.2004.02.028 (their oscillator model,
// clear to about 7 um, then the edge of the reststrahlen band: n falls below 1 near 12 um and
// k rises past 1 at 15 um), as tabulated by the refractiveindex.info database
// (database/data/main/MgO/nk/Synowicki.yml, CC0 1.0, snapshot ff11b5897ef0). 288 nm - 20.6
// um, thinned as brass.
const Row kMagnesia[] = {
    {287.54, 1.8032, 1.6863e-05}, {376.3, 1.7595, 5.0916e-06}, {577.99, 1.7292, 5.1642e-06},
    {1303.6, 1.7129, 5.2133e-06}, {3430.2, 1.681, 4.6492e-05}, {5474.9, 1.6176, 0.00022121},
    {7205, 1.5323, 0.0006239},    {8620.6, 1.4323, 0.001375},  {9721.6, 1.3273, 0.0025761},
    {10508, 1.2315, 0.0041621},   {10980, 1.1628, 0.0056761},  {11452, 1.0828, 0.0079364},
    {11766, 1.0215, 0.010111},    {11924, 0.98803, 0.011494},  {12081, 0.95227, 0.01314},
    {12238, 0.91395, 0.01512},    {12395, 0.8727, 0.017531},   {12553, 0.82804, 0.020512},
    {12710, 0.77934, 0.024264},   {12867, 0.72576, 0.029097},  {13025, 0.66612, 0.035521},
    {13182, 0.59867, 0.044434},   {13339, 0.52066, 0.057644},  {13496, 0.42748, 0.079499},
    {13654, 0.31253, 0.12356},    {13811, 0.19364, 0.22736},   {13968, 0.13836, 0.36385},
    {14126, 0.12055, 0.47853},    {14283, 0.11506, 0.57504},   {14440, 0.11501, 0.65936},
    {14597, 0.11789, 0.73476},    {14755, 0.12241, 0.803},     {15069, 0.13223, 0.92183},
    {15227, 0.13542, 0.97403},    {15384, 0.13611, 1.0228},    {15541, 0.13361, 1.0696},
    {15698, 0.12785, 1.116},      {15856, 0.11935, 1.1635},    {16328, 0.087249, 1.3186},
    {16485, 0.077168, 1.3745},    {16642, 0.068151, 1.4318},   {16799, 0.060295, 1.4903},
    {16957, 0.053567, 1.5497},    {17114, 0.047867, 1.6097},   {17271, 0.043069, 1.6703},
    {17429, 0.039046, 1.7314},    {17586, 0.03568, 1.7931},    {17743, 0.032868, 1.8554},
    {18058, 0.028574, 1.9819},    {18372, 0.02563, 2.1118},    {18687, 0.023675, 2.2457},
    {19159, 0.022107, 2.4563},    {19631, 0.021784, 2.6819},   {20103, 0.022497, 2.9272},
    {20574, 0.024217, 3.198},
};

// The rows of the metal with symbol `symbol`, if any
std::span<const Row> RowsOf(std::string_view symbol) {
    if (symbol == "Fe") return kIron;
    if (symbol == "CuZn") return kBrass;
    if (symbol == "MgO") return kMagnesia;
    return {};
}

}  // namespace

std::optional<std::complex<double>> MeasuredInfraredIndex(std::string_view symbol,
                                                          double lambda_nm) {
    std::span<const Row> rows = RowsOf(symbol);
    if (rows.empty()) return std::nullopt;
    const Row* begin = rows.data();
    const Row* end = rows.data() + rows.size();
    if (!(lambda_nm >= begin->lambda && lambda_nm <= (end - 1)->lambda)) return std::nullopt;
    const Row* hi = std::lower_bound(begin, end, lambda_nm,
                                     [](const Row& r, double l) { return r.lambda < l; });
    if (hi == begin) return std::complex<double>(hi->n, hi->k);
    const Row* lo = hi - 1;
    double t = (lambda_nm - lo->lambda) / (hi->lambda - lo->lambda);
    return std::complex<double>(lo->n + t * (hi->n - lo->n), lo->k + t * (hi->k - lo->k));
}

}  // namespace kiln
