// Stokes vectors and Mueller matrices: Malus's law, frame rotations, retarders.
#include "spectral/polarization.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace kiln;

namespace {

Stokes Light(Float s0, Float s1, Float s2, Float s3) {
    return Stokes(SampledSpectrum(s0), SampledSpectrum(s1), SampledSpectrum(s2),
                  SampledSpectrum(s3));
}

void ExpectStokes(const Stokes& s, Float s0, Float s1, Float s2, Float s3, Float tol = 1e-5f) {
    for (int i = 0; i < NSpectrumSamples; ++i) {
        EXPECT_NEAR(s[0][i], s0, tol);
        EXPECT_NEAR(s[1][i], s1, tol);
        EXPECT_NEAR(s[2][i], s2, tol);
        EXPECT_NEAR(s[3][i], s3, tol);
    }
}

}  // namespace

TEST(Polarization, MalusLaw) {
    // Unpolarised light through two linear polarisers at angles a and b: I/2 cos^2(a - b)
    Stokes unpolarized(SampledSpectrum(2.f));
    for (Float a : {0.f, 20.f, 45.f, 90.f, 133.f})
        for (Float b = 0; b <= 180; b += 15) {
            Stokes out = LinearPolarizer(Radians(b)) * (LinearPolarizer(Radians(a)) * unpolarized);
            Float expected = 1 * Sqr(std::cos(Radians(a - b)));
            EXPECT_NEAR(out[0][0], expected, 1e-5f) << a << " " << b;
            // What leaves is fully polarised along b
            if (expected > 1e-3f) {
                EXPECT_NEAR(DegreeOfPolarization(out)[0], 1, 1e-4f);
                Float angle = AngleOfLinearPolarization(out)[0];
                EXPECT_NEAR(std::cos(2 * angle), std::cos(2 * Radians(b)), 1e-4f);
            }
        }
}

TEST(Polarization, PolarizerIsIdempotentAndHalvesUnpolarisedLight) {
    for (Float t : {0.f, 0.3f, 1.1f, 2.f}) {
        MuellerMatrix P = LinearPolarizer(t), PP = P * P;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(PP(r, c)[0], P(r, c)[0], 1e-6f);
        EXPECT_NEAR((P * Stokes(SampledSpectrum(1.f)))[0][0], 0.5f, 1e-6f);
    }
}

TEST(Polarization, BasisRotation) {
    Vector3f d(0, 0, 1), x(1, 0, 0), y(0, 1, 0), diag = Normalize(Vector3f(1, 1, 0));
    // Light polarised along x
    Stokes s = Light(1, 1, 0, 0);
    ExpectStokes(RotateStokesBasis(s, d, x, y), 1, -1, 0, 0);
    // x is 45 degrees clockwise of the diagonal (seen against the direction of travel)
    ExpectStokes(RotateStokesBasis(s, d, x, diag), 1, 0, -1, 0);
    EXPECT_NEAR(StokesBasisAngle(d, x, diag), Pi / 4, 1e-6f);
    EXPECT_NEAR(StokesBasisAngle(-d, x, diag), -Pi / 4, 1e-6f);
    // A turn of pi changes nothing; rotations compose
    ExpectStokes(RotateStokesBasis(Light(1, 0.3f, -0.4f, 0.5f), d, x, -x), 1, 0.3f, -0.4f, 0.5f);
    MuellerMatrix R = RotatorMatrix(0.4f) * RotatorMatrix(0.7f), R2 = RotatorMatrix(1.1f);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(R(r, c)[0], R2(r, c)[0], 1e-6f);
    // Re-expressing a matrix in other frames and back gives it again
    MuellerMatrix M = LinearRetarder(0.3f, 1.f) * LinearPolarizer(0.2f);
    Vector3f d2 = Normalize(Vector3f(1, 2, 3)), a2 = StokesBasis(d2);
    Vector3f b2 = Normalize(Cross(d2, Vector3f(0, 0, 1)));
    MuellerMatrix back =
        RotateMuellerBasis(RotateMuellerBasis(M, d, x, diag, d2, a2, b2), d, diag, x, d2, b2, a2);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(back(r, c)[0], M(r, c)[0], 1e-5f);
}

TEST(Polarization, StokesBasisIsPerpendicular) {
    for (Vector3f d : {Vector3f(0, 0, 1), Vector3f(0, 0, -1), Normalize(Vector3f(1, -2, 0.5f)),
                       Normalize(Vector3f(-1e-4f, 0, -1))}) {
        Vector3f x = StokesBasis(d);
        EXPECT_NEAR(Dot(x, d), 0, 1e-6f);
        EXPECT_NEAR(Length(x), 1, 1e-6f);
    }
}

TEST(Polarization, Retarders) {
    // A quarter-wave plate at 45 degrees turns light polarised along x circular
    Stokes c = LinearRetarder(Radians(45), Pi / 2) * Light(1, 1, 0, 0);
    EXPECT_NEAR(std::abs(c[3][0]), 1, 1e-5f);
    EXPECT_NEAR(DegreeOfLinearPolarization(c)[0], 0, 1e-5f);
    // A half-wave plate at 22.5 degrees turns it to 45 degrees
    ExpectStokes(LinearRetarder(Radians(22.5f), Pi) * Light(1, 1, 0, 0), 1, 0, 1, 0);
    // Two quarter-wave plates are a half-wave plate
    MuellerMatrix Q = LinearRetarder(0.3f, Pi / 2), H = LinearRetarder(0.3f, Pi), QQ = Q * Q;
    for (int r = 0; r < 4; ++r)
        for (int col = 0; col < 4; ++col) EXPECT_NEAR(QQ(r, col)[0], H(r, col)[0], 1e-5f);
    // Retarders keep the degree of polarisation
    Stokes s = LinearRetarder(1.f, 0.7f) * Light(1, 0.6f, 0.0f, 0.8f);
    EXPECT_NEAR(DegreeOfPolarization(s)[0], 1, 1e-5f);
}

TEST(Polarization, DepolarizerIgnoresPolarisation) {
    MuellerMatrix D = MuellerMatrix::Depolarizer(SampledSpectrum(0.4f));
    ExpectStokes(D * Light(1, 0.6f, 0.8f, 0), 0.4f, 0, 0, 0);
    EXPECT_NEAR(DegreeOfPolarization(Stokes(SampledSpectrum(3.f)))[0], 0, 0);
}
