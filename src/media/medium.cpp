#include "media/medium.h"

namespace kiln {

Medium Medium::Create(const std::string& type, const TextureParameterDictionary& params,
                      const Transform& renderFromMedium, std::optional<EmissionModel> modelOverride,
                      const FileLoc& loc, ObjectArena& arena, Diagnostics& diag) {
    if (renderFromMedium.IsSingular())
        throw SceneError(loc, "the medium's transform is singular (e.g. a zero Scale)", type);
    if (type == "homogeneous")
        return HomogeneousMedium::Create(params, modelOverride, loc, arena, diag);
    if (type == "uniformgrid")
        return GridMedium::Create(params, renderFromMedium, modelOverride, loc, arena, diag);
    if (type == "rgbgrid")
        return RGBGridMedium::Create(params, renderFromMedium, modelOverride, loc, arena, diag);
    if (type == "cloud")
        return CloudMedium::Create(params, renderFromMedium, modelOverride, loc, arena, diag);
    if (type == "nanovdb" || type == "vdb")
        return GridMedium::CreateFromVDB(params, renderFromMedium, modelOverride, loc, arena, diag);
    throw SceneError(loc,
                     "unknown medium type (expected homogeneous, uniformgrid, rgbgrid, cloud, "
                     "nanovdb or vdb)",
                     type);
}

}  // namespace kiln
