// libFuzzer target: a volume file of arbitrary bytes read as a medium reads it
// (media/vdb_file.h ReadVDBVolume) with a 256 MB budget. Every input must be a volume or a
// SceneError naming the file: never std::bad_alloc, a crash or a hang of kiln.
// OpenVDB files go through the OpenVDB plugin, which reads in a child process under a memory
// limit; OpenVDB itself is not instrumented, so this fuzzes kiln's side of the read (the
// child, the pipe, the checks of what comes back), as hostile files exercise it.
// Inputs that begin with NanoVDB's magic number go to kiln's own NanoVDB reader
// (media/nanovdb_volume.h), in this process. A NanoVDB node of the upper level takes 270400
// bytes, more than the 64 KB inputs the fuzzer makes (scripts/sanitize.sh), so such an input
// is padded with zeros to the length its first segment's metadata state (at most 16 MB): the
// seed corpus/vdb/density-uppers-last.nvdb is a grid laid out with its upper node last, cut
// where that node's zero table entries begin.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "base/memory_budget.h"
#include "core/parser/diagnostics.h"
#include "media/vdb_file.h"

namespace {

std::string PaddedNanoVDB(const uint8_t* data, size_t size) {
    std::string s(reinterpret_cast<const char*>(data), size);
    if (size < 16 || std::memcmp(data, "NanoVDB", 7) != 0) return s;
    constexpr uint64_t kMax = 16 << 20;
    uint16_t count;
    std::memcpy(&count, data + 12, 2);
    uint64_t at = 16, total = 16;
    for (uint16_t i = 0; i < count; ++i) {
        if (at + 176 > size) return s;
        uint64_t fileBytes;
        uint32_t nameBytes;
        std::memcpy(&fileBytes, data + at + 8, 8);
        std::memcpy(&nameBytes, data + at + 136, 4);
        if (fileBytes > kMax || nameBytes > size) return s;
        total += 176 + uint64_t(nameBytes) + fileBytes;
        at += 176 + uint64_t(nameBytes);
        if (total > kMax) return s;
    }
    if (total > size) s.resize(total, '\0');
    return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string file = "/tmp/kiln_fuzz_" + std::to_string(getpid()) + ".vdb";
    std::string contents = PaddedNanoVDB(data, size);
    if (std::FILE* f = std::fopen(file.c_str(), "wb")) {
        std::fwrite(contents.data(), 1, contents.size(), f);
        std::fclose(f);
    } else {
        return 0;
    }
    kiln::MemoryBudget budget(256e6);
    try {
        kiln::VDBVolume v = kiln::ReadVDBVolume(file, "density", "temperature", kiln::FileLoc(),
                                                size_t(1) << 22, &budget);
        if (v.density.Empty()) __builtin_trap();
    } catch (const kiln::SceneError& e) {
        if (std::string(e.what()).find(file) == std::string::npos) __builtin_trap();
    }
    return 0;
}
