#include "base/file_reading.h"

#include <sys/stat.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>

#include "base/system_memory.h"

namespace kiln {

bool IsRegularFile(const std::string& filename, std::string* error) {
    struct stat st;
    if (stat(filename.c_str(), &st) != 0) {
        *error = std::strerror(errno);
        return false;
    }
    if (S_ISREG(st.st_mode)) return true;
    *error = S_ISDIR(st.st_mode)    ? "is a directory"
             : S_ISFIFO(st.st_mode) ? "is a FIFO, not a regular file"
                                    : "is a device or special file, not a regular file";
    return false;
}

uint64_t DefaultMaxInputBytes() {
    double memory = PhysicalMemoryBytes();
    return memory > 0 ? uint64_t(memory / 2) : uint64_t(1) << 34;
}

bool GunzipBytes(const std::string& in, std::string* out, std::string* error, uint64_t maxBytes) {
    z_stream z{};
    if (inflateInit2(&z, 15 + 32) != Z_OK) {  // 32: accept the gzip header
        *error = "cannot initialise zlib";
        return false;
    }
    std::unique_ptr<z_stream, int (*)(z_stream*)> guard(&z, inflateEnd);
    out->clear();
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
    size_t remaining = in.size();
    char buf[1 << 16];
    while (true) {
        // zlib counts input in 32-bit units: feed it in pieces
        if (z.avail_in == 0 && remaining > 0) {
            z.avail_in = uInt(std::min<size_t>(remaining, 1u << 30));
            remaining -= z.avail_in;
        }
        z.next_out = reinterpret_cast<Bytef*>(buf);
        z.avail_out = sizeof(buf);
        int r = inflate(&z, Z_NO_FLUSH);
        out->append(buf, sizeof(buf) - z.avail_out);
        if (out->size() > maxBytes) {
            *error = "decompresses to more than " + FormatBytes(double(maxBytes));
            return false;
        }
        if (r == Z_STREAM_END) {
            if (z.avail_in == 0 && remaining == 0) return true;
            // Concatenated gzip members, as gzip itself writes them
            if (inflateReset(&z) != Z_OK) break;
            continue;
        }
        if (r != Z_OK) {
            *error = std::string("corrupt gzip data") + (z.msg ? std::string(": ") + z.msg : "");
            return false;
        }
        if (z.avail_in == 0 && remaining == 0 && z.avail_out != 0) {
            *error = "truncated gzip data";
            return false;
        }
    }
    *error = "corrupt gzip data";
    return false;
}

namespace {

bool ReadFileBytesOrThrow(const std::string& filename, std::string* contents, std::string* error,
                          uint64_t maxBytes);

}  // namespace

bool ReadFileBytes(const std::string& filename, std::string* contents, std::string* error,
                   uint64_t maxBytes) {
    try {
        return ReadFileBytesOrThrow(filename, contents, error, maxBytes);
    } catch (const std::bad_alloc&) {  // e.g. a gzip bomb under a process memory cap
        size_t held = contents->size();
        contents->clear();
        contents->shrink_to_fit();
        *error =
            "out of memory after reading " + FormatBytes(double(held)) + " of it (decompressed)";
        return false;
    }
}

namespace {

bool ReadFileBytesOrThrow(const std::string& filename, std::string* contents, std::string* error,
                          uint64_t maxBytes) {
    if (!IsRegularFile(filename, error)) return false;
    std::FILE* f = std::fopen(filename.c_str(), "rb");
    if (!f) {
        *error = std::strerror(errno);
        return false;
    }
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> guard(f, std::fclose);
    contents->clear();
    char buf[1 << 16];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof(buf), f)) > 0) {
        contents->append(buf, n);
        if (contents->size() > maxBytes) {
            *error = "larger than " + FormatBytes(double(maxBytes));
            return false;
        }
    }
    if (std::ferror(f)) {
        *error = std::strerror(errno);
        return false;
    }
    if (contents->size() >= 2 && uint8_t((*contents)[0]) == 0x1f &&
        uint8_t((*contents)[1]) == 0x8b) {
        std::string raw;
        raw.swap(*contents);
        return GunzipBytes(raw, contents, error, maxBytes);
    }
    return true;
}

}  // namespace

}  // namespace kiln
