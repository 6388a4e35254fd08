// PFM (portable float map) files read and written by kiln itself: "PF" (three channels R, G, B)
// or "Pf" (one channel Y), width and height, a scale whose sign gives the byte order (negative:
// little-endian), then 32-bit floats, rows bottom to top (the format's definition, as Paul
// Debevec's HDRShop and pbrt-v4's Image::ReadPFM / WritePFM use it). The scale's magnitude
// multiplies the samples on reading (as pbrt-v4) and is written as 1.
#pragma once

#include <memory>
#include <string>

#include "core/image/image_codec.h"

namespace kiln {

// A reader for filename if it starts with "PF" or "Pf" and a line break; nullptr otherwise.
// Throws std::runtime_error for a damaged header or a file whose size does not match it.
std::unique_ptr<ImageFileReader> OpenPfm(const std::string& filename);

// One channel, or three named R, G, B; float samples
bool PfmWriterHandles(const ImageFileSpec& spec);

// The bytes of a little-endian PFM file of data (interleaved floats, rows top to bottom).
std::string EncodePfm(const ImageFileSpec& spec, const void* data);

}  // namespace kiln
