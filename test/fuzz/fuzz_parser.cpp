// libFuzzer target: the tokenizer, the parser and the scene builder on arbitrary text. Every
// input must end in a scene description or a SceneError (file:line:column), never a crash, an
// uncaught exception, a hang or a sanitizer report.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/parser/parser.h"
#include "render/scene_builder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    kiln::Diagnostics diag(nullptr);
    try {
        kiln::SceneBuilder builder(diag);
        kiln::ParseString(builder, text, diag, "fuzz.pbrt", "/nonexistent-kiln-fuzz");
    } catch (const kiln::SceneError&) {
    }
    return 0;
}
