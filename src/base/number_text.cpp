#include "base/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace kiln {

std::optional<std::vector<Float>> ParseNumberText(const std::string& text, std::string* error) {
    std::istringstream in(text);
    std::vector<Float> values;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream ls(line);
        std::string tok;
        while (ls >> tok) {
            char* end = nullptr;
            double d = std::strtod(tok.c_str(), &end);
            if (end == tok.c_str() || *end != '\0' || !std::isfinite(Float(d))) {
                if (error)
                    *error = "line " + std::to_string(lineNo) + ": not a finite number: '" +
                             tok.substr(0, 40) + "'";
                return std::nullopt;
            }
            values.push_back(Float(d));
        }
    }
    return values;
}

}  // namespace kiln
