// CIE colorimetric tables: the 1931 2-degree observer and standard illuminants D65 and A.
//
// The colour-matching functions xbar, ybar, zbar are dimensionless weights per nanometre of
// wavelength; illuminant SPDs are relative (100 at 560 nm). Tables are in cie_data.cpp with
// their sources; the functions here interpolate them linearly in wavelength (nm).
#pragma once

#include "base/vecmath.h"

namespace kiln {

namespace cie {
// CIE 1931 2-degree colour-matching functions, 1 nm steps, lambda = kCMFLambdaMin + i nm.
inline constexpr int kCMFLambdaMin = 360, kCMFLambdaMax = 830;
inline constexpr int kNumCMFSamples = kCMFLambdaMax - kCMFLambdaMin + 1;
extern const float kX[kNumCMFSamples];
extern const float kY[kNumCMFSamples];
extern const float kZ[kNumCMFSamples];

// CIE standard illuminant D65, relative SPD (100 at 560 nm), 1 nm, lambda = 300 + i nm.
inline constexpr int kD65LambdaMin = 300, kD65LambdaMax = 830;
inline constexpr int kNumD65Samples = kD65LambdaMax - kD65LambdaMin + 1;
extern const float kD65[kNumD65Samples];
}  // namespace cie

// Sum of ybar over the 1 nm table (360-830 nm), in nm: the integral of ybar. pbrt-v4's
// normalisation constant: XYZ = integral(s cmf) / CIE_Y_integral gives Y = 1 for s = 1.
inline constexpr Float CIE_Y_integral = 106.856917f;

// Colour-matching functions at lambda (nm), dimensionless; 0 outside 360-830 nm.
Float CIE_X(Float lambda_nm);
Float CIE_Y(Float lambda_nm);
Float CIE_Z(Float lambda_nm);

// D65 relative SPD at lambda (nm), 100 at 560 nm; 0 outside 300-830 nm.
Float CIE_D65(Float lambda_nm);

// CIE standard illuminant A, relative SPD (100 at 560 nm), at lambda (nm): by definition a
// Planckian radiator, S_A = 100 (560/l)^5 (e^(c2/(2848 K * 560 nm)) - 1) / (e^(c2/(2848 K l)) - 1)
// with the CIE's c2 = 1.435e7 nm K (CIE 015:2018; = 2856 K with today's c2 = 1.4388e7 nm K).
double CIE_IlluminantA(double lambda_nm);

}  // namespace kiln
