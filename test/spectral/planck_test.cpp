// Planck's law: against an independent long-double evaluation, the reference values of
// /work/shared/data/facts.md (CODATA 2018), Wien's peak, Stefan-Boltzmann, and finiteness.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <vector>

#include "spectral/planck.h"
#include "spectral/spectrum.h"

using namespace kiln;

namespace {

// B_lambda = 2 h c^2 / lambda^5 / (exp(h c / (lambda k T)) - 1), W m^-2 sr^-1 nm^-1, in long
// double (whose range, to 1e4932, holds every value on the test grid).
long double ReferencePlanck(long double lambda_nm, long double T) {
    const long double h = 6.62607015e-34L, c = 299792458.0L, k = 1.380649e-23L;
    const long double l = lambda_nm * 1e-9L;
    const long double x = h * c / (l * k * T);
    return 2 * h * c * c / powl(l, 5) / expm1l(x) * 1e-9L;
}

std::vector<double> LogSpacedLambdas(int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(std::pow(10.0, 6.0 * i / (n - 1)));  // 1 nm - 1 mm
    return v;
}

}  // namespace

// Exact (to double rounding) wherever the value is a normal double; 0 or tiny where the exact
// value underflows.
TEST(Planck, MatchesLongDoubleReference) {
    int compared = 0;
    for (double T : {1e-3, 1.0, 300.0, 798.0, 2856.0, 6504.0, 1e4, 1e6})
        for (double l : LogSpacedLambdas(121)) {
            const long double ref = ReferencePlanck(l, T);
            const double B = planck_radiance(l, T);
            if (ref > 1e-290L && ref < 1e300L) {
                EXPECT_NEAR(B / double(ref), 1.0, 1e-12) << "T " << T << " lambda " << l;
                ++compared;
            } else if (ref <= 1e-290L) {
                EXPECT_LE(B, 1e-289) << "T " << T << " lambda " << l;
            }
        }
    EXPECT_GT(compared, 400);
}

// Reference values of facts.md (10 significant figures).
TEST(Planck, CODATAReferenceValues) {
    struct Row {
        double T, peak, Bpeak, B550, B650, L;
    };
    const Row rows[] = {
        {798, 3631.293177, 1.325378464, 1.371894353e-8, 9.222384555e-7, 7.319365411e3},
        {1000, 2897.771955, 4.095674676, 1.030748991e-5, 2.501726025e-4, 1.804936236e4},
        {1500, 1931.847970, 3.110152957e1, 6.311607035e-2, 4.005101711e-1, 9.137489695e4},
        {2856, 1014.626035, 7.782452315e2, 2.490187999e2, 4.421900834e2, 1.200866353e6},
        {6504, 445.536893, 4.766813007e4, 4.317178462e4, 3.531997688e4, 3.229862203e7},
    };
    for (const Row& r : rows) {
        // (the 6504 K peak is given to 9 figures only)
        EXPECT_NEAR(planck_peak_wavelength_nm(r.T) / r.peak, 1, 2e-9);
        EXPECT_NEAR(planck_radiance(r.peak, r.T) / r.Bpeak, 1, 1e-9);
        EXPECT_NEAR(planck_radiance(550, r.T) / r.B550, 1, 1e-9);
        EXPECT_NEAR(planck_radiance(650, r.T) / r.B650, 1, 1e-9);
        EXPECT_NEAR(stefan_boltzmann_radiance(r.T) / r.L, 1, 1e-9);
    }
}

// The numerical maximum over wavelength lies at b / T within 0.1 %.
TEST(Planck, WienPeak) {
    for (double T : {300.0, 798.0, 1500.0, 5778.0, 1e4, 1e5}) {
        // Golden-section search on log lambda around the predicted peak
        double a = std::log(planck_peak_wavelength_nm(T) / 3),
               b = std::log(planck_peak_wavelength_nm(T) * 3);
        const double g = (std::sqrt(5.0) - 1) / 2;
        for (int i = 0; i < 200; ++i) {
            double c = b - g * (b - a), d = a + g * (b - a);
            if (planck_radiance(std::exp(c), T) > planck_radiance(std::exp(d), T))
                b = d;
            else
                a = c;
        }
        double peak = std::exp(0.5 * (a + b));
        EXPECT_NEAR(peak / planck_peak_wavelength_nm(T), 1, 1e-3) << T;
        EXPECT_NEAR(planck_radiance_normalized(peak, T), 1, 1e-9) << T;
    }
}

