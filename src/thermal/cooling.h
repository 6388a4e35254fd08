// Lumped-capacitance cooling of a hot object: its (uniform) temperature T(t) as it loses heat
// by thermal radiation and convection to surroundings at an ambient temperature Ta.
//
// Energy balance (the object is isothermal, i.e. Biot number << 1; surroundings are a black
// enclosure at Ta, so radiation exchange is eps sigma (T^4 - Ta^4) per unit area):
//   m c dT/dt = -A (eps sigma (T^4 - Ta^4) + h (T - Ta))
// with, in SI units: T, Ta in K; t in s; m mass in kg; c specific heat in J kg^-1 K^-1; A the
// emitting area in m^2; eps the hemispherical total emissivity (dimensionless, in [0, 1]);
// h the convective heat-transfer coefficient in W m^-2 K^-1; sigma Stefan-Boltzmann's
// constant (spectral/planck.h). See e.g. Incropera & DeWitt, "Fundamentals of Heat and Mass
// Transfer", section 5.3 (the lumped capacitance method with radiation).
//
// Pure radiative cooling to 0 K (h = 0, Ta = 0) has the closed form
//   1/T^3 = 1/T0^3 + 3 eps sigma A t / (m c);
// radiation to surroundings at Ta > 0 (h = 0) has the implicit closed form of
// RadiativeCoolingTime. The general case is integrated numerically (adaptive Dormand-Prince
// 5(4) Runge-Kutta in double precision).
#pragma once

#include <span>
#include <vector>

namespace kiln {

// CoolingParameters Definition
struct CoolingParameters {
    double T0 = 1000;           // initial temperature, K
    double emissivity = 1;      // hemispherical total emissivity, dimensionless
    double area = 1;            // emitting / convecting area, m^2
    double mass = 1;            // kg
    double specificHeat = 500;  // J kg^-1 K^-1
    double h = 0;               // convective coefficient, W m^-2 K^-1
    double Tambient = 0;        // surroundings (radiation) and fluid (convection), K

    // Mass of a slab of density rho (kg m^-3) and thickness d (m) over area A: rho d A; of a
    // body of volume V (m^3): rho V.
    static double SlabMass(double density, double thickness, double area) {
        return density * thickness * area;
    }
    static double BodyMass(double density, double volume) { return density * volume; }
};

// CoolingModel Definition
class CoolingModel {
  public:
    // relTol: relative error per step of the integrator (local error control on T; the
    // global error at the end of a long run is a small multiple of it).
    explicit CoolingModel(const CoolingParameters& params, double relTol = 1e-10);

    const CoolingParameters& Parameters() const { return params; }
    // dT/dt at temperature T, K s^-1.
    double dTdt(double T) const;
    // Radiative time scale tau = m c / (eps sigma A T0^3), s: with h = Ta = 0 the closed form
    // reads T(t) = T0 (1 + 3 t / tau)^(-1/3). Infinite without radiation (eps = 0).
    double RadiativeTimeConstant() const;
    // Convective time scale m c / (h A), s (infinite for h = 0).
    double ConvectiveTimeConstant() const;

    // T(t) in K for t >= 0 s (t <= 0 gives T0). Exact closed form when h = 0 and Ta = 0,
    // otherwise integrated from 0.
    double Temperature(double t) const;
    // Always through the integrator (for testing and for the general case).
    double IntegrateTemperature(double t) const;
    // T at each of the given times (any order), integrating once through them in sorted order.
    std::vector<double> IntegrateTemperatures(std::span<const double> times) const;

  private:
    CoolingParameters params;
    // d(T - Ta)/dt at u = T - Ta, K s^-1.
    double dudt(double u) const;

    double relTol;
    double k;  // A / (m c), m^2 K J^-1
};

// Closed form of pure radiative cooling to 0 K, K: (1/T0^3 + 3 eps sigma A t / (m c))^(-1/3).
double RadiativeCoolingTemperature(double T0, double emissivity, double area, double mass,
                                   double specificHeat, double t);

// Time (s) that radiative cooling (no convection) from T0 to T takes with surroundings at
// Ta >= 0 (Ta < T <= T0). Separation of variables with
//   integral dT / (T^4 - Ta^4) = (1 / (4 Ta^3)) ln((T - Ta) / (T + Ta)) - atan(T / Ta) / (2 Ta^3),
// and -1 / (3 T^3) when Ta = 0. Infinite when T <= Ta < T0.
double RadiativeCoolingTime(double T0, double T, double Ta, double emissivity, double area,
                            double mass, double specificHeat);

}  // namespace kiln
