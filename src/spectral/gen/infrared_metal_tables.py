#!/usr/bin/env python3
"""Writes the brass and magnesia tables of spectral/infrared_metal_data.cpp (run by hand).

pbrt-v4's named spectra metal-CuZn and metal-MgO end at 850 and 768 nm; kiln continues them
to 20 um (and down to 300 nm) with the same materials' constants from two files of the
refractiveindex.info database (repository polyanskiy/refractiveindex.info-database, CC0 1.0;
snapshot commit ff11b5897ef0754b15d939d921eb6c745693cbd1), given as the database's root:
  - database/data/other/alloys/Cu-Zn/nk/Querry-Cu70Zn30.yml: brass, 70 % Cu, 30 % Zn, M. R.
    Querry, "Optical constants", Contractor Report CRDC-CR-85034 (1985), 0.21-55.6 um (pbrt-v4's
    metal-CuZn table is this file's 340-850 nm rows);
  - database/data/main/MgO/nk/Synowicki.yml: bulk crystalline MgO, R. A. Synowicki, T. E.
    Tiwald, "Optical properties of bulk c-ZrO2, c-MgO and a-As2S3 determined by variable angle
    spectroscopic ellipsometry", Thin Solid Films 455-456, 248-255 (2004),
    doi:10.1016/j.tsf.2004.02.028 (their oscillator model), 0.13-33 um.
Keeps the source's own points from the last at or below 290 nm to the first at or beyond 20.5
um: from each kept point, the farthest next point such that every dropped point lies within
0.3 % (plus 1e-4) of the straight line between the kept ones in n and in k (kiln interpolates
linearly in wavelength). Prints C++ rows {wavelength nm, n, k} to standard output.
Usage: infrared_metal_tables.py DATABASE_ROOT > tables.txt
"""
import os
import sys

import yaml

from table_thinning import print_array, thin

FILES = {
    "Brass": "database/data/other/alloys/Cu-Zn/nk/Querry-Cu70Zn30.yml",
    "Magnesia": "database/data/main/MgO/nk/Synowicki.yml",
}


def rows_of(path):
    with open(path) as f:
        doc = yaml.safe_load(f)
    for block in doc["DATA"]:
        if block["type"] == "tabulated nk":
            return [[float(x) for x in line.split()] for line in block["data"].strip().split("\n")]
    raise ValueError(f"{path}: no tabulated nk block")


def in_range(rows):
    rows = [(l * 1000, n, k) for l, n, k in rows]
    lo = max(i for i, r in enumerate(rows) if r[0] <= 290)
    hi = min(i for i, r in enumerate(rows) if r[0] >= 20500)
    return rows[lo:hi + 1]


def close(interpolated, actual, column):
    return abs(interpolated - actual) <= 3e-3 * abs(actual) + 1e-4


def main():
    root = sys.argv[1]
    for label, path in FILES.items():
        rows = in_range(rows_of(os.path.join(root, path)))
        table = thin(rows, close)
        print(f"// {label}: {len(table)} of {len(rows)} points")
        print_array(f"const Row k{label}[]",
                    [f"{{{l:.5g}, {n:.5g}, {k:.5g}}}," for l, n, k in table])

if __name__ == "__main__":
    main()
