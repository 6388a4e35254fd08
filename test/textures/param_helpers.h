// Test helpers: building scene parameters without parsing a file.
#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "core/parser/parameter_dictionary.h"
#include "core/parser/parsed_parameter.h"

namespace kiln::test {

inline FileLoc TestLoc(int line = 1) {
    return FileLoc(std::make_shared<const std::string>("test.pbrt"), line, 1);
}

inline ParsedParameter Floats(const std::string& type, const std::string& name,
                              std::vector<Float> values) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.loc = TestLoc(2);
    p.floats = std::move(values);
    return p;
}
inline ParsedParameter Float1(const std::string& name, Float v) {
    return Floats("float", name, {v});
}
inline ParsedParameter Int1(const std::string& name, int v) {
    ParsedParameter p;
    p.type = "integer";
    p.name = name;
    p.loc = TestLoc(2);
    p.ints = {v};
    return p;
}
inline ParsedParameter Bool1(const std::string& name, bool v) {
    ParsedParameter p;
    p.type = "bool";
    p.name = name;
    p.loc = TestLoc(2);
    p.bools = {uint8_t(v)};
    return p;
}
inline ParsedParameter Strings(const std::string& type, const std::string& name,
                               std::vector<std::string> values) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.loc = TestLoc(3);
    p.strings = std::move(values);
    return p;
}
inline ParsedParameter String1(const std::string& name, const std::string& v) {
    return Strings("string", name, {v});
}
inline ParsedParameter Tex(const std::string& name, const std::string& texName) {
    return Strings("texture", name, {texName});
}
inline ParsedParameter Rgb(const std::string& name, Float r, Float g, Float b) {
    return Floats("rgb", name, {r, g, b});
}

inline ParameterDictionary Dict(std::initializer_list<ParsedParameter> params) {
    return ParameterDictionary(ParsedParameterVector(params), nullptr);
}

}  // namespace kiln::test
