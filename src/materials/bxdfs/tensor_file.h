// The RGL "tensor file" format of measured BRDFs (Dupuy and Jakob 2018; the `.bsdf` files of
// the RGL material database, read by pbrt-v4's `measured` material and Mitsuba's `measured`
// plugin). Little-endian:
//   12 bytes "tensor_file\0", 2 bytes version (1, 0), uint32 field count, then per field:
//   uint16 name length, the name, uint16 rank, uint8 dtype, uint64 offset of its data in the
//   file, rank x uint64 shape; the data are the shape's product of dtype values (row-major,
//   the last dimension fastest) at that offset.
// dtype: 1 uint8, 2 int8, 3 uint16, 4 int16, 5 uint32, 6 int32, 7 uint64, 8 int64, 9 float16,
// 10 float32, 11 float64.
//
// Parse checks everything it reads against the bytes it was given: a truncated header, an
// unknown version or dtype, a field whose data runs past the end, a repeated name all throw
// TensorFileError saying what is wrong; nothing is read outside the bytes.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace kiln {

struct TensorFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class TensorFile {
  public:
    enum class DType : uint8_t {
        UInt8 = 1,
        Int8,
        UInt16,
        Int16,
        UInt32,
        Int32,
        UInt64,
        Int64,
        Float16,
        Float32,
        Float64
    };
    static size_t DTypeSize(DType t);
    static const char* DTypeName(DType t);

    struct Field {
        DType dtype;
        std::vector<uint64_t> shape;
        size_t offset = 0;  // of its data in the file
        size_t bytes = 0;   // of its data
    };

    // The file's fields; throws TensorFileError (see above).
    static TensorFile Parse(std::string bytes);
    // Reads and parses `filename` (a regular file; gzip-compressed files are decompressed);
    // throws TensorFileError if it cannot be read or parsed.
    static TensorFile Read(const std::string& filename);

    // The file's size in bytes.
    size_t Size() const { return bytes.size(); }
    // nullptr if there is no such field.
    const Field* Find(const std::string& name) const;
    const std::map<std::string, Field>& Fields() const { return fields; }
    // The field's values (its dtype must be float32, else TensorFileError).
    std::vector<float> Floats(const std::string& name) const;
    // The field's raw bytes.
    std::string_view Bytes(const std::string& name) const;

    // A file with these fields (what Parse reads back); for tests and generators.
    struct NamedField {
        std::string name;
        DType dtype;
        std::vector<uint64_t> shape;
        std::string data;  // little-endian values, the shape's product of them
    };
    static std::string Encode(const std::vector<NamedField>& fields);
    static NamedField FloatField(std::string name, std::vector<uint64_t> shape,
                                 const std::vector<float>& values);

  private:
    std::string bytes;
    std::map<std::string, Field> fields;
};

}  // namespace kiln
