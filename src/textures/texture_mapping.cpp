#include "textures/texture_mapping.h"

#include <cmath>

#include "core/parser/diagnostics.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// UVMapping Method Definitions
TexCoord2D UVMapping::Map(const TextureEvalContext& ctx) const {
    TexCoord2D c;
    c.dsdx = su * ctx.dudx;
    c.dsdy = su * ctx.dudy;
    c.dtdx = sv * ctx.dvdx;
    c.dtdy = sv * ctx.dvdy;
    c.st = Point2f(su * ctx.uv.x + du, sv * ctx.uv.y + dv);
    return c;
}

// SphericalMapping Method Definitions
TexCoord2D SphericalMapping::Map(const TextureEvalContext& ctx) const {
    Point3f pt = textureFromRender(ctx.p);
    // Gradients of theta / pi and phi / (2 pi) with respect to the texture-space point
    Float x2y2 = Sqr(pt.x) + Sqr(pt.y);
    Float r2 = x2y2 + Sqr(pt.z);
    Float sqrtx2y2 = std::sqrt(x2y2);
    Vector3f dsdp, dtdp;
    if (x2y2 > 0 && r2 > 0) {
        dsdp = Vector3f(pt.x * pt.z / sqrtx2y2, pt.y * pt.z / sqrtx2y2, -sqrtx2y2) / (Pi * r2);
        dtdp = Vector3f(-pt.y, pt.x, 0) / (2 * Pi * x2y2);
    }
    Vector3f dpdx = textureFromRender(ctx.dpdx), dpdy = textureFromRender(ctx.dpdy);
    TexCoord2D c;
    c.dsdx = Dot(dsdp, dpdx);
    c.dsdy = Dot(dsdp, dpdy);
    c.dtdx = Dot(dtdp, dpdx);
    c.dtdy = Dot(dtdp, dpdy);
    Vector3f vec = r2 > 0 ? Normalize(Vector3f(pt.x, pt.y, pt.z)) : Vector3f(0, 0, 1);
    c.st = Point2f(SphericalTheta(vec) * InvPi, SphericalPhi(vec) * Inv2Pi);
    return c;
}

// CylindricalMapping Method Definitions
TexCoord2D CylindricalMapping::Map(const TextureEvalContext& ctx) const {
    Point3f pt = textureFromRender(ctx.p);
    Float x2y2 = Sqr(pt.x) + Sqr(pt.y);
    Vector3f dsdp = x2y2 > 0 ? Vector3f(-pt.y, pt.x, 0) / (2 * Pi * x2y2) : Vector3f(0, 0, 0);
    Vector3f dtdp(0, 0, 1);
    Vector3f dpdx = textureFromRender(ctx.dpdx), dpdy = textureFromRender(ctx.dpdy);
    TexCoord2D c;
    c.dsdx = Dot(dsdp, dpdx);
    c.dsdy = Dot(dsdp, dpdy);
    c.dtdx = Dot(dtdp, dpdx);
    c.dtdy = Dot(dtdp, dpdy);
    c.st = Point2f((Pi + std::atan2(pt.y, pt.x)) * Inv2Pi, pt.z);
    return c;
}

// PlanarMapping Method Definitions
TexCoord2D PlanarMapping::Map(const TextureEvalContext& ctx) const {
    Point3f pt = textureFromRender(ctx.p);
    Vector3f vec(pt.x, pt.y, pt.z);
    Vector3f dpdx = textureFromRender(ctx.dpdx), dpdy = textureFromRender(ctx.dpdy);
    TexCoord2D c;
    c.dsdx = Dot(vs, dpdx);
    c.dsdy = Dot(vs, dpdy);
    c.dtdx = Dot(vt, dpdx);
    c.dtdy = Dot(vt, dpdy);
    c.st = Point2f(ds + Dot(vec, vs), dt + Dot(vec, vt));
    return c;
}

// TextureMapping2D Method Definitions
TextureMapping2D TextureMapping2D::Create(const TextureParameterDictionary& params,
                                          const Transform& renderFromTexture, const FileLoc& loc) {
    Transform textureFromRender = Inverse(renderFromTexture);
    std::string type = params.GetOneString("mapping", "uv");
    if (type == "uv") {
        Float su = params.GetOneFloat("uscale", 1), sv = params.GetOneFloat("vscale", 1);
        Float du = params.GetOneFloat("udelta", 0), dv = params.GetOneFloat("vdelta", 0);
        return UVMapping(su, sv, du, dv);
    }
    if (type == "spherical") return SphericalMapping(textureFromRender);
    if (type == "cylindrical") return CylindricalMapping(textureFromRender);
    if (type == "planar")
        return PlanarMapping(textureFromRender, params.GetOneVector3f("v1", Vector3f(1, 0, 0)),
                             params.GetOneVector3f("v2", Vector3f(0, 1, 0)),
                             params.GetOneFloat("udelta", 0), params.GetOneFloat("vdelta", 0));
    FileLoc at = params.Loc("mapping", loc);
    throw SceneError(at, "unknown 2D texture mapping \"" + type + "\"", type);
}

}  // namespace kiln
