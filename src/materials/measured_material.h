// pbrt-v4's "measured" material: an RGL measured BRDF read from "string filename" (a `.bsdf`
// tensor file, resolved like every file parameter), MeasuredBxDF (bxdfs/measured_bxdf.h).
#pragma once

#include <string>

#include "materials/bxdfs/measured_bxdf.h"
#include "materials/material_base.h"
#include "textures/texture_eval_context.h"

namespace kiln {

class TextureParameterDictionary;

class MeasuredMaterial : public MaterialBase {
  public:
    MeasuredMaterial(const MeasuredBxDFData* data, std::string filename)
        : data(data), filename(std::move(filename)) {}
    MeasuredBxDF GetBxDF(const MaterialEvalContext&, const SampledWavelengths& lambda) const {
        return MeasuredBxDF(data, lambda);
    }
    const MeasuredBxDFData* Data() const { return data; }
    const std::string& Filename() const { return filename; }

    // Reads "filename"; a file loaded by several materials is read once per arena (scene).
    // A missing parameter, an unreadable file or a malformed one throw SceneError at the
    // "filename" parameter saying what is wrong.
    static MeasuredMaterial* Create(const TextureParameterDictionary& params, const FileLoc& loc,
                                    ObjectArena& arena);

  private:
    const MeasuredBxDFData* data;
    std::string filename;
};

}  // namespace kiln
