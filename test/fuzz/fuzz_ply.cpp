// libFuzzer target: kiln's PLY reader (ASCII and binary, triangles and quads, per-vertex
// attributes) on arbitrary bytes. Every input must end in a mesh or a SceneError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/geometry/ply_reader.h"
#include "core/parser/diagnostics.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        kiln::TriQuadMesh::ParsePLY(bytes, "fuzz.ply");
    } catch (const kiln::SceneError&) {
    }
    return 0;
}
