// Texture coordinate generation (pbrt-v4's TextureMapping2D and TextureMapping3D): how a
// surface point becomes texture-space coordinates and their screen-space derivatives.
#pragma once

#include <variant>

#include "base/closed_set.h"
#include "base/transform.h"
#include "base/vecmath.h"
#include "textures/texture_eval_context.h"

namespace kiln {

class TextureParameterDictionary;
struct FileLoc;
class Diagnostics;

// 2D texture coordinates st (dimensionless) and their derivatives with respect to screen-space
// x and y (per pixel).
struct TexCoord2D {
    Point2f st;
    Float dsdx = 0, dsdy = 0, dtdx = 0, dtdy = 0;
};

// A texture-space point and its screen-space derivatives (texture-space units per pixel).
struct TexCoord3D {
    Point3f p;
    Vector3f dpdx, dpdy;
};

// UVMapping Definition
// st = (su u + du, sv v + dv).
class UVMapping {
  public:
    UVMapping(Float su = 1, Float sv = 1, Float du = 0, Float dv = 0)
        : su(su), sv(sv), du(du), dv(dv) {}
    TexCoord2D Map(const TextureEvalContext& ctx) const;

    Float su, sv, du, dv;
};

// SphericalMapping Definition
// st = (theta / pi, phi / (2 pi)) of the direction from the texture-space origin to p.
class SphericalMapping {
  public:
    explicit SphericalMapping(const Transform& textureFromRender)
        : textureFromRender(textureFromRender) {}
    TexCoord2D Map(const TextureEvalContext& ctx) const;

  private:
    Transform textureFromRender;
};

// CylindricalMapping Definition
// st = ((pi + atan2(y, x)) / (2 pi), z) in texture space.
class CylindricalMapping {
  public:
    explicit CylindricalMapping(const Transform& textureFromRender)
        : textureFromRender(textureFromRender) {}
    TexCoord2D Map(const TextureEvalContext& ctx) const;

  private:
    Transform textureFromRender;
};

// PlanarMapping Definition
// st = (ds + p . vs, dt + p . vt) with p in texture space.
class PlanarMapping {
  public:
    PlanarMapping(const Transform& textureFromRender, Vector3f vs, Vector3f vt, Float ds, Float dt)
        : textureFromRender(textureFromRender), vs(vs), vt(vt), ds(ds), dt(dt) {}
    TexCoord2D Map(const TextureEvalContext& ctx) const;

  private:
    Transform textureFromRender;
    Vector3f vs, vt;
    Float ds, dt;
};

// TextureMapping2D Definition
class TextureMapping2D
    : public ClosedSet<UVMapping, SphericalMapping, CylindricalMapping, PlanarMapping> {
  public:
    using ClosedSet::ClosedSet;

    TexCoord2D Map(const TextureEvalContext& ctx) const {
        return Dispatch([&](const auto& m) { return m.Map(ctx); });
    }

    // pbrt-v4 parameters: "string mapping" uv|spherical|cylindrical|planar; uv takes "float
    // uscale, vscale, udelta, vdelta", planar "vector3 v1, v2" and "float udelta, vdelta".
    // An unknown mapping throws SceneError.
    static TextureMapping2D Create(const TextureParameterDictionary& params,
                                   const Transform& renderFromTexture, const FileLoc& loc);
};

// TextureMapping3D Definition
// pbrt-v4's PointTransformMapping: p in texture space.
class TextureMapping3D {
  public:
    explicit TextureMapping3D(const Transform& textureFromRender = Transform())
        : textureFromRender(textureFromRender) {}
    TexCoord3D Map(const TextureEvalContext& ctx) const {
        return TexCoord3D{textureFromRender(ctx.p), textureFromRender(ctx.dpdx),
                          textureFromRender(ctx.dpdy)};
    }
    static TextureMapping3D Create(const Transform& renderFromTexture) {
        return TextureMapping3D(Inverse(renderFromTexture));
    }

  private:
    Transform textureFromRender;
};

}  // namespace kiln
