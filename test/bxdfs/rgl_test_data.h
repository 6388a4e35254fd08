// Writes RGL measured-BRDF tensor files (materials/bxdfs/measured_bxdf_data.h) tabulated from an
// analytic model, kiln's rough conductor (Trowbridge-Reitz microfacets with complex Fresnel), so
// that the measured BxDF can be tested against the model it was made from. The tables follow
// the RGL parameterisation (Dupuy and Jakob 2018) as pbrt-v4 reads it:
//   ndf(u)   = D(wm),  sigma(u) = integral D(wm) max(0, wo . wm) dwm = (cos + sqrt(cos^2 +
//              alpha^2 sin^2)) / 2 for wo at u,
//   vndf     = the visible-normal density D_wo(wm) times the Jacobian 2 pi^2 u_x sin theta_m of
//              the square of normals,
//   spectra  = f 4 sigma cos_i / D = F(wo . wm) G(wo, wi) / G1(wo) at the normal the vndf warp
//              (built here from the vndf table, as the renderer builds it) maps each node of
//              the sample square to, and luminance = their mean over the wavelengths.
// test/regression/pbrt_features/measured-ggx.bsdf and measured-aniso.bsdf are
// KilnTestConductor() and KilnTestAnisotropic() written by `KILN_WRITE_MEASURED_FILES=dir
// kiln_bxdfs_tests --gtest_filter=MeasuredFile.*`.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "base/piecewise_linear_2d.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/microfacet.h"
#include "materials/bxdfs/tensor_file.h"

namespace kiln::test {

struct RGLConductor {
    Float alphaX = 0.35f, alphaY = 0.35f;
    std::vector<float> wavelengths{400, 500, 600, 700};  // nm
    std::vector<float> eta{1.18f, 1.13f, 0.25f, 0.21f};  // copper-like, per wavelength
    std::vector<float> k{2.21f, 2.56f, 3.42f, 4.20f};
    int nTheta = 8;    // theta_i nodes over [0, 85] degrees
    int nPhi = 1;      // phi_i nodes over [-pi, pi]; 1: isotropic
    int nNormal = 16;  // ndf, sigma and vndf resolution (per side)
    int nSample = 16;  // spectra and luminance resolution (per side)
};

// The committed test files' models: measured-ggx.bsdf, isotropic, alpha 0.35, and
// measured-aniso.bsdf, alpha 0.15 along x and 0.45 along y, coarse (5 azimuths, 4 elevations,
// 3 wavelengths, 12 x 12 and 8 x 8 tables) to stay small.
inline RGLConductor KilnTestConductor() { return RGLConductor{}; }
inline RGLConductor KilnTestAnisotropic() {
    RGLConductor m;
    m.alphaX = 0.15f, m.alphaY = 0.45f;
    m.wavelengths = {400, 550, 700};
    m.eta = {1.4f, 0.45f, 0.15f};  // gold-like
    m.k = {1.9f, 2.4f, 4.0f};
    m.nTheta = 4, m.nPhi = 5, m.nNormal = 12, m.nSample = 8;
    return m;
}

inline std::vector<float> RGLThetaNodes(const RGLConductor& m) {
    std::vector<float> t(m.nTheta);
    for (int i = 0; i < m.nTheta; ++i) t[i] = Radians(85.f) * i / (m.nTheta - 1);
    return t;
}
inline std::vector<float> RGLPhiNodes(const RGLConductor& m) {
    if (m.nPhi == 1) return {0.f};
    std::vector<float> p(m.nPhi);
    for (int i = 0; i < m.nPhi; ++i) p[i] = -Pi + 2 * Pi * i / (m.nPhi - 1);
    return p;
}

inline std::string WriteRGLConductor(const RGLConductor& m) {
    using Field = TensorFile::NamedField;
    const TrowbridgeReitzDistribution distrib(m.alphaX, m.alphaY);
    const bool isotropic = m.nPhi <= 2;  // as pbrt-v4 decides
    const std::vector<float> thetas = RGLThetaNodes(m), phis = RGLPhiNodes(m);
    auto uToTheta = [](double u) { return u * u * Pi / 2; };
    auto uToPhi = [](double u) { return (2 * u - 1) * Pi; };
    auto direction = [](double theta, double phi) {
        return Vector3f(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                        std::cos(theta));
    };
    const int n = m.nNormal, s = m.nSample, nl = int(m.wavelengths.size());

    std::vector<float> ndf(n * n), sigma(n * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double theta = uToTheta(double(x) / (n - 1)), phi = uToPhi(double(y) / (n - 1));
            ndf[y * n + x] = distrib.D(direction(theta, phi));
            const double a2 = Sqr(std::cos(phi) * m.alphaX) + Sqr(std::sin(phi) * m.alphaY);
            const double c = std::cos(theta), s2 = Sqr(std::sin(theta));
            sigma[y * n + x] = float((c + std::sqrt(c * c + a2 * s2)) / 2);
        }

    std::vector<float> vndf;
    for (float phi_o : phis)
        for (float theta_o : thetas) {
            const Vector3f wo = direction(theta_o, phi_o);
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const double u = double(x) / (n - 1), theta = uToTheta(u);
                    const double phi = uToPhi(double(y) / (n - 1)) + (isotropic ? phi_o : 0);
                    const Vector3f wm = direction(theta, phi);
                    const double jacobian = 2 * Sqr(Pi) * u * std::sin(theta);
                    vndf.push_back(Dot(wo, wm) > 0 ? float(distrib.D(wo, wm) * jacobian) : 0.f);
                }
        }
    const PiecewiseLinear2D warp(vndf, n, n, {phis, thetas}, PiecewiseLinear2D::Kind::Distribution);

