#include "spectral/infrared_metal_data.h"

#include <algorithm>
#include <iterator>

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

}  // namespace

std::optional<std::complex<double>> MeasuredInfraredIndex(std::string_view symbol,
                                                          double lambda_nm) {
    if (symbol != "Fe") return std::nullopt;
    const Row* begin = std::begin(kIron);
    const Row* end = std::end(kIron);
    if (!(lambda_nm >= begin->lambda && lambda_nm <= (end - 1)->lambda)) return std::nullopt;
    const Row* hi = std::lower_bound(begin, end, lambda_nm,
                                     [](const Row& r, double l) { return r.lambda < l; });
    if (hi == begin) return std::complex<double>(hi->n, hi->k);
    const Row* lo = hi - 1;
    double t = (lambda_nm - lo->lambda) / (hi->lambda - lo->lambda);
    return std::complex<double>(lo->n + t * (hi->n - lo->n), lo->k + t * (hi->k - lo->k));
}

}  // namespace kiln
