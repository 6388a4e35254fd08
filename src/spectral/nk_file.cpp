#include "spectral/nk_file.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "base/file_reading.h"

namespace kiln {

namespace {

// The numbers of one line, separated by commas and/or white space; false if a field is not a
// number
bool ParseNumbers(const std::string& line, std::vector<double>* out) {
    out->clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ',' || std::isspace((unsigned char)line[i]))) ++i;
        if (i >= line.size()) break;
        size_t j = i;
        while (j < line.size() && line[j] != ',' && !std::isspace((unsigned char)line[j])) ++j;
        std::string field = line.substr(i, j - i);
        char* end = nullptr;
        double v = std::strtod(field.c_str(), &end);
        if (end != field.c_str() + field.size()) return false;
        out->push_back(v);
        i = j;
    }
    return true;
}

}  // namespace

NkTable ReadNkFile(const std::string& filename) {
    std::string text, error;
    if (!ReadFileBytes(filename, &text, &error)) throw std::runtime_error(filename + ": " + error);
    NkTable t;
    std::vector<double> v;
    int lineNumber = 0;
    size_t start = 0;
    bool first = true;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        auto fail = [&](const std::string& what) {
            throw std::runtime_error(filename + ":" + std::to_string(lineNumber) + ": " + what);
        };
        size_t nonSpace = line.find_first_not_of(" \t");
        if (nonSpace == std::string::npos || line[nonSpace] == '#') continue;
        bool numbers = ParseNumbers(line, &v);
        if (first && !numbers) {  // a header
            first = false;
            continue;
        }
        first = false;
        if (!numbers || v.size() != 3)
            fail("expected three numbers (wavelength in nm, n, k), found \"" + line + "\"");
        if (!(v[0] > 0) || !std::isfinite(v[0]))
            fail("the wavelength must be a positive number of nm");
        if (!t.lambdas.empty() && !(Float(v[0]) > t.lambdas.back()))
            fail("wavelengths must increase from row to row");
        if (!(v[1] >= 0) || !(v[2] >= 0) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            fail("n and k must be finite and 0 or more");
        t.lambdas.push_back(Float(v[0]));
        t.n.push_back(Float(v[1]));
        t.k.push_back(Float(v[2]));
    }
    if (t.lambdas.size() < 2)
        throw std::runtime_error(filename + ": needs at least two rows (wavelength in nm, n, k)");
    return t;
}

}  // namespace kiln