// Integral over wavelength (Simpson in log lambda) equals sigma T^4 / pi within 1e-4.
TEST(Planck, StefanBoltzmann) {
    for (double T : {300.0, 798.0, 1500.0, 5778.0, 1e4}) {
        const double lp = planck_peak_wavelength_nm(T);
        const double a = std::log(lp / 50), b = std::log(lp * 1e5);
        const int n = 20000;  // even
        const double h = (b - a) / n;
        double sum = 0;
        for (int i = 0; i <= n; ++i) {
            const double l = std::exp(a + i * h);
            const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
            sum += w * planck_radiance(l, T) * l;  // d lambda = lambda d(log lambda)
        }
        const double integral = sum * h / 3;
        EXPECT_NEAR(integral / stefan_boltzmann_radiance(T), 1, 1e-4) << T;
    }
}

// Never NaN or Inf, never negative, over the grid and at degenerate inputs.
TEST(Planck, FiniteEverywhere) {
    for (double T : {0.0, 1e-3, 1.0, 300.0, 798.0, 1e4, 1e6})
        for (double l : LogSpacedLambdas(301)) {
            const double B = planck_radiance(l, T), Bn = planck_radiance_normalized(l, T);
            ASSERT_TRUE(std::isfinite(B) && B >= 0) << T << " " << l;
            ASSERT_TRUE(std::isfinite(Bn) && Bn >= 0 && Bn <= 1) << T << " " << l;
            const Float f = BlackbodySpectrum(Float(T))(Float(l));
            ASSERT_TRUE(std::isfinite(f) && f >= 0) << T << " " << l;
        }
    for (double T : {-1.0, 0.0, double(NAN), double(INFINITY), 1e300})
        for (double l : {-1.0, 0.0, double(NAN), double(INFINITY), 1e-300, 500.0, 1e300}) {
            EXPECT_TRUE(std::isfinite(planck_radiance(l, T)));
            EXPECT_TRUE(std::isfinite(planck_radiance_normalized(l, T)));
        }
    EXPECT_EQ(planck_radiance(500, 0), 0);
    EXPECT_EQ(stefan_boltzmann_radiance(0), 0);
    SampledWavelengths swl = SampledWavelengths::SampleUniform(0.3f);
    EXPECT_TRUE(planck_radiance(swl, 1e6).IsFinite());
}

// The per-sample version (single-precision exponential) agrees with the double one.
TEST(Planck, SampledWavelengthsVersionMatchesDouble) {
    double worst = 0;
    for (double T : {1.0, 100.0, 500.0, 798.0, 1000.0, 1500.0, 3000.0, 6500.0, 1e4, 1e5, 1e6})
        for (float u = 0; u < 1; u += 0.01f) {
            SampledWavelengths swl = SampledWavelengths::SampleUniform(u);
            SampledSpectrum B = planck_radiance(swl, T);
            for (int i = 0; i < NSpectrumSamples; ++i) {
                double ref = planck_radiance(double(swl[i]), T);
                ASSERT_TRUE(std::isfinite(B[i]));
                if (ref > 1e-30)
                    worst = std::max(worst, std::abs(B[i] - ref) / ref);
                else
                    EXPECT_LE(B[i], 1e-30);
            }
        }
    EXPECT_LT(worst, 1e-5);
}

// BlackbodySpectrum (pbrt-v4): normalised to peak 1; ratios follow Planck.
TEST(Planck, BlackbodySpectrum) {
    BlackbodySpectrum bb(2856);
    EXPECT_NEAR(bb(Float(planck_peak_wavelength_nm(2856))), 1, 1e-5);
    EXPECT_NEAR(bb(550) / bb(650), planck_radiance(550, 2856) / planck_radiance(650, 2856), 1e-5);
    EXPECT_EQ(BlackbodySpectrum(0)(500), 0);
}

