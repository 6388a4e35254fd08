// What the material tests share: materials made from parameter lists with named textures, and
// the evaluation context of a flat point.
#pragma once

#include <map>
#include <string>

#include "../textures/param_helpers.h"
#include "materials/materials.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln::test {

struct MaterialFixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    NamedTextures named;
    std::map<std::string, Material> namedMaterials;

    const Material* Make(const std::string& type, ParsedParameterVector params) {
        ParameterDictionary d(std::move(params), nullptr);
        TextureParameterDictionary tp(&d, &named);
        return arena.New<Material>(
            Material::Create(type, tp, namedMaterials, TestLoc(), arena, diag));
    }
    // A float texture `name` interpolating v00 ... v11 bilinearly over uv.
    void AddBilerpFloat(const std::string& name, Float v00, Float v10, Float v01, Float v11) {
        ParameterDictionary d(
            {Float1("v00", v00), Float1("v10", v10), Float1("v01", v01), Float1("v11", v11)},
            nullptr);
        TextureParameterDictionary tp(&d, &named);
        named.floatTextures.insert_or_assign(
            name, CreateFloatTexture("bilerp", Transform(), tp, TestLoc(), arena, diag));
    }
};

inline ParsedParameter Texture(const std::string& name, const std::string& texture) {
    return Strings("texture", name, {texture});
}

// A point (uv, 0) of the plane z = 0 with normal +z and dp/du = +x, seen from wo.
inline MaterialEvalContext Context(Point2f uv, Vector3f wo) {
    MaterialEvalContext ctx;
    ctx.p = Point3f(uv.x, uv.y, 0);
    ctx.n = ctx.ns = Normal3f(0, 0, 1);
    ctx.dpdus = Vector3f(1, 0, 0);
    ctx.uv = uv;
    ctx.wo = wo;
    return ctx;
}

}  // namespace kiln::test
