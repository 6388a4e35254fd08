// Emissivity of materials (Kirchhoff's law): 1 - directional-hemispherical reflectance.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "materials/bxdfs/bsdf.h"
#include "materials/emissivity.h"
#include "spectral/named_spectra.h"

namespace kiln {
namespace {

// Normal-incidence emissivity of a smooth metal: 1 - |(n - 1 + ik) / (n + 1 + ik)|^2.
TEST(EmissivityTest, NormalIncidenceEmissivityOfEveryNamedMetal) {
    for (const char* metal : {"Ag", "Al", "Au", "Cu", "CuZn", "Pt", "Ni", "Fe", "W", "Cr", "Ti"}) {
        SCOPED_TRACE(metal);
        const Spectrum* eta = GetNamedSpectrum(std::string("metal-") + metal + "-eta");
        const Spectrum* k = GetNamedSpectrum(std::string("metal-") + metal + "-k");
        ASSERT_TRUE(eta && k);
        for (Float l = 380; l <= 780; l += 20) {
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(l);
            ConductorBxDF conductor(TrowbridgeReitzDistribution(0, 0), eta->Sample(lambda),
                                    k->Sample(lambda));
            BSDF bsdf(Normal3f(0, 0, 1), Vector3f(1, 0, 0), BxDF(conductor));
            Float emissivity = 1 - HemisphericalReflectance(bsdf, Vector3f(0, 0, 1))[0];
            std::complex<double> n((*eta)(l), (*k)(l));
            double expected = 1 - std::norm((n - 1.0) / (n + 1.0));
            EXPECT_NEAR(emissivity, expected, 1e-5) << l << " nm";
            EXPECT_GE(emissivity, 0);
            EXPECT_LE(emissivity, 1);
        }
    }
}

// Emissivity stays in [0, 1] for every direction, and a rough conductor's emission plus its
// reflection of a uniform surround never exceeds a blackbody (R <= 1).
TEST(EmissivityTest, EmissivityIsBoundedForAllDirectionsAndRoughnesses) {
    const Spectrum* eta = GetNamedSpectrum("metal-Au-eta");
    const Spectrum* k = GetNamedSpectrum("metal-Au-k");
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
    for (Float alpha : {0.f, 0.05f, 0.3f, 1.f})
        for (Float cosTheta : {1.f, 0.5f, 0.1f, 1e-3f}) {
            ConductorBxDF conductor(TrowbridgeReitzDistribution(alpha, alpha),
                                    eta->Sample(lambda), k->Sample(lambda));
            BSDF bsdf(Normal3f(0, 0, 1), Vector3f(1, 0, 0), BxDF(conductor));
            Vector3f wo(std::sqrt(1 - cosTheta * cosTheta), 0, cosTheta);
            SampledSpectrum R = HemisphericalReflectance(bsdf, wo);
            for (int i = 0; i < NSpectrumSamples; ++i) {
                EXPECT_TRUE(std::isfinite(R[i]));
                EXPECT_GE(R[i], 0);
                EXPECT_LE(R[i], 1);
            }
        }
}

TEST(EmissivityTest, ParsesEmissionModels) {
    EXPECT_EQ(ParseEmissionModel("kirchhoff"), EmissionModel::Kirchhoff);
    EXPECT_EQ(ParseEmissionModel("additive"), EmissionModel::Additive);
    EXPECT_EQ(ParseEmissionModel("diffuse"), EmissionModel::Diffuse);
    EXPECT_EQ(ParseEmissionModel("none"), EmissionModel::None);
    EXPECT_FALSE(ParseEmissionModel("Kirchhoff"));
}

}  // namespace
}  // namespace kiln
