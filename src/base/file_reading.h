// Reading whole input files (scenes, includes, PLY meshes, spectra) with the checks hostile or
// mistaken input needs: only regular files (not directories, devices such as /dev/zero, or
// FIFOs, which would never end), a size bound, and transparent gzip decompression (detected by
// the gzip magic bytes, whatever the file is called), as pbrt-v4 reads .pbrt.gz and .ply.gz.
#pragma once

#include <cstdint>
#include <string>

namespace kiln {

// Whether `filename` names a regular file; otherwise false with a reason in *error.
bool IsRegularFile(const std::string& filename, std::string* error);

// The largest input read (after decompression) by default: half the machine's memory.
uint64_t DefaultMaxInputBytes();

// The file's bytes, decompressed if gzip-compressed. False with a reason in *error (not a
// regular file, larger than maxBytes, unreadable, corrupt gzip data); *contents is then
// unspecified.
bool ReadFileBytes(const std::string& filename, std::string* contents, std::string* error,
                   uint64_t maxBytes = DefaultMaxInputBytes());

// Decompresses gzip data (one or more members) into *out, at most maxBytes.
bool GunzipBytes(const std::string& in, std::string* out, std::string* error, uint64_t maxBytes);

}  // namespace kiln
