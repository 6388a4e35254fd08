// The thermal module's host interface (surface_emission.h, volume_emission.h) used as a host
// renderer would: with reflectances of its own that know nothing of kiln's materials. Checks
// each emission model against its closed form, Kirchhoff's law per polarisation state for a
// smooth metal (emission + reflection of unpolarised blackbody light is unpolarised B), the
// exitance against numerical integration, and medium emission per model.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "base/rng.h"
#include "spectral/planck.h"
#include "thermal/surface_emission.h"
#include "thermal/volume_emission.h"

namespace kiln {
namespace {

// A host's Lambertian surface of reflectance R: A(wo) = R, unpolarised reflection.
struct LambertianReflectance {
    Float R;
    SampledSpectrum DirectionalAlbedo(Vector3f, const SampledWavelengths&) const {
        return SampledSpectrum(R);
    }
    ReflectedPolarization LinearPolarization(Vector3f) const { return {}; }
};

// A host's smooth conductor with complex index eta + i k: A(wo) = (Rs + Rp) / 2 and the
// reflection's polarisation (Rs - Rp) / 2 about the plane of the normal and wo.
struct SmoothMetalReflectance {
    std::complex<double> n;
    void Fresnel(double cosTheta, double* Rs, double* Rp) const {
        double sin2 = 1 - cosTheta * cosTheta;
        std::complex<double> cosT = std::sqrt(1.0 - sin2 / (n * n));
        std::complex<double> rs = (cosTheta - n * cosT) / (cosTheta + n * cosT);
        std::complex<double> rp = (n * cosTheta - cosT) / (n * cosTheta + cosT);
        *Rs = std::norm(rs);
        *Rp = std::norm(rp);
    }
    SampledSpectrum DirectionalAlbedo(Vector3f wo, const SampledWavelengths&) const {
        double Rs, Rp;
        Fresnel(std::abs(wo.z), &Rs, &Rp);
        return SampledSpectrum(Float((Rs + Rp) / 2));
    }
    ReflectedPolarization LinearPolarization(Vector3f wo) const {
        double Rs, Rp;
        Fresnel(std::abs(wo.z), &Rs, &Rp);
        return {SampledSpectrum(Float((Rs - Rp) / 2)), SampledSpectrum(0.f)};
    }
};

static_assert(SurfaceReflectance<LambertianReflectance>);
static_assert(SurfaceReflectance<SmoothMetalReflectance>);

SampledWavelengths Visible() { return SampledWavelengths::SampleVisible(0.37f); }

TEST(ThermalHostInterface, ModelsEmitTheirClosedForms) {
    SampledWavelengths lambda = Visible();
    SampledSpectrum B = planck_radiance(lambda, 1500);
    LambertianReflectance r{0.3f};
    Frame frame = Frame::FromZ(Normalize(Vector3f(0.2f, -0.1f, 1)));
    Vector3f w = Normalize(Vector3f(0.4f, 0.3f, 0.8f));
    SampledSpectrum kirchhoff =
        SurfaceEmission<SampledSpectrum>(EmissionModel::Kirchhoff, B, r, frame, w, lambda);
    SampledSpectrum additive =
        SurfaceEmission<SampledSpectrum>(EmissionModel::Additive, B, r, frame, w, lambda);
    SampledSpectrum diffuse =
        SurfaceEmission<SampledSpectrum>(EmissionModel::Diffuse, B, r, frame, w, lambda);
    SampledSpectrum none =
        SurfaceEmission<SampledSpectrum>(EmissionModel::None, B, r, frame, w, lambda);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        EXPECT_FLOAT_EQ(kirchhoff[i], 0.7f * B[i]);
        EXPECT_FLOAT_EQ(additive[i], B[i]);
        EXPECT_FLOAT_EQ(diffuse[i], B[i]);
        EXPECT_EQ(none[i], 0);
    }
    // Unpolarised reflectance: unpolarised emission of the same intensity
    Stokes S = SurfaceEmission<Stokes>(EmissionModel::Kirchhoff, B, r, frame, w, lambda);
    for (int i = 0; i < NSpectrumSamples; ++i) {
        EXPECT_FLOAT_EQ(S[0][i], kirchhoff[i]);
        EXPECT_EQ(S[1][i], 0);
        EXPECT_EQ(S[2][i], 0);
    }
}

// Kirchhoff per polarisation state: under unpolarised illumination B a smooth metal reflects
// B (A, a1, 0, 0) about the plane of incidence; what it emits added to that must be exactly
// unpolarised B, at every angle. The emission's angle of polarisation lies in the plane of the
// normal and w (90 degrees from the reflection's).
TEST(ThermalHostInterface, SmoothMetalEmissionCompletesUnpolarisedEquilibrium) {
    SampledWavelengths lambda = Visible();
    SampledSpectrum B = planck_radiance(lambda, 1200);
    SmoothMetalReflectance gold{{0.27, 2.95}};  // gold near 600 nm
    RNG rng(7);
    for (int k = 0; k < 200; ++k) {
        Frame frame = Frame::FromZ(
            Normalize(Vector3f(rng.UniformFloat() - 0.5f, rng.UniformFloat() - 0.5f, 1)));
        Float cosTheta = 0.02f + 0.98f * rng.UniformFloat(), phi = 2 * Pi * rng.UniformFloat();
        Float sinTheta = std::sqrt(1 - cosTheta * cosTheta);
        Vector3f wLocal(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
        Vector3f w = frame.FromLocal(wLocal);
        Stokes E = SurfaceEmission<Stokes>(EmissionModel::Kirchhoff, B, gold, frame, w, lambda);
        // The reflection, B (A, a1, 0, 0) about the plane axis, in w's implicit frame
        ReflectedPolarization a = gold.LinearPolarization(wLocal);
        SampledSpectrum A = gold.DirectionalAlbedo(wLocal, lambda);
        Vector3f axis = frame.FromLocal(PlaneAxis(Vector3f(0, 0, 1), wLocal));
        Stokes R =
            RotateStokesBasis(Stokes(B * A, B * a.s1, B * a.s2, {}), w, axis, StokesBasis(w));
        for (int i = 0; i < NSpectrumSamples; ++i) {
            EXPECT_NEAR(E[0][i] + R[0][i], B[i], 1e-5f * B[i]);
            EXPECT_NEAR(E[1][i] + R[1][i], 0, 1e-5f * B[i]);
            EXPECT_NEAR(E[2][i] + R[2][i], 0, 1e-5f * B[i]);
            EXPECT_EQ(E[3][i], 0);
        }
        // The emission is polarised in the plane of the normal and w: about the s axis
        // (perpendicular to that plane) its S1 = -B (Rs - Rp) / 2 < 0, as Rs > Rp away from
        // normal incidence
        Stokes Es = RotateStokesBasis(E, w, StokesBasis(w), axis);
        if (cosTheta < 0.9f) {
            EXPECT_LT(Es[1][0], 0);
        }
    }
}

// BandExitance: 2 pi integral over 360-830 nm of B (1 - hemispherical albedo), against a
// fine midpoint rule of the same integral (exact for a grey surface, at any temperature).
TEST(ThermalHostInterface, BandExitanceIntegratesTheEmission) {
    LambertianReflectance r{0.25f};
    for (Float T : {500.f, 800.f, 1500.f, 3000.f, 20000.f}) {
        double sum = 0;
        constexpr int n = 4700;
        for (int i = 0; i < n; ++i)
            sum += planck_radiance(360 + (i + 0.5) * 470.0 / n, T) * 470.0 / n;
        double expected = 2 * Pi * 0.75 * sum;
        Float M = BandExitance(EmissionModel::Kirchhoff, T, 1, r);
        EXPECT_NEAR(M, expected, 1e-5 * expected) << T;
        EXPECT_FLOAT_EQ(BandExitance(EmissionModel::Additive, T, 1, r), M / 0.75f);
        EXPECT_EQ(BandExitance(EmissionModel::None, T, 1, r), 0);
    }
    EXPECT_EQ(BandExitance(EmissionModel::Kirchhoff, 0, 1, r), 0);
    EXPECT_EQ(BandExitance(EmissionModel::Kirchhoff, std::nanf(""), 1, r), 0);
}

TEST(ThermalHostInterface, VolumeEmissionPerModel) {
    SampledWavelengths lambda = Visible();
    SampledSpectrum B = planck_radiance(lambda, 1400);
    SampledSpectrum n(1.5f);
    auto emit = [&](EmissionModel model, Float T, SampledSpectrum* sa, SampledSpectrum* ss,
                    const SampledSpectrum* eta) {
        return VolumeEmission(model, T, eta, *sa, *ss, lambda);
    };
    SampledSpectrum sa(0.4f), ss(0.6f);
    SampledSpectrum e = emit(EmissionModel::Kirchhoff, 1400, &sa, &ss, &n);
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_FLOAT_EQ(e[i], 0.4f * 2.25f * B[i]);
    e = emit(EmissionModel::Additive, 1400, &sa, &ss, nullptr);
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_FLOAT_EQ(e[i], 1.0f * B[i]);
    EXPECT_FLOAT_EQ(sa[0], 0.4f);
    EXPECT_FLOAT_EQ(ss[0], 0.6f);
    // Diffuse: a blackbody medium, scattering turned into absorption
    e = emit(EmissionModel::Diffuse, 1400, &sa, &ss, nullptr);
    for (int i = 0; i < NSpectrumSamples; ++i) EXPECT_FLOAT_EQ(e[i], 1.0f * B[i]);
    EXPECT_FLOAT_EQ(sa[0], 1.0f);
    EXPECT_EQ(ss[0], 0);
    SampledSpectrum sa2(0.4f), ss2(0.6f);
    EXPECT_FALSE(emit(EmissionModel::None, 1400, &sa2, &ss2, nullptr));
    EXPECT_FALSE(emit(EmissionModel::Kirchhoff, 0, &sa2, &ss2, nullptr));
    EXPECT_FALSE(emit(EmissionModel::Kirchhoff, -5, &sa2, &ss2, nullptr));
    EXPECT_FALSE(emit(EmissionModel::Kirchhoff, std::nanf(""), &sa2, &ss2, nullptr));
}

}  // namespace
}  // namespace kiln
