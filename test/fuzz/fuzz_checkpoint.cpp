// libFuzzer target: kiln's checkpoint reader (app/checkpoint.h RestoreCheckpoint, what
// ReadCheckpoint does with a file's bytes) on a film with AOV and Stokes layers. The first
// byte chooses what the rest is: 0 the whole file; 1 edits (2-byte offset, byte) to a valid
// checkpoint of this render, whose checksum then fails unless the edits miss; 2 the same edits
// with the checksum recomputed, so that the film's own checks (layout, finite sums, counters)
// are reached; 3 a valid checkpoint cut at a 2-byte offset. Every input must be restored or
// refused with a reason, and a refused one must leave the film as it was.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "../film/film_test_util.h"
#include "app/checkpoint.h"
#include "base/object_arena.h"
#include "core/film/film.h"
#include "core/film/filter.h"
#include "core/parser/diagnostics.h"
#include "core/parser/parameter_dictionary.h"

namespace {

using namespace kiln;

struct Fixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    BoxFilter box;
    Filter filter{&box};
    RGBFilm* film;
    CheckpointIdentity id{"0123456789abcdef", "options", "", 7, 64, Bounds2i{{0, 0}, {6, 4}}};
    std::string valid;  // a checkpoint of this render after 8 spp
    std::string blank;  // the film's state before anything is restored

    Fixture() {
        ParameterDictionary dict(
            {Param("integer", "xresolution", {}, {6}), Param("integer", "yresolution", {}, {4}),
             Param("bool", "stokes", {}, {}, {}, {1})},
            nullptr);
        film = RGBFilm::Create("gbuffer", dict, 1, filter, &RGBColorSpace::sRGB(), FileLoc(), arena,
                               diag);
        blank = film->SaveState();
        SampledWavelengths lambda = film->SampleWavelengths(0.5f);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 6; ++x)
                film->AddSample({x, y}, SampledSpectrum(0.1f * float(x + y)), lambda, nullptr, 1);
        std::string file = "/tmp/kiln_fuzz_checkpoint_seed";
        WriteCheckpoint(file, id, 8, *film);
        std::FILE* f = std::fopen(file.c_str(), "rb");
        char buf[4096];
        size_t n;
        while ((n = std::fread(buf, 1, sizeof(buf), f)) > 0) valid.append(buf, n);
        std::fclose(f);
        std::remove(file.c_str());
        film->Clear();
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static Fixture fx;
    if (size == 0) return 0;
    std::string bytes;
    const uint8_t mode = data[0] % 4;
    const uint8_t* rest = data + 1;
    size_t n = size - 1;
    if (mode == 0) {
        bytes.assign(reinterpret_cast<const char*>(rest), n);
    } else if (mode == 3) {
        size_t cut = n >= 2 ? (size_t(rest[0]) | size_t(rest[1]) << 8) : 0;
        bytes = fx.valid.substr(0, cut % (fx.valid.size() + 1));
    } else {
        bytes = fx.valid;
        for (size_t i = 0; i + 3 <= n; i += 3) {
            size_t at = (size_t(rest[i]) | size_t(rest[i + 1]) << 8) % bytes.size();
            bytes[at] = char(rest[i + 2]);
        }
        if (mode == 2) {  // the checksum line that ends the file, recomputed
            bytes.resize(bytes.size() - kCheckpointChecksumLineBytes);
            bytes += CheckpointChecksumLine(bytes);
        }
    }
    std::string why;
    int completed = RestoreCheckpoint(bytes, "fuzz.checkpoint", fx.id, *fx.film, &why);
    if (completed == 0) {
        if (why.empty() || fx.film->SaveState() != fx.blank) __builtin_trap();
    } else if (completed < 1 || completed >= fx.id.spp) {
        __builtin_trap();
    }
    fx.film->Clear();
    return 0;
}
