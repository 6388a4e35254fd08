// The container of a NanoVDB file (.nvdb, as NanoVDB 32.3's io::writeGrids writes it, the
// version pbrt-v4 bundles): one or more segments, each a 16-byte header (magic "NanoVDB0",
// version, grid count, codec), then per grid 176 bytes of metadata and its NUL-terminated
// name, then each grid's bytes: raw (codec NONE) or an 8-byte length and a zlib stream (ZIP).
// Every count and size is checked against the file's length; errors are
// std::runtime_error("reason").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "media/nanovdb_grid.h"

namespace kiln {

// NanoVDB's io::Codec
enum class NanoVDBCodec : uint16_t { None = 0, Zip = 1, Blosc = 2 };

// NanoVDBFile Definition
class NanoVDBFile {
  public:
    struct Entry {
        std::string name;
        NanoVDBCodec codec;
        uint32_t gridType;
        uint64_t gridBytes;              // in memory
        uint64_t fileOffset, fileBytes;  // in the file
    };

    // Reads the file's segment headers and grid metadata
    explicit NanoVDBFile(const std::string& filename);

    // Every grid, in file order
    const std::vector<Entry>& Grids() const { return grids; }

    // The first grid called `name` (as pbrt-v4's nanovdb::io::readGrid finds it), nullopt if
    // there is none. A grid that would take more than maxBytes of memory is an error.
    std::optional<NanoVDBFloatGrid> ReadFloatGrid(const std::string& name, uint64_t maxBytes) const;

    // Whether bytes begin with a NanoVDB file's magic number ("NanoVDB0"; "NanoVDB2")
    static bool HasMagic(const std::string& firstBytes);

  private:
    std::string filename;
    uint64_t fileBytes = 0;
    std::vector<Entry> grids;
};

}  // namespace kiln
