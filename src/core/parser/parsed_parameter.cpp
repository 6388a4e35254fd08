#include "core/parser/parsed_parameter.h"

#include <array>
#include <charconv>
#include <utility>

namespace kiln {

std::string_view CanonicalParameterType(std::string_view type) {
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 17> kTypes = {{
        {"integer", "integer"},
        {"float", "float"},
        {"bool", "bool"},
        {"string", "string"},
        {"texture", "texture"},
        {"point2", "point2"},
        {"vector2", "vector2"},
        {"point3", "point3"},
        {"point", "point3"},
        {"vector3", "vector3"},
        {"vector", "vector3"},
        {"normal", "normal"},
        {"normal3", "normal"},
        {"rgb", "rgb"},
        {"color", "rgb"},
        {"spectrum", "spectrum"},
        {"blackbody", "blackbody"},
    }};
    for (const auto& [alias, canonical] : kTypes)
        if (alias == type) return canonical;
    return {};
}

ParameterValueKind ValueKindOf(std::string_view t) {
    if (t == "integer") return ParameterValueKind::Int;
    if (t == "bool") return ParameterValueKind::Bool;
    if (t == "string" || t == "texture") return ParameterValueKind::String;
    if (t == "spectrum") return ParameterValueKind::FloatOrString;
    return ParameterValueKind::Float;
}

int ValuesPerItem(std::string_view t) {
    if (t == "point2" || t == "vector2" || t == "spectrum") return 2;
    if (t == "point3" || t == "vector3" || t == "normal" || t == "rgb") return 3;
    return 1;
}

std::string ParsedParameter::ToString() const {
    std::string s(1, '"');
    s += Declaration();
    s += "\" [";
    char buf[32];
    for (Float f : floats) {
        auto r = std::to_chars(buf, buf + sizeof(buf), f);
        s += ' ';
        s.append(buf, r.ptr);
    }
    for (int i : ints) {
        s += ' ';
        s += std::to_string(i);
    }
    for (uint8_t b : bools) s += b ? " true" : " false";
    for (const std::string& str : strings) {
        s += " \"";
        for (char c : str) {
            if (c == '\n') {
                s += "\\n";
                continue;
            }
            if (c == '"' || c == '\\') s += '\\';
            s += c;
        }
        s += '"';
    }
    return s + " ]";
}

}  // namespace kiln
