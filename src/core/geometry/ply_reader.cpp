// PLY parsing: header, then ascii or binary element data. Format reference: Greg Turk, "The
// PLY Polygon File Format" (1994).
#include "core/geometry/ply_reader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>

#include "base/file_reading.h"
#include "core/geometry/shape_util.h"
#include "core/parser/diagnostics.h"

namespace kiln {

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64, Invalid };

PlyType ParseType(const std::string& s) {
    if (s == "char" || s == "int8") return PlyType::Int8;
    if (s == "uchar" || s == "uint8") return PlyType::UInt8;
    if (s == "short" || s == "int16") return PlyType::Int16;
    if (s == "ushort" || s == "uint16") return PlyType::UInt16;
    if (s == "int" || s == "int32") return PlyType::Int32;
    if (s == "uint" || s == "uint32") return PlyType::UInt32;
    if (s == "float" || s == "float32") return PlyType::Float32;
    if (s == "double" || s == "float64") return PlyType::Float64;
    return PlyType::Invalid;
}

int TypeSize(PlyType t) {
    switch (t) {
        case PlyType::Int8:
        case PlyType::UInt8:
            return 1;
        case PlyType::Int16:
        case PlyType::UInt16:
            return 2;
        case PlyType::Int32:
        case PlyType::UInt32:
        case PlyType::Float32:
            return 4;
        default:
            return 8;
    }
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Invalid;
    bool isList = false;
    PlyType countType = PlyType::Invalid;
};

struct PlyElement {
    std::string name;
    size_t count = 0;
    std::vector<PlyProperty> props;
};

enum class PlyFormat { Ascii, BinaryLE, BinaryBE };

// Reads values from the element data section, ascii or binary.
class PlyDataReader {
  public:
    PlyDataReader(const std::string& filename, const std::string& data, size_t offset,
                  PlyFormat format, int line)
        : filename(filename), data(data), pos(offset), format(format), line(line) {}

    // A list's length: a whole number >= 0 (ASCII data may say anything)
    size_t ReadCount(PlyType t) {
        double n = Read(t);
        if (!(n >= 0 && n <= 4294967295.0 && n == std::floor(n)))
            Fail("list length " + std::to_string(n) + " is not a count");
        return size_t(n);
    }

    double Read(PlyType t) {
        if (format == PlyFormat::Ascii) return ReadAscii();
        int n = TypeSize(t);
        if (pos + n > data.size()) Fail("unexpected end of file in binary data");
        unsigned char b[8];
        std::memcpy(b, data.data() + pos, n);
        pos += n;
        bool fileLE = format == PlyFormat::BinaryLE;
        if (fileLE != (std::endian::native == std::endian::little))
            for (int i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
        switch (t) {
            case PlyType::Int8:
                return int8_t(b[0]);
            case PlyType::UInt8:
                return b[0];
            case PlyType::Int16:
                return Get<int16_t>(b);
            case PlyType::UInt16:
                return Get<uint16_t>(b);
            case PlyType::Int32:
                return Get<int32_t>(b);
            case PlyType::UInt32:
                return Get<uint32_t>(b);
            case PlyType::Float32:
                return Get<float>(b);
            default:
                return Get<double>(b);
        }
    }
    [[noreturn]] void Fail(const std::string& message) const {
        auto file = std::make_shared<const std::string>(filename);
        throw SceneError(FileLoc(file, format == PlyFormat::Ascii ? line : 0, 0),
                         "malformed PLY file: " + message);
    }

  private:
    template <typename T>
    static double Get(const unsigned char* b) {
        T v;
        std::memcpy(&v, b, sizeof(T));
        return double(v);
    }
    double ReadAscii() {
        while (pos < data.size() && std::isspace((unsigned char)data[pos])) {
            if (data[pos] == '\n') ++line;
            ++pos;
        }
        if (pos >= data.size()) Fail("unexpected end of file in ascii data");
        const char* start = data.c_str() + pos;
        char* end = nullptr;
        double v = std::strtod(start, &end);
        if (end == start || (*end && !std::isspace((unsigned char)*end))) {
            size_t e = pos;
            while (e < data.size() && !std::isspace((unsigned char)data[e])) ++e;
            Fail("invalid number '" + data.substr(pos, e - pos) + "'");
        }
        pos += end - start;
        return v;
    }

    const std::string& filename;
    const std::string& data;
    size_t pos;
    PlyFormat format;
    int line;
};

// A quad is planar when its fourth vertex lies on the plane of the first three, relative to
// the quad's size.
bool IsPlanar(Point3f p0, Point3f p1, Point3f p2, Point3f p3) {
    Vector3f n = SafeNormalize(Cross(p1 - p0, p2 - p0));
    if (n == Vector3f(0, 0, 0)) n = SafeNormalize(Cross(p2 - p0, p3 - p0));
    if (n == Vector3f(0, 0, 0)) return true;
    Float scale = std::max({Length(p1 - p0), Length(p2 - p0), Length(p3 - p0)});
    return std::abs(Dot(n, p3 - p0)) <= 1e-5f * scale;
}

}  // namespace

