#include "render/scene_inputs.h"

#include <cstdint>
#include <cstdio>
#include <set>

#include "base/file_reading.h"
#include "base/rng.h"
#include "core/parser/search_path.h"

namespace kiln {

namespace {

// Every parameter of every directive, in the description's order
template <typename F>
void ForEachParameter(const SceneDescription& d, F&& f) {
    auto entity = [&](const SceneEntity& e, bool isFilm = false) {
        for (const ParsedParameter& p : e.parameters.Parameters()) f(p, isFilm);
    };
    entity(d.film, true);
    for (const SceneEntity* e : {&d.sampler, &d.integrator, &d.filter, &d.accelerator}) entity(*e);
    entity(d.camera);
    for (const auto& [name, e] : d.namedMaterials) entity(e);
    for (const SceneEntity& e : d.materials) entity(e);
    for (const auto& [name, e] : d.floatTextures) entity(e);
    for (const auto& [name, e] : d.spectrumTextures) entity(e);
    for (const auto& [name, e] : d.media) entity(e);
    for (const SceneEntity& e : d.lights) entity(e);
    for (const SceneEntity& e : d.areaLights) entity(e);
    for (const SceneEntity& e : d.shapes) entity(e);
    for (const auto& [name, def] : d.instanceDefinitions)
        for (const SceneEntity& e : def.shapes) entity(e);
}

}  // namespace

std::vector<std::string> SceneInputFiles(const SceneDescription& desc,
                                         const std::vector<std::string>& parsed) {
    std::vector<std::string> files;
    std::set<std::string> seen;
    auto add = [&](const std::string& file) {
        if (seen.insert(file).second) files.push_back(file);
    };
    for (const std::string& f : parsed) add(f);
    ForEachParameter(desc, [&](const ParsedParameter& p, bool isFilm) {
        if ((p.type != "string" && p.type != "spectrum") || (isFilm && p.name == "filename"))
            return;
        for (const std::string& value : p.strings) {
            if (value.empty()) continue;
            std::string path = ResolveFilename(p.searchDirectory, value), error;
            if (IsRegularFile(path, &error)) add(path);
        }
    });
    return files;
}

std::string HashInputFiles(const std::vector<std::string>& files) {
    uint64_t h = 0;
    for (const std::string& file : files) {
        std::string bytes, error;
        h = HashBytes(file.data(), file.size(), h);
        h = ReadFileBytes(file, &bytes, &error) ? HashLargeBytes(bytes.data(), bytes.size(), h)
                                                : HashBytes(error.data(), error.size(), h);
    }
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

}  // namespace kiln
