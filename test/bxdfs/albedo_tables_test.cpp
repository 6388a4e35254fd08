// The deterministic albedo computations behind Kirchhoff emissivity (emissivity = 1 - albedo)
// against the BxDFs themselves: each value must equal the mean of f cos / pdf over Sample_f
// (what the integrator scatters with) within the Monte Carlo standard error plus a stated
// accuracy (conductors 5e-5, layered 2e-4).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "base/quadrature.h"
#include "base/rng.h"
#include "base/statistics.h"
#include "materials/bxdfs/bxdf.h"
#include "materials/bxdfs/conductor_albedo.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/layered_albedo.h"
#include "materials/bxdfs/microfacet_quadrature.h"

using namespace kiln;

namespace {

// Mean and standard error of the scattering weight f |cos| / pdf of Sample_f from wo.
RunningStats SampledAlbedo(const BxDF& bxdf, double cosTheta, int n, uint64_t seed) {
    Vector3f wo(Float(std::sqrt(1 - cosTheta * cosTheta)), 0, Float(cosTheta));
    RunningStats s;
    RNG rng(seed);
    for (int i = 0; i < n; ++i) {
        Float uc = rng.UniformFloat();
        Point2f u(rng.UniformFloat(), rng.UniformFloat());
        std::optional<BSDFSample> bs = bxdf.Sample_f(wo, uc, u);
        s.Add(bs && bs->pdf > 0 ? double(bs->f[0]) * AbsCosTheta(bs->wi) / bs->pdf : 0.0);
    }
    return s;
}

double Fresnel(double mu, double eta, double k) {
    return FrComplex(Float(mu), std::complex<Float>(Float(eta), Float(k)));
}

}  // namespace

TEST(AlbedoTables, GaussLegendreIsExactForPolynomials) {
    for (int n : {5, 8, 13}) {
        QuadratureRule r = GaussLegendre(n, -1, 2);
        for (int degree = 0; degree < 2 * n; ++degree) {
            double sum = 0;
            for (size_t i = 0; i < r.x.size(); ++i) sum += r.weight[i] * std::pow(r.x[i], degree);
            double exact = (std::pow(2.0, degree + 1) - std::pow(-1.0, degree + 1)) / (degree + 1);
            EXPECT_NEAR(sum, exact, 1e-12 * std::max(1.0, std::abs(exact)))
                << n << " points, degree " << degree;
        }
    }
}

TEST(AlbedoTables, VisibleNormalsIntegrateToOne) {
    for (double alpha : {0.002, 0.05, 0.4, 1.0, 2.0})
        for (double mu : {1.0, 0.7, 0.2, 0.02}) {
            double sum = 0;
            for (const NormalQuadraturePoint& q :
                 VisibleNormalQuadrature(alpha, mu, NormalRegion::Visible()))
                sum += q.weight;
            EXPECT_NEAR(sum, 1, 2e-5) << alpha << " " << mu;
        }
}

TEST(AlbedoTables, RoughConductorAlbedoMatchesSampling) {
    struct Metal {
        double eta, k;
    } metals[] = {{0.27, 2.8}, {0.05, 3.5}, {2.5, 3.3}, {1.0, 0.3}, {1.0, 1e5}};
    uint64_t seed = 1;
    for (double alpha : {0.002, 0.03, 0.3, 1.0})
        for (double mu : {1.0, 0.6, 0.2, 0.03}) {
            ConductorAlbedoMoments::Weights w = ConductorAlbedoMoments::Compute(alpha, mu);
            for (Metal m : metals) {
                double A = ConductorAlbedoMoments::Apply(
                    w, [&](double c) { return Fresnel(c, m.eta, m.k); });
                TrowbridgeReitzDistribution distrib{Float(alpha), Float(alpha)};
                BxDF bxdf = ConductorBxDF(distrib, SampledSpectrum(Float(m.eta)),
                                          SampledSpectrum(Float(m.k)));
                RunningStats s = SampledAlbedo(bxdf, mu, 200000, seed++);
                EXPECT_NEAR(A, s.Mean(), 4 * s.StandardError() + 5e-5)
                    << "alpha " << alpha << " mu " << mu << " eta " << m.eta << " k " << m.k;
            }
        }
}

TEST(AlbedoTables, CoatedDiffuseAlbedoMatchesSampling) {
    std::vector<double> mus = {1.0, 0.5, 0.1};
    uint64_t seed = 100;
    for (double alpha : {0.0, 0.08, 0.5})
        for (double thickness : {0.01, 0.4})
            for (int maxDepth : {3, 10}) {
                CoatParameters coat{1.5, alpha, thickness, maxDepth};
                std::vector<std::vector<double>> poly = CoatedDiffuseAlbedoPolynomials(coat, mus);
                for (double r : {0.0, 0.5, 0.95}) {
                    BxDF bxdf = CoatedDiffuseBxDF(
                        DielectricBxDF(1.5f,
                                       TrowbridgeReitzDistribution(Float(alpha), Float(alpha))),
                        DiffuseBxDF(SampledSpectrum(Float(r))), Float(thickness),
                        SampledSpectrum(0.f), 0, maxDepth, 1);
                    for (size_t o = 0; o < mus.size(); ++o) {
                        double A = 0, rk = 1;
                        for (double c : poly[o]) A += c * rk, rk *= r;
                        RunningStats s = SampledAlbedo(bxdf, mus[o], 100000, seed++);
                        EXPECT_NEAR(A, s.Mean(), 4 * s.StandardError() + 2e-4)
                            << "alpha " << alpha << " thickness " << thickness << " maxdepth "
                            << maxDepth << " r " << r << " mu " << mus[o];
                    }
                }
            }
}

