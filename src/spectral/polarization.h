// Polarised light: Stokes vectors and Mueller matrices per sampled wavelength.
//
// A Stokes vector (S0, S1, S2, S3) describes light travelling along a direction d relative to
// a reference frame (x, y, d), x and y unit vectors perpendicular to d with y = d x x:
//   S0 total radiance, S1 = I(x) - I(y), S2 = I(+45) - I(-45) (the +45 degree axis is
//   (x + y) / sqrt 2), S3 = I(right circular) - I(left circular),
// each in the units of radiance (W m^-2 sr^-1 nm^-1) at each sampled wavelength. A Mueller
// matrix maps the Stokes vector of incident light, in a frame about its direction, to that of
// the outgoing light, in a frame about its own direction; a matrix is only meaningful together
// with those two frames. kiln's convention (Mitsuba 3's): every direction d has an implicit
// frame, x = StokesBasis(d), and Mueller matrices in path transport map between implicit
// frames, so throughput is a plain matrix product. Matrices built in other frames (the plane
// of incidence) are converted with RotateMuellerBasis.
//
// References: Collett, Field Guide to Polarization (2005), ch. 4-6; Wilkie & Weidlich,
// "Polarised light in computer graphics", SIGGRAPH Asia 2016 course.
#pragma once

#include <array>

#include "base/vecmath.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

class Stokes {
  public:
    Stokes() = default;
    // Unpolarised light of radiance L.
    explicit Stokes(const SampledSpectrum& L) : s{L, {}, {}, {}} {}
    Stokes(const SampledSpectrum& s0, const SampledSpectrum& s1, const SampledSpectrum& s2,
           const SampledSpectrum& s3)
        : s{s0, s1, s2, s3} {}

    const SampledSpectrum& operator[](int i) const { return s[i]; }
    SampledSpectrum& operator[](int i) { return s[i]; }
    // The intensity S0.
    const SampledSpectrum& Intensity() const { return s[0]; }

    explicit operator bool() const { return bool(s[0]) || bool(s[1]) || bool(s[2]) || bool(s[3]); }
    Stokes& operator+=(const Stokes& o) {
        for (int i = 0; i < 4; ++i) s[i] += o.s[i];
        return *this;
    }
    Stokes operator+(const Stokes& o) const { return Stokes(*this) += o; }
    Stokes& operator*=(Float a) {
        for (SampledSpectrum& c : s) c *= a;
        return *this;
    }
    Stokes operator*(Float a) const { return Stokes(*this) *= a; }
    Stokes& operator*=(const SampledSpectrum& a) {
        for (SampledSpectrum& c : s) c *= a;
        return *this;
    }
    Stokes operator*(const SampledSpectrum& a) const { return Stokes(*this) *= a; }
    Stokes operator/(Float a) const { return Stokes(*this) *= (1 / a); }
    bool IsFinite() const {
        return s[0].IsFinite() && s[1].IsFinite() && s[2].IsFinite() && s[3].IsFinite();
    }

  private:
    std::array<SampledSpectrum, 4> s;
};
inline Stokes operator*(Float a, const Stokes& s) { return s * a; }
inline Stokes operator*(const SampledSpectrum& a, const Stokes& s) { return s * a; }

class MuellerMatrix {
  public:
    // The zero matrix.
    MuellerMatrix() = default;
    // Identity times a (a non-polarising, non-depolarising attenuation).
    static MuellerMatrix Diagonal(const SampledSpectrum& a) {
        MuellerMatrix m;
        for (int i = 0; i < 4; ++i) m.m[i][i] = a;
        return m;
    }
    static MuellerMatrix Identity() { return Diagonal(SampledSpectrum(1.f)); }
    // Ideal depolariser with transmittance a: only M00 = a, whatever the frames.
    static MuellerMatrix Depolarizer(const SampledSpectrum& a) {
        MuellerMatrix m;
        m.m[0][0] = a;
        return m;
    }

    const SampledSpectrum& operator()(int r, int c) const { return m[r][c]; }
    SampledSpectrum& operator()(int r, int c) { return m[r][c]; }

    explicit operator bool() const {
        for (const auto& row : m)
            for (const SampledSpectrum& e : row)
                if (e) return true;
        return false;
    }

