#include "core/geometry/ply_writer.h"

#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace kiln {

namespace {

template <typename T>
void Append(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace

std::string EncodePly(const PlyTriangles& m) {
    size_t nv = m.p.size(), nt = m.indices.size() / 3;
    if (m.indices.size() % 3 != 0 || (!m.n.empty() && m.n.size() != nv) ||
        (!m.uv.empty() && m.uv.size() != nv) ||
        (!m.faceIndices.empty() && m.faceIndices.size() != nt))
        throw std::invalid_argument("PLY mesh: inconsistent array sizes");
    for (int i : m.indices)
        if (i < 0 || size_t(i) >= nv) throw std::invalid_argument("PLY mesh: index out of range");
    for (const auto& [name, values] : m.vertexAttributes)
        if (values.size() != nv)
            throw std::invalid_argument("PLY mesh: attribute \"" + name + "\" size");
    std::ostringstream header;
    header << "ply\nformat binary_little_endian 1.0\ncomment written by kiln\nelement vertex " << nv
           << "\nproperty float x\nproperty float y\nproperty float z\n";
    if (!m.n.empty()) header << "property float nx\nproperty float ny\nproperty float nz\n";
    if (!m.uv.empty()) header << "property float u\nproperty float v\n";
    for (const auto& [name, values] : m.vertexAttributes)
        header << "property float " << name << "\n";
    header << "element face " << nt << "\nproperty list uchar int vertex_indices\n";
    if (!m.faceIndices.empty()) header << "property int face_indices\n";
    header << "end_header\n";
    std::string out = header.str();
    for (size_t i = 0; i < nv; ++i) {
        for (Float c : {m.p[i].x, m.p[i].y, m.p[i].z}) Append(out, float(c));
        if (!m.n.empty())
            for (Float c : {m.n[i].x, m.n[i].y, m.n[i].z}) Append(out, float(c));
        if (!m.uv.empty())
            for (Float c : {m.uv[i].x, m.uv[i].y}) Append(out, float(c));
        for (const auto& [name, values] : m.vertexAttributes) Append(out, float(values[i]));
    }
    for (size_t t = 0; t < nt; ++t) {
        Append(out, uint8_t(3));
        for (int k = 0; k < 3; ++k) Append(out, int32_t(m.indices[3 * t + k]));
        if (!m.faceIndices.empty()) Append(out, int32_t(m.faceIndices[t]));
    }
    return out;
}

}  // namespace kiln
