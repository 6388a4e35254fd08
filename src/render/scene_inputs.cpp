#include "render/scene_inputs.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
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

// 64-bit hash of bytes, four independent multiply-rotate lanes over 8-byte words (FNV-1a, as
// HashBytes uses, does one dependent multiply per byte: 2 GB of meshes would take seconds)
uint64_t HashLarge(const std::string& bytes, uint64_t seed) {
    uint64_t lane[4] = {seed ^ 0x9e3779b97f4a7c15ULL, seed + 0x632be59bd9b4e019ULL,
                        seed ^ 0x85ebca77c2b2ae63ULL, seed - 0xc2b2ae3d27d4eb4fULL};
    auto round = [](uint64_t h, uint64_t w) {
        h ^= w * 0x87c37b91114253d5ULL;
        h = (h << 31) | (h >> 33);
        return h * 0x4cf5ad432745937fULL;
    };
    size_t n = bytes.size(), i = 0;
    for (; i + 32 <= n; i += 32)
        for (int k = 0; k < 4; ++k) {
            uint64_t w;
            std::memcpy(&w, bytes.data() + i + 8 * k, 8);
            lane[k] = round(lane[k], w);
        }
    uint64_t h = MixBits(lane[0]) ^ MixBits(lane[1] + 1) ^ MixBits(lane[2] + 2) ^
                 MixBits(lane[3] + 3) ^ uint64_t(n);
    return HashBytes(bytes.data() + i, n - i, h);
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
        h = ReadFileBytes(file, &bytes, &error) ? HashLarge(bytes, h)
                                                : HashBytes(error.data(), error.size(), h);
    }
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

}  // namespace kiln
