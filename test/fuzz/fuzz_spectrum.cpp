// libFuzzer target: spectrum files ("lambda value" pairs, comments, commas) on arbitrary text.
// Every input must end in an error or a spectrum whose values are finite everywhere.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "spectral/spectrum.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    std::string error;
    auto s = kiln::PiecewiseLinearSpectrum::Parse(text, "fuzz.spd", &error);
    if (!s) return 0;
    for (kiln::Float lambda : {0.f, 360.f, 555.5f, 830.f, 1e6f})
        if (!std::isfinite((*s)(lambda))) __builtin_trap();
    if (!std::isfinite(s->MaxValue())) __builtin_trap();
    return 0;
}