// The normalised Planck function at a path's wavelengths (fast, per path) and BlackbodySpectrum's
// Sample agree with the exact function from a cold body to a star, 300-1000 nm, and with each
// other; outside 1-1e6 K they are the exact function.
TEST(Planck, NormalizedAtSampledWavelengthsMatchesExact) {
    for (Float T : {0.5f, 1.f, 300.f, 1000.f, 2856.f, 6500.f, 1e5f, 1e6f, 1e9f}) {
        BlackbodySpectrum bb(T);
        for (Float u : {0.f, 0.13f, 0.5f, 0.77f}) {
            SampledWavelengths lambda = SampledWavelengths::SampleUniform(u, 300, 1000);
            SampledSpectrum s = planck_radiance_normalized(lambda, T), b = bb.Sample(lambda);
            for (int i = 0; i < NSpectrumSamples; ++i) {
                double exact = planck_radiance_normalized(lambda[i], T);
                EXPECT_NEAR(s[i], exact, 2e-5 * exact + 1e-30) << T << " K, " << lambda[i];
                EXPECT_EQ(b[i], s[i]);
            }
        }
    }
}

namespace kiln {
namespace {

// The band integral against composite Gauss-Legendre quadrature of planck_radiance (1000
// panels of 8 points: converged to about 1e-13 for these bands), from a cold furnace to a
// star, over the visible band, a narrow pyrometer band and thermal infrared.
TEST(PlanckBand, MatchesQuadratureOfTheSpectralRadiance) {
    struct Band {
        double l1, l2;
    };
    for (Band b : {Band{360, 830}, Band{650, 660}, Band{8000, 14000}, Band{100, 100000}})
        for (double T : {300.0, 800.0, 1500.0, 3000.0, 6000.0, 1e5, 1e7}) {
            double sum = 0;
            constexpr int panels = 1000;
            // 8-point Gauss-Legendre nodes and weights on [-1, 1]
            const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                 0.9602898564975363};
            const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                 0.1012285362903763};
            double h = (b.l2 - b.l1) / panels;
            for (int p = 0; p < panels; ++p) {
                double mid = b.l1 + (p + 0.5) * h;
                for (int i = 0; i < 4; ++i)
                    sum += h / 2 * w[i] *
                           (planck_radiance(mid - h / 2 * x[i], T) +
                            planck_radiance(mid + h / 2 * x[i], T));
            }
            double band = planck_band_radiance(b.l1, b.l2, T);
            EXPECT_NEAR(band, sum, 1e-9 * sum + 1e-300) << b.l1 << "-" << b.l2 << " nm, " << T;
        }
}

TEST(PlanckBand, AllWavelengthsGiveStefanBoltzmann) {
    for (double T : {1.0, 300.0, 5772.0, 1e6})
        EXPECT_NEAR(planck_band_radiance(0, 1e15, T), stefan_boltzmann_radiance(T),
                    1e-9 * stefan_boltzmann_radiance(T))
            << T;
}

TEST(PlanckBand, FiniteForAnyTemperatureAndBand) {
    EXPECT_EQ(planck_band_radiance(360, 830, 0), 0);
    EXPECT_EQ(planck_band_radiance(360, 830, -10), 0);
    EXPECT_EQ(planck_band_radiance(360, 830, std::nan("")), 0);
    EXPECT_EQ(planck_band_radiance(830, 360, 1500), 0);
    EXPECT_EQ(planck_band_radiance(360, 830, 1e-3), 0);  // underflows to exactly 0
    double previous = 0;
    for (double T : {1e3, 1e10, 1e38, 1e100, 1e300, DBL_MAX}) {
        double band = planck_band_radiance(360, 830, T);
        EXPECT_TRUE(std::isfinite(band)) << T;
        EXPECT_GE(band, previous) << T;
        previous = band;
    }
    // Rayleigh-Jeans where hc / (lambda k T) is tiny: linear in T
    EXPECT_NEAR(planck_band_radiance(360, 830, 2e20) / planck_band_radiance(360, 830, 1e20), 2,
                1e-9);
}

}  // namespace
}  // namespace kiln
