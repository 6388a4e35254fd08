#!/usr/bin/env python3
"""Writes the infrared glass tables of spectral/named_spectra_glass_data.cpp (run by hand).

Reads three files of the refractiveindex.info database (repository
polyanskiy/refractiveindex.info-database, CC0 1.0; snapshot commit
ff11b5897ef0754b15d939d921eb6c745693cbd1), given as the database's root folder:
  - database/data/main/SiO2/nk/Franta.yml: fused silica plate (SCHOTT Lithosil Q2), n and k
    from 24.8 nm to 125 um, D. Franta, D. Necas, I. Ohlidal, A. Giglia, Proc. SPIE 9890,
    989014 (2016), doi:10.1117/12.2227580;
  - database/data/glass/misc/soda-lime/nk/Rubin-clear.yml and Rubin-IR.yml: clear soda-lime
    silica window glass, M. Rubin, "Optical properties of soda lime silica glasses", Sol.
    Energy Mater. 12, 275-288 (1985), doi:10.1016/0165-1633(85)90052-8: n from Rubin's formula
    n = 1.5130 - 0.003169 l^2 + 0.003962 / l^2 (l in um, 0.31-4.6 um) at the wavelengths of
    his tabulated k, then his tabulated n and k from 5 um on.
Keeps the source's own points from 300 nm to the first point at or beyond 20 um: from each
kept point, the farthest next point such that every dropped point lies within 2e-4 (n) and
within 2 % or 1e-8 (k; 1e-8 absorbs 0.13 per metre at 1 um) of the straight line between the
kept ones (kiln interpolates linearly in wavelength). k below 1e-12 (the model's tails in the visible, down to 1e-251) is written as
0: its absorption is below 3e-5 per metre. Prints C++ arrays to standard output.
Usage: glass_ir_tables.py DATABASE_ROOT > tables.txt
"""
import os
import sys

import yaml

from table_thinning import print_array, thin


def rows_of(path, kind):
    with open(path) as f:
        doc = yaml.safe_load(f)
    for block in doc["DATA"]:
        if block["type"] == kind:
            return [[float(x) for x in line.split()] for line in block["data"].strip().split("\n")]
    raise ValueError(f"{path}: no {kind} block")


def fused_silica(root):
    rows = rows_of(os.path.join(root, "database/data/main/SiO2/nk/Franta.yml"), "tabulated nk")
    return [(l * 1000, n, k) for l, n, k in rows]


def soda_lime(root):
    folder = os.path.join(root, "database/data/glass/misc/soda-lime/nk")
    out = []
    for l, k in rows_of(os.path.join(folder, "Rubin-clear.yml"), "tabulated k"):
        n = 1.5130 - 0.003169 * l * l + 0.003962 / (l * l)
        out.append((l * 1000, n, k))
    for l, n, k in rows_of(os.path.join(folder, "Rubin-IR.yml"), "tabulated nk"):
        out.append((l * 1000, n, k))
    return out


def in_range(rows):
    lo = max(i for i, r in enumerate(rows) if r[0] <= 300) if rows[0][0] <= 300 else 0
    hi = min(i for i, r in enumerate(rows) if r[0] >= 20000)
    return [(l, n, 0.0 if k < 1e-12 else k) for l, n, k in rows[lo:hi + 1]]


def close(interpolated, actual, column):
    if column == 1:
        return abs(interpolated - actual) <= 2e-4
    return abs(interpolated - actual) <= max(0.02 * actual, 1e-8)


def emit(name, rows, column):
    print_array(f"const float {name}[]", [f"{r[0]:.6g}, {r[column]:.6g}," for r in rows])


def main():
    root = sys.argv[1]
    for label, rows in (("FusedSilica", fused_silica(root)), ("SodaLime", soda_lime(root))):
        table = thin(in_range(rows), close)
        print(f"// {label}: {len(table)} of {len(in_range(rows))} points")
        emit(f"kGlass{label}Eta", table, 1)
        emit(f"kGlass{label}K", table, 2)


if __name__ == "__main__":
    main()
