// Checkpoints (kiln --checkpoint SECONDS): the film's state after a whole number of samples per
// pixel, with what identifies the render it belongs to (a hash of every file the scene read, the
// options that change pixels, frame, seed, spp, pixel bounds) and a checksum, so that a render
// killed at any moment and started again with the same command resumes and ends bit-identical to an
// uninterrupted one (render/renderer.h, startSample). Written atomically (base/atomic_file.h: a new
// temporary file beside FILE, renamed to FILE; a kill leaves the previous checkpoint whole). Read
// only from a regular file of at most the film's state and a header, whose checksum matches and
// whose sums are all finite; anything else is ignored with a reason.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "base/vecmath.h"

namespace kiln {

class RGBFilm;

struct CheckpointIdentity {
    std::string scene;    // HashInputFiles of every file the scene read (render/scene_inputs.h)
    std::string options;  // RenderOptionsKey (render/render_options.h)
    std::string frame;    // "" for a still
    int seed = 0, spp = 0;
    Bounds2i pixelBounds;
};

// The checkpoint file of an output image: OUTPUT.checkpoint.
std::string CheckpointFile(const std::string& output);

// Writes the film's state after `completed` samples per pixel; throws std::runtime_error.
void WriteCheckpoint(const std::string& file, const CheckpointIdentity& id, int completed,
                     const RGBFilm& film);

// Restores a checkpoint of this render into film and returns its samples per pixel; 0 when
// there is none, or (with the reason in *why) when the file is of another render or damaged.
int ReadCheckpoint(const std::string& file, const CheckpointIdentity& id, RGBFilm& film,
                   std::string* why);

// The line that ends a checkpoint: "checksum " and 16 hexadecimal digits of a 64-bit hash of
// everything before it (`contents`), so that a damaged file is not resumed.
std::string CheckpointChecksumLine(std::string_view contents);
inline constexpr size_t kCheckpointChecksumLineBytes = 26;

// What ReadCheckpoint does with the file's bytes (named `file` in the reasons): also the
// fuzzing target's entry (test/fuzz/fuzz_checkpoint.cpp).
int RestoreCheckpoint(std::string bytes, const std::string& file, const CheckpointIdentity& id,
                      RGBFilm& film, std::string* why);

// Removes the checkpoint (after the output is written) if it is a regular file, and the
// temporaries of checkpoint writes that a kill interrupted.
void RemoveCheckpoint(const std::string& file);

}  // namespace kiln
