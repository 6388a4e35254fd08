// The tables of an RGL measured BRDF (Dupuy and Jakob 2018) as pbrt-v4's MeasuredBxDFData
// builds them from a tensor file (tensor_file.h). Fields used, all float32 except where said:
//   theta_i [nt], phi_i [np]    incident elevations and azimuths (radians) at which the
//                               conditional tables are given; strictly increasing
//   wavelengths [nl]            nm, strictly increasing
//   ndf [ny, nx]                the microfacet distribution D over the square of
//                               (theta2u(theta_m), phi2u(phi_m))
//   sigma [ny, nx]              projected area sigma(wo) over (theta2u(theta_o), phi2u(phi_o))
//   vndf [np, nt, ny, nx]       visible-normal density over that square of normals, per wo
//   luminance [np, nt, n, n]    the density sampled first, over the vndf's unit square
//   spectra [np, nt, nl, n, n]  the BRDF times 4 sigma(wo) cos(theta_i) / D(wm), over the
//                               vndf's unit square
//   description (uint8 text), jacobian ([1] uint8): must exist; their values are not used
//                               (as in pbrt-v4)
// Other fields (such as `rgb` or `isotropic`) are ignored, as pbrt-v4 does. The BRDF is
// isotropic when phi_i has at most 2 values (phi of the normals is then relative to phi_o);
// an anisotropic one must cover 2 pi of phi_i (pbrt-v4 refuses symmetry-reduced files too).
// Angles map to the unit square as theta2u(t) = sqrt(2 t / pi), phi2u(p) = p / (2 pi) + 1/2.
#pragma once

#include <string>
#include <vector>

#include "base/piecewise_linear_2d.h"
#include "materials/bxdfs/tensor_file.h"

namespace kiln {

struct MeasuredBxDFData {
    std::vector<float> wavelengths;
    PiecewiseLinear2D ndf, sigma;  // values
    PiecewiseLinear2D vndf;        // distribution, parameters (phi_i, theta_i)
    PiecewiseLinear2D luminance;   // distribution, parameters (phi_i, theta_i)
    PiecewiseLinear2D spectra;     // values, parameters (phi_i, theta_i, wavelength)
    bool isotropic = true;
    int azimuths = 1;  // the number of phi_i values
    std::string description;

    // The tables of the file; throws TensorFileError saying which field is missing or wrong
    // (shape, dtype, values not finite, negative densities, parameters not increasing).
    static MeasuredBxDFData FromTensor(const TensorFile& file);
    size_t BytesUsed() const;
};

}  // namespace kiln