    MuellerMatrix operator*(const MuellerMatrix& b) const {
        MuellerMatrix r;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                SampledSpectrum sum = m[i][0] * b.m[0][j];
                for (int k = 1; k < 4; ++k) sum += m[i][k] * b.m[k][j];
                r.m[i][j] = sum;
            }
        return r;
    }
    Stokes operator*(const Stokes& s) const {
        Stokes r;
        for (int i = 0; i < 4; ++i) {
            SampledSpectrum sum = m[i][0] * s[0];
            for (int k = 1; k < 4; ++k) sum += m[i][k] * s[k];
            r[i] = sum;
        }
        return r;
    }
    MuellerMatrix& operator*=(const SampledSpectrum& a) {
        for (auto& row : m)
            for (SampledSpectrum& e : row) e *= a;
        return *this;
    }
    MuellerMatrix operator*(const SampledSpectrum& a) const { return MuellerMatrix(*this) *= a; }
    MuellerMatrix& operator*=(Float a) {
        for (auto& row : m)
            for (SampledSpectrum& e : row) e *= a;
        return *this;
    }
    MuellerMatrix operator*(Float a) const { return MuellerMatrix(*this) *= a; }
    MuellerMatrix operator/(Float a) const { return MuellerMatrix(*this) *= (1 / a); }
    MuellerMatrix& operator+=(const MuellerMatrix& b) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) m[i][j] += b.m[i][j];
        return *this;
    }
    MuellerMatrix operator+(const MuellerMatrix& b) const { return MuellerMatrix(*this) += b; }
    MuellerMatrix Transposed() const {
        MuellerMatrix r;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
        return r;
    }

    // The throughput of unpolarised light, M00: what an unpolarised renderer's scalar BSDF is.
    const SampledSpectrum& Intensity() const { return m[0][0]; }
    // Largest |entry| of the first row: bounds the S0 any unit Stokes input can produce.
    Float MaxComponentValue() const {
        Float r = 0;
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < NSpectrumSamples; ++i) r = std::max(r, std::abs(m[0][j][i]));
        return r;
    }
    bool IsFinite() const {
        for (const auto& row : m)
            for (const SampledSpectrum& e : row)
                if (!e.IsFinite()) return false;
        return true;
    }

  private:
    std::array<std::array<SampledSpectrum, 4>, 4> m;
};
inline MuellerMatrix operator*(Float a, const MuellerMatrix& m) { return m * a; }
inline MuellerMatrix operator*(const SampledSpectrum& a, const MuellerMatrix& m) { return m * a; }

// Frames
//
// Unit axis perpendicular to the plane containing n and w (both unit): normalize(n x w); when
// w is parallel to n, a fixed axis perpendicular to n (the same for every such w).
inline Vector3f PlaneAxis(Vector3f n, Vector3f w) {
    Vector3f c = Cross(n, w);
    Float len2 = LengthSquared(c);
    if (len2 > 1e-12f) return c / std::sqrt(len2);
    Vector3f x, y;
    CoordinateSystem(n, &x, &y);
    return x;
}
// The implicit reference x axis of light travelling along unit d (a unit vector perpendicular
// to d, a fixed function of d).
inline Vector3f StokesBasis(Vector3f d) {
    Vector3f x, y;
    CoordinateSystem(d, &x, &y);
    return x;
}
// Angle (radians) by which the reference axis `from` must turn about d, counter-clockwise seen
// against the direction of travel, to become `to` (both perpendicular to unit d).
Float StokesBasisAngle(Vector3f d, Vector3f from, Vector3f to);
// Mueller matrix that re-expresses a Stokes vector given with reference axis x in the frame
// turned by theta (radians) about the direction of travel (Collett eq. 4.2-3).
MuellerMatrix RotatorMatrix(Float theta);
// The Stokes vector s of light travelling along d, given with reference axis `from`, expressed
// with reference axis `to`.
Stokes RotateStokesBasis(const Stokes& s, Vector3f d, Vector3f from, Vector3f to);
// M maps (dIn, inFrom) to (dOut, outFrom); returns the matrix mapping (dIn, inTo) to
// (dOut, outTo).
MuellerMatrix RotateMuellerBasis(const MuellerMatrix& M, Vector3f dIn, Vector3f inFrom,
                                 Vector3f inTo, Vector3f dOut, Vector3f outFrom, Vector3f outTo);

// Optical elements, in the frame of the light's reference axis x
//
// Ideal linear polariser with transmission axis at angle theta (radians) from x.
MuellerMatrix LinearPolarizer(Float theta);
// Linear retarder with fast axis at theta (radians) from x and retardance delta (radians):
// the slow component is delayed by delta (a quarter-wave plate has delta = pi / 2).
MuellerMatrix LinearRetarder(Float theta, Float delta);

// Degree of (total) polarisation sqrt(S1^2 + S2^2 + S3^2) / S0 and of linear polarisation
// sqrt(S1^2 + S2^2) / S0 at each wavelength (0 where S0 = 0); angle of linear polarisation
// 0.5 atan2(S2, S1), radians from the reference axis.
SampledSpectrum DegreeOfPolarization(const Stokes& s);
SampledSpectrum DegreeOfLinearPolarization(const Stokes& s);
SampledSpectrum AngleOfLinearPolarization(const Stokes& s);

}  // namespace kiln
