#include "materials/bxdfs/measured_albedo.h"

#include <array>
#include <cmath>

#include "base/quadrature.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/measured_bxdf.h"

namespace kiln {

std::vector<double> MeasuredAlbedo(const MeasuredBxDFData& data, Vector3f wo, int order) {
    const size_t nl = data.wavelengths.size();
    std::vector<double> albedo(nl, 0.0);
    if (wo.z < 0) wo = -wo;
    const double phi_o = std::atan2(wo.y, wo.x);
    const QuadratureRule ux = CompositeGaussLegendre(data.vndf.NX() - 1, order);
    const QuadratureRule uy = CompositeGaussLegendre(data.vndf.NY() - 1, order);
    for (size_t j = 0; j < uy.x.size(); ++j)
        for (size_t i = 0; i < ux.x.size(); ++i) {
            // The half vector at (u_x, u_y) of the square (azimuth relative to wo's when
            // isotropic) and the direction it reflects wo to
            const double theta_m = ux.x[i] * ux.x[i] * Pi / 2;
            const double phi_m = (2 * uy.x[j] - 1) * Pi + (data.isotropic ? phi_o : 0);
            const double sinTheta_m = std::sin(theta_m);
            const Vector3f wm(sinTheta_m * std::cos(phi_m), sinTheta_m * std::sin(phi_m),
                              std::cos(theta_m));
            const Vector3f wi = Reflect(wo, wm);
            const Float woDotWm = Dot(wo, wm);
            if (wi.z <= 0 || woDotWm <= 0) continue;
            std::optional<MeasuredBxDF::Draw> d = MeasuredBxDF::EvaluateGeometry(data, wo, wi);
            if (!d) continue;
            const double dwi = 4 * double(woDotWm) * 2 * Pi * Pi * ux.x[i] * sinTheta_m;
            const double weight = ux.weight[i] * uy.weight[j] * d->scale * wi.z * dwi;
            for (size_t k = 0; k < nl; ++k)
                albedo[k] += weight * std::max<Float>(
                                          0, data.spectra.Evaluate(
                                                 d->p, std::array<Float, 3>{d->phi_o, d->theta_o,
                                                                            data.wavelengths[k]}));
        }
    return albedo;
}

}  // namespace kiln
