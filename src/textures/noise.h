// Perlin noise and its sums over octaves (pbrt-v4's Noise, FBm and Turbulence), used by the
// procedural textures. Values are dimensionless; Noise is in about [-1, 1] and 0 at integer
// lattice points.
#pragma once

#include "base/vecmath.h"

namespace kiln {

// Improved Perlin noise (Perlin 2002) at a point.
Float Noise(Float x, Float y = Float(0.5), Float z = Float(0.5));
inline Float Noise(Point3f p) { return Noise(p.x, p.y, p.z); }
// Its gradient, by forward differences over 0.01 (pbrt-v4's DNoise).
inline Vector3f DNoise(Point3f p) {
    constexpr Float delta = 0.01f;
    Float n = Noise(p);
    return Vector3f(Noise(p + Vector3f(delta, 0, 0)) - n, Noise(p + Vector3f(0, delta, 0)) - n,
                    Noise(p + Vector3f(0, 0, delta)) - n) /
           delta;
}

// Fractional Brownian motion: octaves of noise at frequencies 1.99^i with amplitudes omega^i,
// truncated where the footprint (dpdx, dpdy) would alias; at most maxOctaves octaves.
Float FBm(Point3f p, Vector3f dpdx, Vector3f dpdy, Float omega, int maxOctaves);
// Like FBm with |noise| per octave; aliased octaves are replaced by their mean 0.2.
Float Turbulence(Point3f p, Vector3f dpdx, Vector3f dpdy, Float omega, int maxOctaves);

}  // namespace kiln
