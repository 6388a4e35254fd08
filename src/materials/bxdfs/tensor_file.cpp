#include "materials/bxdfs/tensor_file.h"

#include <bit>
#include <cstring>

#include "base/file_reading.h"

namespace kiln {

static_assert(std::endian::native == std::endian::little,
              "tensor files are little-endian; kiln reads them on little-endian machines only");

size_t TensorFile::DTypeSize(DType t) {
    switch (t) {
        case DType::UInt8:
        case DType::Int8:
            return 1;
        case DType::UInt16:
        case DType::Int16:
        case DType::Float16:
            return 2;
        case DType::UInt32:
        case DType::Int32:
        case DType::Float32:
            return 4;
        case DType::UInt64:
        case DType::Int64:
        case DType::Float64:
            return 8;
    }
    return 0;
}

const char* TensorFile::DTypeName(DType t) {
    static constexpr const char* kNames[] = {"uint8",   "int8",    "uint16", "int16",
                                             "uint32",  "int32",   "uint64", "int64",
                                             "float16", "float32", "float64"};
    return unsigned(t) >= 1 && unsigned(t) <= 11 ? kNames[unsigned(t) - 1] : "unknown";
}

namespace {

// Reads little-endian values from a byte string, throwing when one would pass its end
class Reader {
  public:
    explicit Reader(const std::string& bytes) : bytes(bytes) {}
    template <typename T>
    T Get(const char* what) {
        if (bytes.size() - pos < sizeof(T))
            throw TensorFileError(std::string("truncated: the file ends inside the ") + what +
                                  " (at byte " + std::to_string(pos) + ")");
        T v;
        std::memcpy(&v, bytes.data() + pos, sizeof(T));
        pos += sizeof(T);
        return v;
    }
    std::string GetString(size_t n, const char* what) {
        if (bytes.size() - pos < n)
            throw TensorFileError(std::string("truncated: the file ends inside the ") + what +
                                  " (at byte " + std::to_string(pos) + ")");
        std::string s = bytes.substr(pos, n);
        pos += n;
        return s;
    }

  private:
    const std::string& bytes;
    size_t pos = 0;
};

}  // namespace

TensorFile TensorFile::Parse(std::string data) {
    TensorFile file;
    file.bytes = std::move(data);
    const std::string& bytes = file.bytes;
    Reader in(bytes);
    if (in.GetString(12, "header") != std::string("tensor_file\0", 12))
        throw TensorFileError("not a tensor file (it does not start with \"tensor_file\")");
    const uint8_t major = in.Get<uint8_t>("version"), minor = in.Get<uint8_t>("version");
    if (major != 1 || minor != 0)
        throw TensorFileError("unknown tensor file version " + std::to_string(major) + "." +
                              std::to_string(minor) + " (kiln reads 1.0)");
    const uint32_t count = in.Get<uint32_t>("field count");
    // Every field's header takes at least 13 bytes
    if (count > bytes.size() / 13)
        throw TensorFileError("field count " + std::to_string(count) +
                              " is more than the file's size allows");
    for (uint32_t i = 0; i < count; ++i) {
        const std::string what = "header of field " + std::to_string(i);
        const uint16_t nameLength = in.Get<uint16_t>(what.c_str());
        std::string name = in.GetString(nameLength, what.c_str());
        const uint16_t rank = in.Get<uint16_t>(what.c_str());
        const uint8_t dtype = in.Get<uint8_t>(what.c_str());
        const uint64_t offset = in.Get<uint64_t>(what.c_str());
        if (dtype < 1 || dtype > 11)
            throw TensorFileError("field \"" + name + "\" has unknown dtype " +
                                  std::to_string(dtype));
        Field f;
        f.dtype = DType(dtype);
        uint64_t total = DTypeSize(f.dtype);
        for (uint16_t j = 0; j < rank; ++j) {
            const uint64_t n = in.Get<uint64_t>(what.c_str());
            f.shape.push_back(n);
            if (n != 0 && total > bytes.size() / n)
                throw TensorFileError("field \"" + name + "\" is larger than the file");
            total *= n;
        }
        if (offset > bytes.size() || total > bytes.size() - offset)
            throw TensorFileError("the data of field \"" + name + "\" (" + std::to_string(total) +
                                  " bytes at offset " + std::to_string(offset) +
                                  ") run past the end of the file (" +
                                  std::to_string(bytes.size()) + " bytes)");
        f.offset = size_t(offset);
        f.bytes = size_t(total);
        if (!file.fields.emplace(name, std::move(f)).second)
            throw TensorFileError("field \"" + name + "\" appears twice");
    }
    return file;
}

TensorFile TensorFile::Read(const std::string& filename) {
    std::string bytes, error;
    if (!ReadFileBytes(filename, &bytes, &error)) throw TensorFileError(error);
    return Parse(std::move(bytes));
}

const TensorFile::Field* TensorFile::Find(const std::string& name) const {
    auto it = fields.find(name);
    return it == fields.end() ? nullptr : &it->second;
}

std::string_view TensorFile::Bytes(const std::string& name) const {
    const Field* f = Find(name);
    if (!f) throw TensorFileError("missing field \"" + name + "\"");
    return std::string_view(bytes).substr(f->offset, f->bytes);
}

std::vector<float> TensorFile::Floats(const std::string& name) const {
    const Field* f = Find(name);
    if (!f) throw TensorFileError("missing field \"" + name + "\"");
    if (f->dtype != DType::Float32)
        throw TensorFileError("field \"" + name + "\" must be float32, not " + DTypeName(f->dtype));
    std::vector<float> v(f->bytes / sizeof(float));
    if (!v.empty()) std::memcpy(v.data(), bytes.data() + f->offset, v.size() * sizeof(float));
    return v;
}

std::string TensorFile::Encode(const std::vector<NamedField>& fields) {
    auto put = [](std::string& s, const auto& v) {
        s.append(reinterpret_cast<const char*>(&v), sizeof(v));
    };
    std::string header("tensor_file\0", 12);
    header += char(1), header += char(0);
    put(header, uint32_t(fields.size()));
    size_t headerSize = header.size();
    for (const NamedField& f : fields)
        headerSize += 2 + f.name.size() + 2 + 1 + 8 + 8 * f.shape.size();
    uint64_t offset = headerSize;
    std::string data;
    for (const NamedField& f : fields) {
        put(header, uint16_t(f.name.size()));
        header += f.name;
        put(header, uint16_t(f.shape.size()));
        put(header, uint8_t(f.dtype));
        put(header, offset);
        for (uint64_t n : f.shape) put(header, n);
        data += f.data;
        offset += f.data.size();
    }
    return header + data;
}

TensorFile::NamedField TensorFile::FloatField(std::string name, std::vector<uint64_t> shape,
                                              const std::vector<float>& values) {
    return {
        std::move(name), DType::Float32, std::move(shape),
        std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float))};
}

}  // namespace kiln
