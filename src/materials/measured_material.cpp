#include "materials/measured_material.h"

#include "core/parser/diagnostics.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

MeasuredMaterial* MeasuredMaterial::Create(const TextureParameterDictionary& params,
                                           const FileLoc& loc, ObjectArena& arena) {
    const std::string filename = params.GetOneFilename("filename", "");
    if (filename.empty())
        throw SceneError(loc, "\"measured\" material needs \"string filename\" (a .bsdf file)",
                         "measured");
    const MeasuredBxDFData* data;
    try {
        data = arena.Shared<MeasuredBxDFData>(filename, [&] {
            TensorFile file = TensorFile::Read(filename);
            // The tables take about twice the file (the distributions add their CDFs)
            arena.Budget().Charge(2.0 * file.Size(), "the measured BRDF \"" + filename + "\"");
            return MeasuredBxDFData::FromTensor(file);
        });
    } catch (const TensorFileError& e) {
        throw SceneError(params.Loc("filename"), "measured BRDF \"" + filename + "\": " + e.what(),
                         filename);
    } catch (const MemoryLimitError& e) {
        throw SceneError(params.Loc("filename"), e.what(), filename);
    }
    return arena.New<MeasuredMaterial>(data, filename);
}

}  // namespace kiln
