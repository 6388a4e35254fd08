// libFuzzer target: a .vdb file of arbitrary bytes read as a medium reads it
// (media/vdb_file.h ReadVDBVolume, through the OpenVDB plugin, which reads in a child process
// under a memory limit) with a 256 MB budget. Every input must be a volume or a SceneError
// naming the file: never std::bad_alloc, a crash or a hang of kiln. OpenVDB itself is not
// instrumented, so this fuzzes kiln's side of the read (the child, the pipe, the checks of
// what comes back), as hostile files exercise it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "base/memory_budget.h"
#include "core/parser/diagnostics.h"
#include "media/vdb_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string file = "/tmp/kiln_fuzz_" + std::to_string(getpid()) + ".vdb";
    if (std::FILE* f = std::fopen(file.c_str(), "wb")) {
        std::fwrite(data, 1, size, f);
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
