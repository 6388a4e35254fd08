#include "media/nanovdb_file.h"

#include <zlib.h>

#include <cstring>
#include <fstream>
#include <stdexcept>

#include "base/file_reading.h"

namespace kiln {

namespace {

constexpr uint64_t kHeaderBytes = 16, kMetadataBytes = 176;
// zlib's deflate compresses at most about 1032:1
constexpr uint64_t kMaxZipRatio = 1100;

const char* CodecName(uint16_t codec) {
    switch (codec) {
        case 0:
            return "NONE";
        case 1:
            return "ZIP";
        case 2:
            return "BLOSC";
        default:
            return "unknown";
    }
}

template <typename T>
T Get(const char* bytes, size_t offset) {
    T v;
    std::memcpy(&v, bytes + offset, sizeof(T));
    return v;
}

// "NanoVDB0", or "NanoVDB2", which later NanoVDB versions may write and read
bool IsFileMagic(uint64_t magic) {
    return magic == kNanoVDBMagic || magic == kNanoVDBMagic + (uint64_t(2) << 56);
}

}  // namespace

bool NanoVDBFile::HasMagic(const std::string& firstBytes) {
    return firstBytes.size() >= 8 && IsFileMagic(Get<uint64_t>(firstBytes.data(), 0));
}

NanoVDBFile::NanoVDBFile(const std::string& filename) : filename(filename) {
    std::string why;
    if (!IsRegularFile(filename, &why)) throw std::runtime_error("cannot read it: " + why);
    std::ifstream in(filename, std::ios::binary | std::ios::ate);
    if (!in) throw std::runtime_error("cannot open it");
    fileBytes = uint64_t(in.tellg());
    in.seekg(0);
    uint64_t at = 0;
    auto read = [&](char* to, uint64_t n, const char* what) {
        if (n > fileBytes - at)
            throw std::runtime_error(std::string("the file ends inside ") + what + " at byte " +
                                     std::to_string(at) + " (it is truncated or damaged)");
        in.seekg(std::streamoff(at));
        if (!in.read(to, std::streamsize(n))) throw std::runtime_error("cannot read it");
        at += n;
    };
    if (fileBytes == 0) throw std::runtime_error("the file is empty");
    // Segments until the end of the file
    while (at < fileBytes) {
        char header[kHeaderBytes];
        read(header, kHeaderBytes, "a segment header");
        uint64_t magic = Get<uint64_t>(header, 0);
        if (!IsFileMagic(magic))
            throw std::runtime_error(
                at == kHeaderBytes ? "not a NanoVDB file (no \"NanoVDB0\" magic number)"
                                   : "the segment at byte " + std::to_string(at - kHeaderBytes) +
                                         " lacks NanoVDB's magic number (the file is damaged)");
        uint32_t version = Get<uint32_t>(header, 8);
        if ((version >> 21) != 32)
            throw std::runtime_error("NanoVDB version " + std::to_string(version >> 21) + "." +
                                     std::to_string((version >> 10) & 2047) +
                                     "; kiln reads version 32 files (pbrt-v4's NanoVDB, 32.3)");
        uint16_t count = Get<uint16_t>(header, 12), codec = Get<uint16_t>(header, 14);
        size_t first = grids.size();
        for (uint16_t i = 0; i < count; ++i) {
            char m[kMetadataBytes];
            read(m, kMetadataBytes, "a grid's metadata");
            Entry e;
            e.gridBytes = Get<uint64_t>(m, 0);
            e.fileBytes = Get<uint64_t>(m, 8);
            e.gridType = Get<uint32_t>(m, 32);
            e.codec = NanoVDBCodec(codec);
            uint32_t nameBytes = Get<uint32_t>(m, 136);
            if (nameBytes > fileBytes - at)
                throw std::runtime_error("a grid name of " + std::to_string(nameBytes) +
                                         " bytes passes the end of the file (it is damaged)");
            std::string name(nameBytes, '\0');
            read(name.data(), nameBytes, "a grid name");
            e.name = name.substr(0, name.find('\0'));
            grids.push_back(std::move(e));
        }
        // The grids' bytes follow, in order
        for (size_t i = first; i < grids.size(); ++i) {
            Entry& e = grids[i];
            if (e.fileBytes > fileBytes - at)
                throw std::runtime_error("the grid \"" + e.name + "\" of " +
                                         std::to_string(e.fileBytes) + " bytes at byte " +
                                         std::to_string(at) +
                                         " passes the end of the file (it is truncated)");
            e.fileOffset = at;
            at += e.fileBytes;
        }
    }
}

std::optional<NanoVDBFloatGrid> NanoVDBFile::ReadFloatGrid(const std::string& name,
                                                           uint64_t maxBytes) const {
    const Entry* e = nullptr;
    for (const Entry& g : grids)
        if (g.name == name) {
            e = &g;
            break;
        }
    if (!e) return std::nullopt;
    const std::string grid = "the grid \"" + name + "\"";
    if (e->gridType != uint32_t(NanoVDBGridType::Float))
        throw std::runtime_error(grid + " is not a float grid (NanoVDB grid type " +
                                 std::to_string(e->gridType) + "); kiln reads float grids");
    if (e->codec != NanoVDBCodec::None && e->codec != NanoVDBCodec::Zip)
        throw std::runtime_error(grid + " is compressed with codec " +
                                 CodecName(uint16_t(e->codec)) +
                                 "; kiln reads NanoVDB codecs NONE and ZIP (save the volume "
                                 "uncompressed or with ZIP)");
    if (e->gridBytes > maxBytes)
        throw std::runtime_error(grid + " states " + std::to_string(e->gridBytes) +
                                 " bytes, more than the " + std::to_string(maxBytes) +
                                 " memory allows (the file is damaged or too large)");
    std::ifstream in(filename, std::ios::binary);
    in.seekg(std::streamoff(e->fileOffset));
    auto damaged = [&](const std::string& why) {
        return std::runtime_error(grid + ": " + why + " (the file is damaged)");
    };
    std::vector<uint8_t> bytes;
    if (e->codec == NanoVDBCodec::None) {
        if (e->fileBytes != e->gridBytes)
            throw damaged("it takes " + std::to_string(e->fileBytes) +
                          " bytes of the file but states " + std::to_string(e->gridBytes));
        bytes.resize(e->gridBytes);
        if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size())))
            throw std::runtime_error("cannot read it");
    } else {
        uint64_t zipped = 0;
        if (e->fileBytes < 8 || !in.read(reinterpret_cast<char*>(&zipped), 8))
            throw damaged("its compressed length is missing");
        if (zipped > e->fileBytes - 8)
            throw damaged("its compressed length " + std::to_string(zipped) + " passes its end");
        if (e->gridBytes / kMaxZipRatio > zipped + 64)
            throw damaged("ZIP cannot expand " + std::to_string(zipped) + " bytes to " +
                          std::to_string(e->gridBytes));
        std::vector<uint8_t> z(zipped);
        if (!in.read(reinterpret_cast<char*>(z.data()), std::streamsize(zipped)))
            throw std::runtime_error("cannot read it");
        bytes.resize(e->gridBytes);
        uLongf n = uLongf(bytes.size());
        int status = uncompress(bytes.data(), &n, z.data(), uLong(zipped));
        if (status != Z_OK || n != bytes.size())
            throw damaged("its ZIP data do not decompress to its " + std::to_string(e->gridBytes) +
                          " bytes");
    }
    return NanoVDBFloatGrid(std::move(bytes));
}

}  // namespace kiln
