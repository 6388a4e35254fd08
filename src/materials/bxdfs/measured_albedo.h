// Directional albedo of a measured BRDF (measured_bxdf.h) for Kirchhoff emission tables
// (thermal/measured_emissivity.h): A(wo, lambda_k) = integral f cos dwi at each of the file's
// wavelengths lambda_k, integrated over the square of half vectors u_wm (dwi = 4 (wo . wm)
// 2 pi^2 u_x sin theta_m du_wm) by a 4 x 4-point Gauss-Legendre rule on every cell of the
// vndf's grid, where the tables are smooth but for the kinks of the spectral table's cells.
// This is the mean of the BxDF's sampling weights f cos / pdf, since its pdf is the density
// of its sampling. Between the file's wavelengths the BxDF interpolates its values linearly,
// so its albedo there is the linear interpolation of these.
#pragma once

#include <vector>

#include "materials/bxdfs/measured_bxdf_data.h"

namespace kiln {

// wo in the local frame (mirrored through the surface when wo.z < 0, as the BxDF does);
// `order` points per cell and axis
std::vector<double> MeasuredAlbedo(const MeasuredBxDFData& data, Vector3f wo, int order = 4);

}  // namespace kiln