TEST(AlbedoTables, CoatedConductorAlbedoMatchesSampling) {
    std::vector<double> mus = {1.0, 0.5, 0.1};
    const double eta = 0.2 / 1.5, k = 3.0 / 1.5;  // relative to the coat
    uint64_t seed = 1000;
    for (double alpha : {0.0, 0.3})
        for (double baseAlpha : {0.0, 0.05, 0.4}) {
            CoatParameters coat{1.5, alpha, 0.01, 10};
            std::vector<std::vector<double>> A = CoatedConductorAlbedo(
                coat, baseAlpha, {[&](double mu) { return Fresnel(mu, eta, k); }}, mus);
            BxDF bxdf = CoatedConductorBxDF(
                DielectricBxDF(1.5f, TrowbridgeReitzDistribution(Float(alpha), Float(alpha))),
                ConductorBxDF(TrowbridgeReitzDistribution(Float(baseAlpha), Float(baseAlpha)),
                              SampledSpectrum(Float(eta)), SampledSpectrum(Float(k))),
                0.01f, SampledSpectrum(0.f), 0, 10, 1);
            for (size_t o = 0; o < mus.size(); ++o) {
                RunningStats s = SampledAlbedo(bxdf, mus[o], 200000, seed++);
                EXPECT_NEAR(A[0][o], s.Mean(), 4 * s.StandardError() + 2e-4)
                    << "alpha " << alpha << " base alpha " << baseAlpha << " mu " << mus[o];
            }
        }
}

TEST(AlbedoTables, AnisotropicQuadratureAgreesWithIsotropicAtEqualRoughness) {
    for (double alpha : {0.01, 0.1, 0.5, 1.0})
        for (double mu : {1.0, 0.6, 0.2, 0.03})
            for (double phi : {0.0, 0.9}) {
                double s = std::sqrt(1 - mu * mu);
                double wo[3] = {s * std::cos(phi), s * std::sin(phi), mu};
                auto gold = [](double c) { return Fresnel(c, 0.27, 2.8); };
                double iso =
                    ConductorAlbedoMoments::Apply(ConductorAlbedoMoments::Compute(alpha, mu), gold);
                double aniso = ConductorAlbedoMoments::Apply(
                    ConductorAlbedoMoments::Compute(alpha, alpha, wo), gold);
                EXPECT_NEAR(iso, aniso, 5e-5) << "alpha " << alpha << " mu " << mu;
            }
}

TEST(AlbedoTables, AnisotropicConductorAlbedoMatchesSampling) {
    struct Metal {
        double eta, k;
    } metals[] = {{0.27, 2.8}, {1.0, 0.3}};
    uint64_t seed = 100;
    double pairs[][2] = {{0.05, 0.3}, {0.3, 1.0}, {0.002, 1.0}, {1.0, 0.01}};
    for (auto [ax, ay] : pairs)
        for (double mu : {1.0, 0.5, 0.1})
            for (double phi : {0.3, 1.2}) {
                double s = std::sqrt(1 - mu * mu);
                double wo[3] = {s * std::cos(phi), s * std::sin(phi), mu};
                ConductorAlbedoMoments::Weights w = ConductorAlbedoMoments::Compute(ax, ay, wo);
                for (Metal m : metals) {
                    double A = ConductorAlbedoMoments::Apply(
                        w, [&](double c) { return Fresnel(c, m.eta, m.k); });
                    TrowbridgeReitzDistribution distrib{Float(ax), Float(ay)};
                    BxDF bxdf = ConductorBxDF(distrib, SampledSpectrum(Float(m.eta)),
                                              SampledSpectrum(Float(m.k)));
                    Vector3f v{Float(wo[0]), Float(wo[1]), Float(wo[2])};
                    RunningStats st;
                    RNG rng(seed++);
                    for (int i = 0; i < 200000; ++i) {
                        Float uc = rng.UniformFloat();
                        Point2f u(rng.UniformFloat(), rng.UniformFloat());
                        std::optional<BSDFSample> bs = bxdf.Sample_f(v, uc, u);
                        st.Add(bs && bs->pdf > 0 ? double(bs->f[0]) * AbsCosTheta(bs->wi) / bs->pdf
                                                 : 0.0);
                    }
                    EXPECT_NEAR(A, st.Mean(), 4 * st.StandardError() + 5e-5)
                        << "alpha " << ax << " x " << ay << " mu " << mu << " phi " << phi;
                }
            }
}
