#!/usr/bin/env python3
"""Fits the temperature dependence of tungsten's Lorentz-Drude model (run by hand; not built).

Prints the two coefficients of spectral/metal_temperature.cpp's tungsten model. The model is
Rakic et al. (1998)'s Lorentz-Drude fit of tungsten (spectral/lorentz_drude.cpp) with
  - the Drude damping G_0 scaled by the electrical resistivity rho(T) / rho(293 K) (the table
    below, linear between its points and beyond its last two),
  - the Lorentz dampings G_j scaled by 1 + a (T - 293 K) and the Lorentz strengths f_j by
    1 + b (T - 293 K).
a and b minimise the RMS difference of the model's normal emissivity 4n / ((n + 1)^2 + k^2)
from Larrabee's fit of his measured normal spectral emissivity of tungsten,
  eps(lambda, T) = 0.4655 + 0.01558 lambda + 0.2675e-4 T - 0.7305e-4 lambda T  (lambda in um),
R. D. Larrabee, "Spectral emissivity of tungsten", J. Opt. Soc. Am. 49, 619-625 (1959), over
310-800 nm in 10 nm steps and 1600-2800 K in 100 K steps (his measurements' range). A grid
search in steps of 1e-6 per K around the optimum, then printed with the RMS and the largest
difference. Nothing here uses Cezairliyan and Miiller's (1982) measurement at the melting point,
which test/spectral/metal_temperature_test.cpp checks the model against.
Usage: hot_tungsten_fit.py
"""
import cmath
import math

# Rakic et al. 1998, Table 1, tungsten: (f_j, G_j eV, w_j eV); j = 0 the Drude term
TERMS = [(0.206, 0.064, 0), (0.054, 0.530, 1.004), (0.166, 1.281, 1.917),
         (0.706, 3.332, 3.580), (2.590, 5.836, 7.498)]
OMEGA_P = 13.22
# Electrical resistivity of tungsten, micro-ohm cm (kiln's table; metal_temperature.cpp cites it)
RESISTIVITY = [(293, 5.5), (500, 10.5), (1000, 24.3), (2000, 55.7), (3000, 90.4), (3500, 108.5)]


def resistivity(T):
    pts = RESISTIVITY
    for (t0, r0), (t1, r1) in zip(pts, pts[1:]):
        if T <= t1 or (t1, r1) == pts[-1]:
            return r0 + (r1 - r0) * (T - t0) / (t1 - t0)


def permittivity(lam, T, a, b):
    E = 1239.841984 / lam
    s = resistivity(T) / resistivity(293)
    f0, g0, _ = TERMS[0]
    eps = 1 - f0 * OMEGA_P**2 / (E * complex(E, g0 * s))
    for f, g, w in TERMS[1:]:
        eps += f * (1 + b * (T - 293)) * OMEGA_P**2 / complex(w * w - E * E,
                                                              -E * g * (1 + a * (T - 293)))
    return eps


def emissivity(eps):
    N = cmath.sqrt(eps)
    return 4 * N.real / ((N.real + 1)**2 + N.imag**2)


def larrabee(lam, T):
    l = lam / 1000
    return 0.4655 + 0.01558 * l + 0.2675e-4 * T - 0.7305e-4 * l * T


POINTS = [(l, T) for l in range(310, 801, 10) for T in range(1600, 2801, 100)]


def errors(a, b):
    return [emissivity(permittivity(l, T, a, b)) - larrabee(l, T) for l, T in POINTS]


def rms(a, b):
    e = errors(a, b)
    return math.sqrt(sum(x * x for x in e) / len(e))


def main():
    best = min((rms(a * 1e-5, b * 1e-5), a * 1e-5, b * 1e-5)
               for a in range(0, 100, 2) for b in range(-50, 51, 2))
    for step in (1e-6,):
        _, a0, b0 = best
        best = min((rms(a0 + i * step, b0 + j * step), a0 + i * step, b0 + j * step)
                   for i in range(-20, 21) for j in range(-20, 21))
    r, a, b = best
    print(f"a = {a:.6g} per K, b = {b:.6g} per K: RMS {r:.4f}, "
          f"largest {max(abs(x) for x in errors(a, b)):.4f}")


if __name__ == "__main__":
    main()
