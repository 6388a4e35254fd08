// Helpers for the film tests: parameters and a film made from them.
#pragma once

#include <string>
#include <vector>

#include "core/film/film.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {

inline ParsedParameter Param(std::string type, std::string name, std::vector<Float> floats = {},
                             std::vector<int> ints = {}, std::vector<std::string> strings = {},
                             std::vector<uint8_t> bools = {}) {
    ParsedParameter p;
    p.type = std::move(type);
    p.name = std::move(name);
    p.floats = std::move(floats);
    p.ints = std::move(ints);
    p.strings = std::move(strings);
    p.bools = std::move(bools);
    return p;
}

struct FilmFixture {
    ObjectArena arena;
    Diagnostics diag{nullptr};
    BoxFilter box;
    Filter filter{&box};
    RGBFilm* Make(ParsedParameterVector params, std::string type = "rgb", Float exposureTime = 1,
                  const RGBColorSpace* colorSpace = &RGBColorSpace::sRGB()) {
        ParameterDictionary dict(std::move(params), nullptr);
        return RGBFilm::Create(type, dict, exposureTime, filter, colorSpace, FileLoc(), arena,
                               diag);
    }
};

inline ParsedParameterVector SmallRes() {
    return {Param("integer", "xresolution", {}, {8}), Param("integer", "yresolution", {}, {4})};
}

}  // namespace kiln
