// Writes test images through OpenImageIO (formats and sample types kiln's own writers do not
// make: 16-bit PNGs, grey EXRs, ...), for the texture and temperature-field tests.
#pragma once

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace kiln::test {

// px: w x h pixels of nc channels, interleaved, rows top to bottom, of the given type.
template <typename T>
void WriteWithOIIO(const std::string& path, const std::vector<T>& px, int w, int h, int nc,
                   OIIO::TypeDesc type) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path;
    OIIO::ImageSpec spec(w, h, nc, type);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, px.data())) << out->geterror();
    out->close();
}

}  // namespace kiln::test
