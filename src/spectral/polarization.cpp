#include "spectral/polarization.h"

#include <cmath>

namespace kiln {

// Frames
Float StokesBasisAngle(Vector3f d, Vector3f from, Vector3f to) {
    return std::atan2(Dot(Cross(from, to), d), Dot(from, to));
}

MuellerMatrix RotatorMatrix(Float theta) {
    Float c = std::cos(2 * theta), s = std::sin(2 * theta);
    MuellerMatrix R;
    R(0, 0) = R(3, 3) = SampledSpectrum(1.f);
    R(1, 1) = R(2, 2) = SampledSpectrum(c);
    R(1, 2) = SampledSpectrum(s);
    R(2, 1) = SampledSpectrum(-s);
    return R;
}

Stokes RotateStokesBasis(const Stokes& s, Vector3f d, Vector3f from, Vector3f to) {
    Float theta = StokesBasisAngle(d, from, to);
    Float c = std::cos(2 * theta), sn = std::sin(2 * theta);
    return Stokes(s[0], c * s[1] + sn * s[2], -sn * s[1] + c * s[2], s[3]);
}

MuellerMatrix RotateMuellerBasis(const MuellerMatrix& M, Vector3f dIn, Vector3f inFrom,
                                 Vector3f inTo, Vector3f dOut, Vector3f outFrom, Vector3f outTo) {
    // Input given about inTo: re-express about inFrom, apply M, re-express about outTo
    return RotatorMatrix(StokesBasisAngle(dOut, outFrom, outTo)) * M *
           RotatorMatrix(StokesBasisAngle(dIn, inTo, inFrom));
}

// Optical elements
namespace {

// Element with matrix M0 in the frame whose x axis is the element's axis, seen from the frame
// turned by -theta.
MuellerMatrix Oriented(const MuellerMatrix& M0, Float theta) {
    return RotatorMatrix(-theta) * M0 * RotatorMatrix(theta);
}

}  // namespace

MuellerMatrix LinearPolarizer(Float theta) {
    // Transmission axis along x: passes I(x), blocks I(y) (Collett eq. 5.2-10)
    MuellerMatrix P;
    SampledSpectrum half(0.5f);
    P(0, 0) = P(0, 1) = P(1, 0) = P(1, 1) = half;
    return Oriented(P, theta);
}

MuellerMatrix LinearRetarder(Float theta, Float delta) {
    // Fast axis along x (Collett eq. 5.3-9)
    MuellerMatrix W;
    Float c = std::cos(delta), s = std::sin(delta);
    W(0, 0) = W(1, 1) = SampledSpectrum(1.f);
    W(2, 2) = W(3, 3) = SampledSpectrum(c);
    W(2, 3) = SampledSpectrum(s);
    W(3, 2) = SampledSpectrum(-s);
    return Oriented(W, theta);
}

// Degree and angle of polarisation
SampledSpectrum DegreeOfPolarization(const Stokes& s) {
    SampledSpectrum r;
    for (int i = 0; i < NSpectrumSamples; ++i)
        if (s[0][i] != 0)
            r[i] = std::sqrt(Sqr(s[1][i]) + Sqr(s[2][i]) + Sqr(s[3][i])) / std::abs(s[0][i]);
    return r;
}

SampledSpectrum DegreeOfLinearPolarization(const Stokes& s) {
    SampledSpectrum r;
    for (int i = 0; i < NSpectrumSamples; ++i)
        if (s[0][i] != 0) r[i] = std::sqrt(Sqr(s[1][i]) + Sqr(s[2][i])) / std::abs(s[0][i]);
    return r;
}

SampledSpectrum AngleOfLinearPolarization(const Stokes& s) {
    SampledSpectrum r;
    for (int i = 0; i < NSpectrumSamples; ++i) r[i] = 0.5f * std::atan2(s[2][i], s[1][i]);
    return r;
}

}  // namespace kiln
