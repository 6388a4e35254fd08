// libFuzzer target: what kiln merge reads from a part, on arbitrary bytes written as an .exr
// file: kiln's EXR codec (header, channels, data window, attributes, the kiln:checksum of the
// samples), the metadata merge checks (kiln:scene, kiln:options, seed, frame, spp, exposure,
// pixel bounds inside the full resolution) and the merges themselves, tiles (the part alone)
// and samples (the part twice). Every input must be merged or refused with an exception
// naming what is wrong, never crash, hang or allocate what a header merely claims.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/merge.h"
#include "base/memory_budget.h"
#include "core/image/image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string file = "/tmp/kiln_fuzz_part_" + std::to_string(getpid()) + ".exr";
    if (std::FILE* f = std::fopen(file.c_str(), "wb")) {
        std::fwrite(data, 1, size, f);
        std::fclose(f);
    } else {
        return 0;
    }
    try {
        kiln::RenderPart part;
        part.file = file;
        // kiln merge reads parts with the memory the machine has; here 64 MB, so that a
        // header that claims gigabytes is refused as it would be under --memory-limit
        kiln::MemoryBudget budget(64e6);
        part.image = kiln::Image::Read(file, &part.metadata, std::nullopt, &budget);
        kiln::ImageMetadata merged;
        try {
            kiln::MergeTiles({part}, &merged);
        } catch (const std::runtime_error&) {
        }
        kiln::MergeSamples({part, part}, &merged);
    } catch (const std::runtime_error&) {
    }
    return 0;
}
