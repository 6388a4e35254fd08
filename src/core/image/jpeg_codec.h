// JPEG files read by kiln itself, through libjpeg (libjpeg-turbo in Debian), so that a scene with
// .jpg textures does not load OpenImageIO (about 125 MB of a process; image_codec.h).
// Baseline and progressive 8-bit JPEG, grey ("Y") or colour (converted to "R", "G", "B" by
// libjpeg); CMYK and YCCK files are refused, as pbrt-v4's reader (stb_image) refuses them.
// EXIF orientation is not applied (pbrt-v4 does not either). Corrupt data (which libjpeg would
// read on with a warning, filling grey) is an error.
#pragma once

#include <memory>
#include <string>

#include "core/image/image_codec.h"

namespace kiln {

// A reader for filename if it starts with the JPEG signature (FF D8 FF), nullptr otherwise.
// Throws std::runtime_error for a damaged header; Read decodes the pixels and throws for
// damaged data.
std::unique_ptr<ImageFileReader> OpenJpeg(const std::string& filename);

}  // namespace kiln
