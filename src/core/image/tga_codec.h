// Truevision TGA files read by kiln itself (as the PNG and PFM codecs: a scene whose textures
// are .tga files, as in every public pbrt-v4 conversion of the Bitterli scenes, then never
// loads OpenImageIO, which costs a process about 125 MB). The format as the Truevision TGA
// File Format Specification 2.0 (1989) defines it: image types 1, 2, 3 (colour-mapped,
// true-colour, grey) and their run-length-encoded forms 9, 10, 11; 8-bit grey (16 with
// alpha), 15/16-bit (5-5-5), 24-bit and 32-bit (with alpha) pixels, colour maps of those
// sizes; rows bottom to top unless the descriptor's bit 5 says top to bottom, right to left
// when its bit 4 says so. Samples are 8-bit: "Y", "Y", "A", "R", "G", "B" or "R", "G", "B", "A";
// 5-bit values are expanded as v * 255 / 31 rounded down, as stb_image (pbrt-v4's reader) does.
#pragma once

#include <memory>
#include <string>

#include "core/image/image_codec.h"

namespace kiln {

// A reader for filename if its extension is .tga (any case), nullptr otherwise (TGA files have
// no signature). Throws std::runtime_error for a file that is damaged or that the format
// does not allow (checked as far as the header goes: the pixel data must fit the file, or
// for run-length data could); Read decodes the pixels and throws for damaged run-length data
// or colour-map indices.
std::unique_ptr<ImageFileReader> OpenTga(const std::string& filename);

}  // namespace kiln
