#!/usr/bin/env python3
"""Generates filmic_tone.spi1d, the tone curve of kiln's "Filmic" view (config.ocio).

Curve (scene-linear x >= 0 -> display-linear y in [0, 1)), a log-logistic "filmic" shoulder:
    y = x^p / (x^p + k),  p = 1.1 (contrast), k chosen so that mid grey 0.18 -> 0.13
It is monotone, maps 0 to 0 and approaches 1 only asymptotically, so very bright values
(x = 1e3, e.g. incandescent emitters) still map below 1 and keep their gradations.
The LUT is indexed by a log2 shaper: u = (log2(x) - LOG_MIN) / (LOG_MAX - LOG_MIN), which the
config applies with a LogAffineTransform before the FileTransform.

Run from this directory: python3 make_filmic_lut.py
"""
import math

P = 1.1
MID_IN, MID_OUT = 0.18, 0.13
K = MID_IN ** P * (1 / MID_OUT - 1)
LOG_MIN, LOG_MAX = -16.0, 14.0
N = 4096


def curve(x):
    xp = x ** P
    return xp / (xp + K)


with open("filmic_tone.spi1d", "w") as f:
    f.write("Version 1\nFrom 0.0 1.0\nLength %d\nComponents 1\n{\n" % N)
    for i in range(N):
        u = i / (N - 1)
        x = 2.0 ** (LOG_MIN + u * (LOG_MAX - LOG_MIN))
        f.write("    %.9g\n" % curve(x))
    f.write("}\n")
print("k =", K)
