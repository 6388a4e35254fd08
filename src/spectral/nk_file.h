// Optical constants n and k tabulated against wavelength, read from a text file (a conductor's
// "nkfiles", one file per temperature: materials/material.cpp).
//
// Format: one row per wavelength, "lambda_nm n k" separated by commas and/or white space (the
// CSV files of refractiveindex.info exports and of ../shared/data read as they are); a first
// line that is not three numbers (a header) and lines starting with '#' are skipped; gzip-
// compressed files are read too. At least two rows; wavelengths (nm, in vacuum) strictly
// increasing, positive and finite; n and k finite and >= 0.
#pragma once

#include <string>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

struct NkTable {
    std::vector<Float> lambdas, n, k;
};

// Throws std::runtime_error "file:line: what is wrong" on unreadable or malformed input.
NkTable ReadNkFile(const std::string& filename);

}  // namespace kiln
