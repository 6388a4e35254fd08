// The measured optical constants of ../shared/data (wavelength_nm,n,k CSV files) for tests that
// check kiln's tables and models against them.
#pragma once

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace kiln::test {

struct NK {
    double lambda, n, k;
};

// The rows of KILN_SHARED_DIR/data/<file> (none if it cannot be read).
inline std::vector<NK> ReadNkCSV(const std::string& file) {
    std::ifstream in(std::string(KILN_SHARED_DIR) + "/data/" + file);
    std::vector<NK> rows;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream ls(line);
        NK r;
        if (ls >> r.lambda >> r.n >> r.k) rows.push_back(r);
    }
    return rows;
}

}  // namespace kiln::test
