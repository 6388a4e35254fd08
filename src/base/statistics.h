// Statistical tests for Monte Carlo code: Pearson's chi-square goodness-of-fit test (as in
// Nori's warptest and pbrt-v4's sampling tests) and Student-style error bounds.
//
// Used by the tests of every sampling routine: bin the samples, integrate the claimed pdf over
// each bin, and ask whether the observed counts could come from that density.
#pragma once

#include <span>
#include <string>

namespace kiln {

struct ChiSquareResult {
    bool passed = false;
    double pValue = 0;     // probability of a statistic at least this large under H0
    double statistic = 0;  // Pearson's chi^2 after pooling small bins
    int degreesOfFreedom = 0;
    std::string message;  // human-readable reason when the test fails
};

// Pearson's chi-square test. Bins whose expected count is below minExpected are pooled.
// The null hypothesis is rejected when p < significance / numTests (Sidak-like correction for
// running several tests in one suite). Observed counts with zero expected count fail at once.
ChiSquareResult ChiSquareTest(std::span<const double> observed, std::span<const double> expected,
                              double significance = 0.01, int numTests = 1, double minExpected = 5);

// Regularised upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a).
double RegularizedGammaQ(double a, double x);
// Survival function of the chi-square distribution with k degrees of freedom.
inline double ChiSquareSurvival(double x, int k) { return RegularizedGammaQ(0.5 * k, 0.5 * x); }

// Running mean and variance (Welford), for variance-derived tolerances.
class RunningStats {
  public:
    void Add(double x) {
        ++n;
        double d = x - mean;
        mean += d / n;
        m2 += d * (x - mean);
    }
    long long Count() const { return n; }
    double Mean() const { return mean; }
    double Variance() const { return n > 1 ? m2 / (n - 1) : 0; }
    // Standard error of the mean.
    double StandardError() const;

  private:
    long long n = 0;
    double mean = 0, m2 = 0;
};

}  // namespace kiln
