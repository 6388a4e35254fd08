#include "textures/noise.h"

#include <array>
#include <cmath>

namespace kiln {

namespace {

// Ken Perlin's permutation of 0..255, from his reference implementation of improved noise
// (K. Perlin, "Improving Noise", SIGGRAPH 2002; https://mrl.cs.nyu.edu/~perlin/noise/), as used
// by pbrt. Indexed modulo 256 twice over, hence the doubled lookup below.
constexpr int kNoisePermSize = 256;
constexpr std::array<unsigned char, kNoisePermSize> kNoisePerm = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180,
};

int Perm(int i) { return kNoisePerm[i & (kNoisePermSize - 1)]; }

// Gradient (one of 12 cube edge directions) at lattice point (x, y, z) dotted with the offset
Float Grad(int x, int y, int z, Float dx, Float dy, Float dz) {
    int h = Perm(Perm(Perm(x) + y) + z) & 15;
    Float u = (h < 8 || h == 12 || h == 13) ? dx : dy;
    Float v = (h < 4 || h == 12 || h == 13) ? dy : dz;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// Quintic fade curve 6t^5 - 15t^4 + 10t^3
Float NoiseWeight(Float t) {
    Float t3 = t * t * t, t4 = t3 * t;
    return 6 * t4 * t - 15 * t4 + 10 * t3;
}

Float SmoothStepF(Float x, Float a, Float b) {
    if (a == b) return x < a ? 0 : 1;
    Float t = Clamp((x - a) / (b - a), Float(0), Float(1));
    return t * t * (3 - 2 * t);
}

// Octaves that the footprint allows before aliasing (fractional), at most maxOctaves
Float OctaveCount(Vector3f dpdx, Vector3f dpdy, int maxOctaves) {
    Float len2 = std::max(LengthSquared(dpdx), LengthSquared(dpdy));
    if (len2 <= 0) return Float(maxOctaves);
    return Clamp(-1 - std::log2(len2) / 2, Float(0), Float(maxOctaves));
}

}  // namespace

// Noise Function Definitions
Float Noise(Float x, Float y, Float z) {
    // Lattice cell and offsets within it
    Float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    Float dx = x - fx, dy = y - fy, dz = z - fz;
    int ix = int(int64_t(fx) & (kNoisePermSize - 1));
    int iy = int(int64_t(fy) & (kNoisePermSize - 1));
    int iz = int(int64_t(fz) & (kNoisePermSize - 1));
    // Gradient weights at the eight corners, trilinearly blended with the fade curve
    Float w000 = Grad(ix, iy, iz, dx, dy, dz);
    Float w100 = Grad(ix + 1, iy, iz, dx - 1, dy, dz);
    Float w010 = Grad(ix, iy + 1, iz, dx, dy - 1, dz);
    Float w110 = Grad(ix + 1, iy + 1, iz, dx - 1, dy - 1, dz);
    Float w001 = Grad(ix, iy, iz + 1, dx, dy, dz - 1);
    Float w101 = Grad(ix + 1, iy, iz + 1, dx - 1, dy, dz - 1);
    Float w011 = Grad(ix, iy + 1, iz + 1, dx, dy - 1, dz - 1);
    Float w111 = Grad(ix + 1, iy + 1, iz + 1, dx - 1, dy - 1, dz - 1);
    Float wx = NoiseWeight(dx), wy = NoiseWeight(dy), wz = NoiseWeight(dz);
    Float x00 = Lerp(wx, w000, w100), x10 = Lerp(wx, w010, w110);
    Float x01 = Lerp(wx, w001, w101), x11 = Lerp(wx, w011, w111);
    Float y0 = Lerp(wy, x00, x10), y1 = Lerp(wy, x01, x11);
    return Lerp(wz, y0, y1);
}

Float FBm(Point3f p, Vector3f dpdx, Vector3f dpdy, Float omega, int maxOctaves) {
    Float n = OctaveCount(dpdx, dpdy, maxOctaves);
    int nInt = int(std::floor(n));
    Float sum = 0, lambda = 1, o = 1;
    for (int i = 0; i < nInt; ++i) {
        sum += o * Noise(Point3f(lambda * p.x, lambda * p.y, lambda * p.z));
        lambda *= Float(1.99);
        o *= omega;
    }
    // Fade in the partial octave
    Float nPartial = n - nInt;
    sum += o * SmoothStepF(nPartial, Float(0.3), Float(0.7)) *
           Noise(Point3f(lambda * p.x, lambda * p.y, lambda * p.z));
    return sum;
}

Float Turbulence(Point3f p, Vector3f dpdx, Vector3f dpdy, Float omega, int maxOctaves) {
    Float n = OctaveCount(dpdx, dpdy, maxOctaves);
    int nInt = int(std::floor(n));
    Float sum = 0, lambda = 1, o = 1;
    for (int i = 0; i < nInt; ++i) {
        sum += o * std::abs(Noise(Point3f(lambda * p.x, lambda * p.y, lambda * p.z)));
        lambda *= Float(1.99);
        o *= omega;
    }
    // The partial octave blends towards the mean of |noise|, and the aliased ones use it
    Float nPartial = n - nInt;
    sum += o * Lerp(SmoothStepF(nPartial, Float(0.3), Float(0.7)), Float(0.2),
                    std::abs(Noise(Point3f(lambda * p.x, lambda * p.y, lambda * p.z))));
    for (int i = nInt; i < maxOctaves; ++i) {
        sum += o * Float(0.2);
        o *= omega;
    }
    return sum;
}

}  // namespace kiln
