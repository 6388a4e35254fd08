// A shape's alpha (pbrt-v4's "alpha" parameter): the fraction of the surface that exists at a
// point. Where alpha is 0 the surface is cut out (rays pass through it, shadow rays too, and it
// does not emit); where it lies between 0 and 1 a ray passes with probability 1 - alpha, decided
// by a hash of the query (pbrt-v4's stochastic alpha test).
//
// The accelerator (core/geometry) evaluates alpha through this interface at a surface point;
// the texture that gives it lives in the textures layer above (textures/texture_alpha_mask.h).
#pragma once

#include <cstdint>

#include "base/interaction.h"
#include "base/vecmath.h"

namespace kiln {

class AlphaMask {
  public:
    virtual ~AlphaMask() = default;
    // Alpha at the surface point (values above 1 count as 1, below 0 as 0).
    virtual Float Alpha(const SurfaceInteraction& si) const = 0;

    // Whether the surface is absent at si for a query whose uniform number is u in [0, 1):
    // never where alpha >= 1, always where alpha <= 0, otherwise when u > alpha.
    bool Masked(const SurfaceInteraction& si, Float u) const {
        Float a = Alpha(si);
        if (!(a < 1)) return false;
        return a <= 0 || u > a;
    }
    // Whether alpha is the constant 0 ("float alpha" 0): pbrt-v4 makes an area light on such a
    // shape an invisible light that still emits (DiffuseAreaLight).
    virtual bool IsConstantZero() const { return false; }
};

// A uniform number in [0, 1) from a 64-bit hash (the top 24 bits).
inline Float HashToUniform(uint64_t h) { return Float(h >> 40) * 0x1p-24f; }

}  // namespace kiln
