// Bump and normal mapping (pbrt-v4's BumpMap and NormalMap): a material's "displacement" float
// texture or "normalmap" image perturbs the shading frame at a surface point before its BSDF is
// built. The integrator, light sampling and thermal emission all get the BSDF from
// the scene's shader (render/scene.h: SceneShader::GetBSDF), so a bumped hot surface emits in the
// same perturbed frame it scatters in.
#pragma once

#include <optional>

#include "base/interaction.h"
#include "base/object_arena.h"
#include "textures/texture.h"

namespace kiln {

class Image;
class TextureParameterDictionary;
class Diagnostics;

struct ShadingPerturbation {
    // pbrt-v4: a normal map takes precedence over a displacement texture.
    std::optional<FloatTexture> displacement;
    // R, G, B (linear) in [0, 1] encode a tangent-space normal 2 c - 1 (x along the shading
    // dp/du, z along the shading normal); looked up bilinearly at (u, 1 - v), repeating.
    const Image* normalMap = nullptr;

    bool Any() const { return displacement || normalMap; }
    // Whether BumpMap uses the screen-space footprint (it offsets by half the footprint in uv).
    bool UsesFootprint() const { return !normalMap && displacement; }

    // Reads a material's "displacement" (float or float texture) and "normalmap" (image file
    // name; a located SceneError when it cannot be read or lacks R, G, B channels). Normal
    // maps are shared through the NamedTextures' image cache.
    static ShadingPerturbation Read(const TextureParameterDictionary& params, ObjectArena& arena);
};

// The shading dp/du and dp/dv that the displacement texture d gives si (pbrt-v4's BumpMap):
// finite differences of d over half the uv footprint (du = 0.0005 without one),
// dp/du' = dp/du + (d(u + du) - d(u)) / du n + d dn/du, likewise for v.
void BumpMap(const FloatTexture& displacement, const SurfaceInteraction& si, Vector3f* dpdu,
             Vector3f* dpdv);
// The shading dp/du and dp/dv whose normal is the normal map's at si (pbrt-v4's NormalMap):
// the map's normal taken in the frame (dp/du, n x dp/du, n) of the shading geometry, lengths of
// dp/du and dp/dv kept.
void NormalMap(const Image& normalMap, const SurfaceInteraction& si, Vector3f* dpdu,
               Vector3f* dpdv);
// Replaces si's shading frame by the perturbed one (normal on the geometric normal's side).
// Perturbations that give a degenerate frame leave si unchanged.
void ApplyShadingPerturbation(const ShadingPerturbation& perturbation, SurfaceInteraction& si);

}  // namespace kiln
