// PNG files read and written with libpng, without OpenImageIO (loading it costs a process about
// 0.25 s of CPU and 117 MB): the PNGs scenes use as textures and renders write, as OpenImageIO
// 2.4 reads and writes them, so images are the same either way.
//
// Reading: grey and RGB files of any bit depth, palette files, interlaced or not, without
// transparency. Low bit depths and palettes are expanded to 8 bits and RGB; channels are "Y" or
// "R", "G", "B"; 16-bit samples are SampleType::U16. The colour space is "sRGB" for an sRGB
// chunk or none, else from a gAMA chunk ("linear" for gamma 1, else "GammaG" with G = 1/gAMA
// to two decimals), replaced by a tEXt "oiio:ColorSpace" if there is one; tEXt chunks become
// strings.
// Files with an alpha channel or a tRNS chunk are left to OpenImageIO, which kiln asks for the
// colours as stored, not multiplied by alpha, as pbrt-v4 reads them (OpenPng returns nullptr for
// them).
//
// Writing: 8-bit grey or RGB images (an alpha channel goes to the plugin, which writes the
// colours as given, not un-premultiplied), with the chunks OpenImageIO writes: sRGB with its gAMA
// and cHRM for sRGB data, gAMA 1/g for gamma g (1 for linear), oFFs 0 0, and a tEXt chunk for
// "oiio:ColorSpace" and for every string attribute.
#pragma once

#include <memory>
#include <string>

#include "core/image/image_codec.h"

namespace kiln {

// A reader for filename if it is a PNG kiln reads itself; nullptr if it is a PNG with
// transparency or not a PNG at all. Throws std::runtime_error for a damaged PNG.
std::unique_ptr<ImageFileReader> OpenPng(const std::string& filename);

// 8-bit samples, and one channel or three named R, G, B
bool PngWriterHandles(const ImageFileSpec& spec);

// The bytes of a PNG file of data (interleaved 8-bit samples, rows top to bottom), encoded in
// memory; throws std::runtime_error("reason") on failure.
std::string EncodePng(const ImageFileSpec& spec, const void* data);

}  // namespace kiln
