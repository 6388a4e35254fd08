// Interpolated look-ups into the CIE tables of cie_data.cpp.
#include "spectral/cie.h"

#include <cmath>

namespace kiln {

namespace {

// Linear interpolation in a table sampled at 1 nm from lambdaMin; 0 outside it.
Float Lookup1nm(const float* table, int lambdaMin, int count, Float lambda) {
    Float x = lambda - Float(lambdaMin);
    if (!(x >= 0) || x > Float(count - 1)) return 0;
    int i = std::min(int(x), count - 2);
    Float t = x - Float(i);
    return Lerp(t, table[i], table[i + 1]);
}

}  // namespace

Float CIE_X(Float l) { return Lookup1nm(cie::kX, cie::kCMFLambdaMin, cie::kNumCMFSamples, l); }
Float CIE_Y(Float l) { return Lookup1nm(cie::kY, cie::kCMFLambdaMin, cie::kNumCMFSamples, l); }
Float CIE_Z(Float l) { return Lookup1nm(cie::kZ, cie::kCMFLambdaMin, cie::kNumCMFSamples, l); }

Float CIE_D65(Float l) { return Lookup1nm(cie::kD65, cie::kD65LambdaMin, cie::kNumD65Samples, l); }

double CIE_IlluminantA(double lambda_nm) {
    if (!(lambda_nm > 0)) return 0;
    constexpr double c2 = 1.435e7, T = 2848, ref = 560;  // nm K, K, nm
    double num = std::expm1(c2 / (T * ref));
    double den = std::expm1(c2 / (T * lambda_nm));
    return 100 * std::pow(ref / lambda_nm, 5) * num / den;
}

}  // namespace kiln