    std::vector<float> spectra, luminance;
    for (float phi_o : phis)
        for (float theta_o : thetas) {
            const Vector3f wo = direction(theta_o, phi_o);
            std::vector<float> values(size_t(nl) * s * s, 0.f);
            for (int y = 0; y < s; ++y)
                for (int x = 0; x < s; ++x) {
                    const Point2f p = warp.Draw(Point2f(Float(x) / (s - 1), Float(y) / (s - 1)),
                                                std::array<Float, 2>{phi_o, theta_o})
                                          .p;
                    const double phi = uToPhi(p.y) + (isotropic ? phi_o : 0);
                    const Vector3f wm = direction(uToTheta(p.x), phi);
                    const Vector3f wi = Reflect(wo, wm);
                    if (wi.z <= 0 || Dot(wo, wm) <= 0) continue;
                    const Float g = distrib.G(wo, wi) / distrib.G1(wo);
                    for (int l = 0; l < nl; ++l)
                        values[(size_t(l) * s + y) * s + x] =
                            FrComplex(Dot(wo, wm), std::complex<Float>(m.eta[l], m.k[l])) * g;
                }
            spectra.insert(spectra.end(), values.begin(), values.end());
            for (int i = 0; i < s * s; ++i) {
                float sum = 0;
                for (int l = 0; l < nl; ++l) sum += values[size_t(l) * s * s + i];
                luminance.push_back(sum / nl);
            }
        }

    const std::string description = "kiln test data: Trowbridge-Reitz conductor, alpha " +
                                    std::to_string(m.alphaX) + " x " + std::to_string(m.alphaY) +
                                    ", tabulated by test/bxdfs/rgl_test_data.h";
    const uint64_t np = phis.size(), nt = thetas.size();
    std::vector<Field> fields{
        {"description", TensorFile::DType::UInt8, {description.size()}, description},
        {"jacobian", TensorFile::DType::UInt8, {1}, std::string(1, '\1')},
        TensorFile::FloatField("theta_i", {nt}, thetas),
        TensorFile::FloatField("phi_i", {np}, phis),
        TensorFile::FloatField("wavelengths", {uint64_t(nl)}, m.wavelengths),
        TensorFile::FloatField("ndf", {uint64_t(n), uint64_t(n)}, ndf),
        TensorFile::FloatField("sigma", {uint64_t(n), uint64_t(n)}, sigma),
        TensorFile::FloatField("vndf", {np, nt, uint64_t(n), uint64_t(n)}, vndf),
        TensorFile::FloatField("luminance", {np, nt, uint64_t(s), uint64_t(s)}, luminance),
        TensorFile::FloatField("spectra", {np, nt, uint64_t(nl), uint64_t(s), uint64_t(s)},
                               spectra)};
    return TensorFile::Encode(fields);
}

}  // namespace kiln::test
