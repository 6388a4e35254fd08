#include "materials/shading_perturbation.h"

#include <cmath>

#include "core/image/image.h"
#include "textures/image_texture.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// Reading
ShadingPerturbation ShadingPerturbation::Read(const TextureParameterDictionary& params,
                                              ObjectArena& arena) {
    ShadingPerturbation p;
    p.displacement = params.GetFloatTextureOrNull("displacement", arena);
    std::string filename = params.GetOneFilename("normalmap", "");
    if (filename.empty()) return p;
    ImageTextureCache* cache = params.Textures() ? params.Textures()->imageCache.get() : nullptr;
    if (cache) p.normalMap = cache->FindImage(filename);
    if (p.normalMap) return p;
    Image rgb;
    try {
        Image image = Image::Read(filename, nullptr, ColorEncoding::Linear(), &arena.Budget());
        if (image.ChannelIndex("R") < 0 || image.ChannelIndex("G") < 0 ||
            image.ChannelIndex("B") < 0)
            throw SceneError(params.Loc("normalmap"),
                             "normal map image must have R, G and B channels", filename);
        rgb = image.SelectChannels({"R", "G", "B"});
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        throw SceneError(params.Loc("normalmap"),
                         std::string("cannot read normal map: ") + e.what(), filename);
    }
    p.normalMap = arena.New<Image>(std::move(rgb));
    if (cache) cache->InsertImage(filename, p.normalMap);
    return p;
}

// BumpMap and NormalMap
void BumpMap(const FloatTexture& displacement, const SurfaceInteraction& si, Vector3f* dpdu,
             Vector3f* dpdv) {
    TextureEvalContext ctx(si), shifted(si);
    // Shift half the footprint in u, then in v
    Float du = .5f * (std::abs(si.dudx) + std::abs(si.dudy));
    if (du == 0) du = .0005f;
    shifted.p = si.p + du * si.shading.dpdu;
    shifted.uv = si.uv + Vector2f(du, 0.f);
    Float uDisplace = displacement.Evaluate(shifted);
    Float dv = .5f * (std::abs(si.dvdx) + std::abs(si.dvdy));
    if (dv == 0) dv = .0005f;
    shifted.p = si.p + dv * si.shading.dpdv;
    shifted.uv = si.uv + Vector2f(0.f, dv);
    Float vDisplace = displacement.Evaluate(shifted);
    Float displace = displacement.Evaluate(ctx);
    Vector3f ns(si.shading.n);
    *dpdu =
        si.shading.dpdu + (uDisplace - displace) / du * ns + displace * Vector3f(si.shading.dndu);
    *dpdv =
        si.shading.dpdv + (vDisplace - displace) / dv * ns + displace * Vector3f(si.shading.dndv);
}

void NormalMap(const Image& normalMap, const SurfaceInteraction& si, Vector3f* dpdu,
               Vector3f* dpdv) {
    // The map repeats: reduce uv to [0, 1) first (exact, and keeps pixel indices small)
    Point2f st(si.uv.x - std::floor(si.uv.x), 1 - si.uv.y);
    st.y -= std::floor(st.y);
    Vector3f ns(2 * normalMap.BilerpChannel(st, 0, WrapMode::Repeat) - 1,
                2 * normalMap.BilerpChannel(st, 1, WrapMode::Repeat) - 1,
                2 * normalMap.BilerpChannel(st, 2, WrapMode::Repeat) - 1);
    ns = Normalize(ns);
    Frame frame = Frame::FromXZ(Normalize(si.shading.dpdu), Vector3f(si.shading.n));
    ns = frame.FromLocal(ns);
    Float ulen = Length(si.shading.dpdu), vlen = Length(si.shading.dpdv);
    *dpdu = Normalize(GramSchmidt(si.shading.dpdu, ns)) * ulen;
    *dpdv = Normalize(Cross(ns, *dpdu)) * vlen;
}

void ApplyShadingPerturbation(const ShadingPerturbation& perturbation, SurfaceInteraction& si) {
    if (!IsFinite(si.uv.x) || !IsFinite(si.uv.y)) return;
    Vector3f dpdu, dpdv;
    if (perturbation.normalMap)
        NormalMap(*perturbation.normalMap, si, &dpdu, &dpdv);
    else if (perturbation.displacement)
        BumpMap(*perturbation.displacement, si, &dpdu, &dpdv);
    else
        return;
    Vector3f c = Cross(dpdu, dpdv);
    Float len2 = LengthSquared(c);
    // A zero or non-finite frame (a black normal-map texel, a displacement overflowing float)
    // keeps the unperturbed one
    if (!(len2 > 0) || !IsFinite(len2) || !IsFinite(dpdu.x + dpdu.y + dpdu.z) ||
        !IsFinite(dpdv.x + dpdv.y + dpdv.z))
        return;
    Normal3f ns(c / std::sqrt(len2));
    si.SetShadingGeometry(ns, dpdu, dpdv, si.shading.dndu, si.shading.dndv, false);
}

}  // namespace kiln