// PLY reading
TriQuadMesh TriQuadMesh::ReadPLY(const std::string& filename, const HeaderCounts& beforeData,
                                 uint64_t maxBytes) {
    std::string data, error;
    if (!ReadFileBytes(filename, &data, &error, maxBytes))  // gzip-compressed PLY too
        throw SceneError(FileLoc(std::make_shared<const std::string>(filename), 0, 0),
                         "cannot read PLY file: " + error);
    return ParsePLY(data, filename, beforeData);
}

TriQuadMesh TriQuadMesh::ParsePLY(const std::string& data, const std::string& filename,
                                  const HeaderCounts& beforeData) {
    auto file = std::make_shared<const std::string>(filename);
    auto fail = [&](int line, const std::string& message) {
        throw SceneError(FileLoc(file, line, 0), "malformed PLY file: " + message);
    };

    // Header
    size_t pos = 0;
    int line = 0;
    auto nextLine = [&]() -> std::optional<std::string> {
        if (pos >= data.size()) return std::nullopt;
        size_t e = data.find('\n', pos);
        if (e == std::string::npos) e = data.size();
        std::string l = data.substr(pos, e - pos);
        if (!l.empty() && l.back() == '\r') l.pop_back();
        pos = std::min(e + 1, data.size() + 1);
        ++line;
        return l;
    };
    auto first = nextLine();
    if (!first || *first != "ply") fail(1, "missing 'ply' magic number");
    std::optional<PlyFormat> format;
    std::vector<PlyElement> elements;
    bool ended = false;
    while (auto l = nextLine()) {
        std::istringstream ls(*l);
        std::string key;
        ls >> key;
        if (key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "end_header") {
            ended = true;
            break;
        }
        if (key == "format") {
            std::string f, version;
            ls >> f >> version;
            if (f == "ascii")
                format = PlyFormat::Ascii;
            else if (f == "binary_little_endian")
                format = PlyFormat::BinaryLE;
            else if (f == "binary_big_endian")
                format = PlyFormat::BinaryBE;
            else
                fail(line, "unknown format '" + f + "'");
        } else if (key == "element") {
            PlyElement e;
            long long count = -1;
            ls >> e.name >> count;
            if (e.name.empty() || !ls || count < 0) fail(line, "bad element declaration");
            e.count = size_t(count);
            elements.push_back(e);
        } else if (key == "property") {
            if (elements.empty()) fail(line, "property before any element");
            PlyProperty p;
            std::string t;
            ls >> t;
            if (t == "list") {
                std::string ct, it;
                ls >> ct >> it >> p.name;
                p.isList = true;
                p.countType = ParseType(ct);
                p.type = ParseType(it);
                if (p.countType == PlyType::Invalid || p.countType == PlyType::Float32 ||
                    p.countType == PlyType::Float64)
                    fail(line, "bad list count type '" + ct + "'");
            } else {
                p.type = ParseType(t);
                ls >> p.name;
            }
            if (p.type == PlyType::Invalid || p.name.empty())
                fail(line, "bad property declaration '" + *l + "'");
            elements.back().props.push_back(p);
        } else {
            fail(line, "unknown header keyword '" + key + "'");
        }
    }
    if (!ended) fail(line, "missing 'end_header'");
    if (!format) fail(line, "missing 'format' line");

    // Element data
    PlyDataReader reader(filename, data, std::min(pos, data.size()), *format, line);
    TriQuadMesh mesh;
    double nVertices = 0, nFaces = 0;  // from the header (indices are checked against it)
    for (const PlyElement& e : elements) {
        if (e.name == "vertex") nVertices = double(e.count);
        if (e.name == "face" && !e.props.empty()) nFaces = double(e.count);
    }
    if (beforeData) beforeData(nVertices, nFaces);
    // Faces as four vertex indices (the last -1 for a triangle): no allocation per face
    std::vector<std::array<int, 4>> faces;
    std::vector<int> faceIndices;
    bool haveVertices = false;
    for (const PlyElement& e : elements) {
        // An element without properties has no data, whatever its count says (a huge count
        // would otherwise loop without reading anything)
        if (e.props.empty()) {
            if (e.name == "vertex") fail(line, "vertex element lacks x, y or z");
            if (e.name == "face" && e.count > 0) fail(line, "face element lacks vertex_indices");
            continue;
        }
        if (e.name == "vertex") {
            haveVertices = true;
            std::vector<std::vector<Float>> values(e.props.size());
            for (size_t i = 0; i < e.count; ++i)
                for (size_t j = 0; j < e.props.size(); ++j) {
                    const PlyProperty& p = e.props[j];
                    if (p.isList) {
                        size_t n = reader.ReadCount(p.countType);
                        for (size_t k = 0; k < n; ++k) reader.Read(p.type);
                    } else {
                        values[j].push_back(Float(reader.Read(p.type)));
                    }
                }
            auto find = [&](std::initializer_list<const char*> names) -> int {
                for (const char* n : names)
                    for (size_t j = 0; j < e.props.size(); ++j)
                        if (!e.props[j].isList && e.props[j].name == n) return int(j);
                return -1;
            };
            int ix = find({"x"}), iy = find({"y"}), iz = find({"z"});
            if (ix < 0 || iy < 0 || iz < 0) reader.Fail("vertex element lacks x, y or z");
            int inx = find({"nx"}), iny = find({"ny"}), inz = find({"nz"});
            int iu = find({"u", "s", "texture_u", "texture_s"});
            int iv = find({"v", "t", "texture_v", "texture_t"});
            mesh.p.resize(e.count);
            for (size_t i = 0; i < e.count; ++i)
                mesh.p[i] = Point3f(values[ix][i], values[iy][i], values[iz][i]);
            if (inx >= 0 && iny >= 0 && inz >= 0) {
                mesh.n.resize(e.count);
                for (size_t i = 0; i < e.count; ++i)
                    mesh.n[i] = Normal3f(values[inx][i], values[iny][i], values[inz][i]);
            }
            if (iu >= 0 && iv >= 0) {
                mesh.uv.resize(e.count);
                for (size_t i = 0; i < e.count; ++i)
                    mesh.uv[i] = Point2f(values[iu][i], values[iv][i]);
            }
            for (size_t j = 0; j < e.props.size(); ++j) {
                int jj = int(j);
                if (e.props[j].isList || jj == ix || jj == iy || jj == iz || jj == inx ||
                    jj == iny || jj == inz || jj == iu || jj == iv)
                    continue;
                mesh.vertexAttributes[e.props[j].name] = std::move(values[j]);
            }
        } else if (e.name == "face") {
            faces.reserve(std::min<size_t>(e.count, data.size() / 4));
            for (size_t i = 0; i < e.count; ++i) {
                std::array<int, 4> face = {-1, -1, -1, -1};  // a triangle leaves the last -1
                bool haveIndices = false;
                for (const PlyProperty& p : e.props) {
                    if (p.isList) {
                        size_t n = reader.ReadCount(p.countType);
                        bool isIndices = p.name == "vertex_indices" || p.name == "vertex_index";
                        if (isIndices && n != 3 && n != 4)
                            reader.Fail("face " + std::to_string(i) + " has " + std::to_string(n) +
                                        " vertices; only triangles and quads are supported");
                        for (size_t k = 0; k < n; ++k) {
                            double v = reader.Read(p.type);
                            if (!isIndices) continue;
                            if (!(v >= 0 && v < nVertices &&
                                  v <= double(std::numeric_limits<int>::max())))
                                reader.Fail("face " + std::to_string(i) + ": vertex index " +
                                            std::to_string(int64_t(std::clamp(v, -9e18, 9e18))) +
                                            " out of range (" + std::to_string(int64_t(nVertices)) +
                                            " vertices)");
                            face[k] = int(v);
                        }
                        haveIndices = haveIndices || isIndices;
                    } else {
                        double v = reader.Read(p.type);
                        if (p.name != "face_indices") continue;
                        if (!(std::abs(v) <= double(std::numeric_limits<int>::max())))
                            reader.Fail("face " + std::to_string(i) + ": face index " +
                                        std::to_string(v) + " does not fit in 32 bits");
                        faceIndices.push_back(int(v));
                    }
                }
                if (!haveIndices) reader.Fail("face element lacks vertex_indices");
                faces.push_back(face);
            }
        } else {
            for (size_t i = 0; i < e.count; ++i)
                for (const PlyProperty& p : e.props) {
                    size_t n = p.isList ? reader.ReadCount(p.countType) : 1;
                    for (size_t k = 0; k < n; ++k) reader.Read(p.type);
                }
        }
    }
    if (!haveVertices) fail(0, "no vertex element");

    // Triangles, planar quads as triangle pairs, other quads as bilinear patches.
    for (size_t f = 0; f < faces.size(); ++f) {
        const std::array<int, 4>& v = faces[f];
        const bool triangle = v[3] < 0;
        int fi = faceIndices.size() == faces.size() ? faceIndices[f] : -1;
        if (triangle || IsPlanar(mesh.p[v[0]], mesh.p[v[1]], mesh.p[v[2]], mesh.p[v[3]])) {
            mesh.triIndices.insert(mesh.triIndices.end(), {v[0], v[1], v[2]});
            if (fi >= 0) mesh.triFaceIndices.push_back(fi);
            if (!triangle) {
                mesh.triIndices.insert(mesh.triIndices.end(), {v[0], v[2], v[3]});
                if (fi >= 0) mesh.triFaceIndices.push_back(fi);
            }
        } else {
            mesh.quadIndices.insert(mesh.quadIndices.end(), {v[0], v[1], v[3], v[2]});
            if (fi >= 0) mesh.quadFaceIndices.push_back(fi);
        }
    }
    return mesh;
}

}  // namespace kiln
