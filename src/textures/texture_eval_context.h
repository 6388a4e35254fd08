// Where textures are evaluated: the surface point and its screen-space footprint (pbrt-v4's
// TextureEvalContext and MaterialEvalContext).
#pragma once

#include <array>

#include "base/interaction.h"
#include "base/vecmath.h"

namespace kiln {

class TriangleMesh;

// Render-space point p with geometric normal n, surface coordinates uv, and the screen-space
// derivatives used to filter image textures (zero when unknown: the finest MIP level is used).
// On triangle meshes, mesh / triIndex / b identify the point for per-vertex attribute
// textures ("vertexattribute"); they come from SurfaceInteraction (set by
// Triangle::InteractionFromBarycentrics). Code that builds a context from a shape sample
// (an Interaction) must set them itself, e.g. for a Triangle tri:
//   ctx.mesh = tri->GetMesh(); ctx.triIndex = tri->TriangleIndex(); ctx.b = tri->Barycentrics(p);
struct TextureEvalContext {
    Point3f p;
    Vector3f dpdx, dpdy;
    Normal3f n;
    Point2f uv;
    Float dudx = 0, dudy = 0, dvdx = 0, dvdy = 0;
    int faceIndex = 0;
    Float time = 0;                      // shutter time in [0, 1]
    const TriangleMesh* mesh = nullptr;  // triangle hits only (not owned)
    int triIndex = 0;
    std::array<Float, 3> b = {0, 0, 0};  // barycentrics of p in triangle triIndex
    // The surface's temperature, kelvin, for materials whose textures depend on it
    // (Material::UsesTemperature; set by the scene's shader); 0: none given
    Float temperature = 0;

    TextureEvalContext() = default;
    TextureEvalContext(const SurfaceInteraction& si)
        : p(si.p),
          dpdx(si.dpdx),
          dpdy(si.dpdy),
          n(si.n),
          uv(si.uv),
          dudx(si.dudx),
          dudy(si.dudy),
          dvdx(si.dvdx),
          dvdy(si.dvdy),
          faceIndex(si.faceIndex),
          time(si.time),
          mesh(si.mesh),
          triIndex(si.triIndex),
          b(si.b) {}
};

// What a material needs besides the texture context: the outgoing direction and the shading
// frame (shading normal ns and tangent dpdus).
struct MaterialEvalContext : TextureEvalContext {
    Vector3f wo;
    Normal3f ns;
    Vector3f dpdus;

    MaterialEvalContext() = default;
    MaterialEvalContext(const SurfaceInteraction& si)
        : TextureEvalContext(si), wo(si.wo), ns(si.shading.n), dpdus(si.shading.dpdu) {}
};

}  // namespace kiln
