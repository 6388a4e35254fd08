// What the kiln command's tests share.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/image/image.h"

namespace kiln::testing {

// Every pixel value (all channels, row by row) of an image file, for bit-exact comparisons.
inline std::vector<float> Pixels(const std::string& file) {
    Image im = Image::Read(file);
    std::vector<float> v;
    for (int y = 0; y < im.Resolution().y; ++y)
        for (int x = 0; x < im.Resolution().x; ++x)
            for (int c = 0; c < im.NChannels(); ++c) v.push_back(im.GetChannel({x, y}, c));
    return v;
}

// A word for a test's shell commands: single-quoted, single quotes escaped
inline std::string ShellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// The whole content of a file ("" if it cannot be read)
inline std::string ReadAll(const std::string& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace kiln::testing
