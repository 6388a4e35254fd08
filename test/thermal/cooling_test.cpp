// Tests of the lumped-capacitance cooling model: closed forms against the Runge-Kutta
// integrator, and the integrator against an independent reference obtained by separation of
// variables (adaptive Gauss-Kronrod quadrature of dT / (dT/dt)).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "spectral/planck.h"
#include "thermal/cooling.h"

namespace kiln {
namespace {

// A 1 cm thick steel plate, 10 cm x 10 cm, emissivity 0.8, heated to 1500 K. Steel: density
// 7850 kg m^-3, specific heat ~ 500 J kg^-1 K^-1 (Incropera & DeWitt, table A.1, AISI 1010
// at 300 K: 7832 kg m^-3, 434 J kg^-1 K^-1; round values are used here). Two faces radiate.
CoolingParameters SteelPlate() {
    CoolingParameters p;
    p.T0 = 1500;
    p.emissivity = 0.8;
    p.area = 2 * 0.1 * 0.1;
    p.mass = CoolingParameters::SlabMass(7850, 0.01, 0.1 * 0.1);
    p.specificHeat = 500;
    return p;
}

// Adaptive Gauss-Kronrod (7, 15) quadrature of f over [a, b] to absolute tolerance tol.
double Integrate(const std::function<double(double)>& f, double a, double b, double tol,
                 int depth = 0) {
    static const double xk[8] = {
        0.991455371120812639, 0.949107912342758525, 0.864864423359769073, 0.741531185599394440,
        0.586087235467691130, 0.405845151377397167, 0.207784955007898468, 0.0};
    static const double wk[8] = {0.022935322010529225, 0.063092092629978553, 0.104790010322250184,
                                 0.140653259715525919, 0.169004726639267903, 0.190350578064785410,
                                 0.204432940075298892, 0.209482141084727828};
    static const double wg[4] = {0.129484966168869693, 0.279705391489276668, 0.381830050505118945,
                                 0.417959183673469388};
    double c = 0.5 * (a + b), h = 0.5 * (b - a);
    double fc = f(c);
    double k = wk[7] * fc, g = wg[3] * fc;
    for (int i = 0; i < 7; ++i) {
        double f1 = f(c - h * xk[i]), f2 = f(c + h * xk[i]);
        k += wk[i] * (f1 + f2);
        if (i % 2 == 1) g += wg[i / 2] * (f1 + f2);
    }
    k *= h, g *= h;
    if (std::abs(k - g) <= tol || depth > 40) return k;
    return Integrate(f, a, c, tol / 2, depth + 1) + Integrate(f, c, b, tol / 2, depth + 1);
}

// Time to cool from T0 to T by separation of variables: integral_T^T0 dT' / -(dT/dt)(T').
double ReferenceTime(const CoolingModel& model, double T, double tol) {
    return Integrate([&](double x) { return -1 / model.dTdt(x); }, T, model.Parameters().T0, tol);
}

TEST(Cooling, ClosedFormMatchesIntegratorPureRadiation) {
    CoolingParameters p = SteelPlate();
    CoolingModel model(p);
    double tau = model.RadiativeTimeConstant();
    // tau = m c / (eps sigma A T0^3) = 785 * 500 / ... ~ 1.3e3 s for this plate
    EXPECT_GT(tau, 100);
    EXPECT_LT(tau, 1e5);
    std::vector<double> times;
    for (double f : {0.0, 1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 30.0, 100.0, 1000.0})
        times.push_back(f * tau);
    std::vector<double> numeric = model.IntegrateTemperatures(times);
    for (size_t i = 0; i < times.size(); ++i) {
        double exact = RadiativeCoolingTemperature(p.T0, p.emissivity, p.area, p.mass,
                                                   p.specificHeat, times[i]);
        EXPECT_NEAR(numeric[i], exact, 1e-4 * exact) << "t = " << times[i] << " s";
        // Much tighter in fact (the integrator runs at 1e-10 per step)
        EXPECT_NEAR(numeric[i], exact, 1e-7 * exact) << "t = " << times[i] << " s";
        EXPECT_DOUBLE_EQ(model.Temperature(times[i]), exact);
    }
    // T0 (1 + 3 t / tau)^(-1/3)
    EXPECT_NEAR(model.Temperature(tau), p.T0 / std::cbrt(4.0), 1e-9 * p.T0);
    // One-at-a-time and batched integration agree
    EXPECT_NEAR(model.IntegrateTemperature(times[6]), numeric[6], 1e-8 * numeric[6]);
}

TEST(Cooling, RadiationToWarmSurroundingsClosedForm) {
    CoolingParameters p = SteelPlate();
    p.Tambient = 300;
    CoolingModel model(p);
    for (double t : {1.0, 10.0, 100.0, 1000.0, 5000.0, 20000.0}) {
        double T = model.IntegrateTemperature(t);
        ASSERT_GT(T, p.Tambient);
        double tBack =
            RadiativeCoolingTime(p.T0, T, p.Tambient, p.emissivity, p.area, p.mass, p.specificHeat);
        EXPECT_NEAR(tBack, t, 1e-6 * t) << "T = " << T;
    }
    // The series branch (Ta << T) agrees with the closed-form branch where they meet, and with
    // the Ta = 0 closed form in the limit.
    double t1 = RadiativeCoolingTime(1500, 1000, 49.9, 0.8, 0.02, 0.785, 500);
    double t2 = RadiativeCoolingTime(1500, 1000, 50.1, 0.8, 0.02, 0.785, 500);
    EXPECT_NEAR(t1, t2, 1e-3 * t1);
    double t0 = RadiativeCoolingTime(1500, 1000, 0, 0.8, 0.02, 0.785, 500);
    EXPECT_NEAR(RadiativeCoolingTemperature(1500, 0.8, 0.02, 0.785, 500, t0), 1000, 1e-9 * 1000);
    EXPECT_TRUE(std::isinf(RadiativeCoolingTime(1500, 300, 300, 0.8, 0.02, 0.785, 500)));
}

TEST(Cooling, ConvectionAndRadiationAgainstQuadratureReference) {
    CoolingParameters p = SteelPlate();
    p.Tambient = 293;
    p.h = 25;  // W m^-2 K^-1: free convection in air is ~ 5 - 25
    CoolingModel model(p);
    double tauC = model.ConvectiveTimeConstant();
    EXPECT_NEAR(tauC, p.mass * p.specificHeat / (p.h * p.area), 1e-9 * tauC);
    for (double f : {0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0}) {
        double t = f * tauC;
        double T = model.IntegrateTemperature(t);
        // Independent reference: time to reach T by quadrature.
        double tRef = ReferenceTime(model, T, 1e-9 * t);
        EXPECT_NEAR(tRef, t, 1e-6 * t) << "T = " << T;
        // Same integrator at a much tighter tolerance.
        CoolingModel tight(p, 1e-13);
        EXPECT_NEAR(tight.IntegrateTemperature(t) - p.Tambient, T - p.Tambient,
                    1e-6 * (T - p.Tambient));
    }
}

TEST(Cooling, MonotoneDecreaseTowardsAmbient) {
    CoolingParameters p = SteelPlate();
    p.Tambient = 400;
    p.h = 10;
    CoolingModel model(p);
    std::vector<double> times;
    for (int i = 0; i <= 200; ++i) times.push_back(std::pow(10.0, -1 + 0.03 * i));  // 0.1 s - 1e5 s
    std::vector<double> T = model.IntegrateTemperatures(times);
    double prev = p.T0;
    for (size_t i = 0; i < T.size(); ++i) {
        EXPECT_LE(T[i], prev) << "t = " << times[i];
        EXPECT_GE(T[i], p.Tambient) << "t = " << times[i];
        prev = T[i];
    }
    // After ~ 1e5 s (many time constants) it has reached the surroundings.
    EXPECT_NEAR(T.back(), p.Tambient, 1e-3);
    // Energy balance over the first interval: m c (T0 - T(t)) equals the heat lost, the
    // integral of A (eps sigma (T^4 - Ta^4) + h (T - Ta)) dt, by the trapezoid rule on a fine grid.
    double t1 = 50, lost = 0;
    int n = 2000;
    std::vector<double> grid(n + 1);
    for (int i = 0; i <= n; ++i) grid[i] = t1 * i / n;
    std::vector<double> Tg = model.IntegrateTemperatures(grid);
    for (int i = 0; i < n; ++i) {
        double q0 = -model.dTdt(Tg[i]), q1 = -model.dTdt(Tg[i + 1]);
        lost += 0.5 * (q0 + q1) * (grid[i + 1] - grid[i]);
    }
    EXPECT_NEAR(lost, p.T0 - Tg.back(), 1e-6 * (p.T0 - Tg.back()));
    // An object colder than its surroundings warms up towards them.
    CoolingParameters cold = p;
    cold.T0 = 300;
    CoolingModel warming(cold);
    double Tw = warming.IntegrateTemperature(1000);
    EXPECT_GT(Tw, 300);
    EXPECT_LT(Tw, p.Tambient);
}

TEST(Cooling, DegenerateCases) {
    CoolingParameters p = SteelPlate();
    p.emissivity = 0;  // nothing exchanges heat
    EXPECT_EQ(CoolingModel(p).IntegrateTemperature(1e4), p.T0);
    p = SteelPlate();
    p.Tambient = p.T0;  // already in equilibrium
    p.h = 10;
    EXPECT_EQ(CoolingModel(p).IntegrateTemperature(1e4), p.T0);
    EXPECT_EQ(CoolingModel(SteelPlate()).Temperature(-1), 1500);
    EXPECT_DOUBLE_EQ(CoolingParameters::BodyMass(7850, 1e-3), 7.85);
}

}  // namespace
}  // namespace kiln
